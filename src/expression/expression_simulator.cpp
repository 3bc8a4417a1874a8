// The expression simulator (thesis chapter 4): blinks, eyebrow raises, tilts and turns at random
// intervals, a nod at each pause.
#include "talkface/expression_simulator.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include "expression/envelopes.hpp"
#include "expression/random.hpp"
#include "expression/style_fields.hpp"
#include "timing/timeline_checks.hpp"
#include "talkface/errors.hpp"

namespace talkface {
inline namespace v0 {

namespace {

constexpr std::size_t kKindCount = 5;

std::size_t kind_index(ExpressionEventKind kind) {
    return static_cast<std::size_t>(kind);
}

// Events of one kind at random intervals (end of one to start of the next, thesis 4.2) until
// the next would end after end_s. Each event draws interval, duration, then its amount.
template <typename DrawInterval, typename DrawAmount>
void simulate_intervals(ExpressionEventKind kind, detail::Xoshiro256& random, double end_s,
                        DrawInterval draw_interval, UniformRange duration_s, DrawAmount draw_amount,
                        std::vector<ExpressionEvent>& events) {
    double time_s = 0.0;
    for (;;) {
        const double interval_s = draw_interval();
        const double length_s = random.uniform(duration_s.min, duration_s.max);
        const double amount = draw_amount();
        const double start_s = time_s + interval_s;
        if (start_s + length_s > end_s) return;
        events.push_back({kind, start_s, start_s + length_s, amount});
        time_s = start_s + length_s;
    }
}

// Tilts and turns: a random interval and duration, then an angle of random size and sign.
void simulate_head_turns(ExpressionEventKind kind, std::uint64_t seed, double end_s, UniformRange interval_s,
                         UniformRange duration_s, UniformRange angle_deg,
                         std::vector<ExpressionEvent>& events) {
    detail::Xoshiro256 random(seed, kind_index(kind));
    simulate_intervals(
        kind, random, end_s, [&] { return random.uniform(interval_s.min, interval_s.max); }, duration_s,
        [&] {
            const double size = random.uniform(angle_deg.min, angle_deg.max);
            return random.sign() * size;
        },
        events);
}

bool overlaps(const ExpressionEvent& a, const ExpressionEvent& b) {
    return a.start_s < b.end_s && b.start_s < a.end_s;
}

void sort_events(std::vector<ExpressionEvent>& events) {
    std::stable_sort(events.begin(), events.end(), [](const ExpressionEvent& a, const ExpressionEvent& b) {
        if (a.start_s != b.start_s) return a.start_s < b.start_s;
        return a.kind < b.kind;
    });
}

}  // namespace

struct ExpressionSimulator::Impl {
    std::uint64_t seed = 0;
    ExpressionStyle style;
    double duration_s = 0.0;
    std::vector<ExpressionEvent> simulated;
    std::vector<ExpressionEvent> combined;
    // combined, split by kind, by start time; for tilt, turn and nod also the angle each event
    // starts from (where the one before it ended).
    std::array<std::vector<ExpressionEvent>, kKindCount> by_kind;
    std::array<std::vector<double>, kKindCount> start_amounts;

    void index_events() {
        for (auto& list : by_kind) list.clear();
        for (auto& list : start_amounts) list.clear();
        for (const ExpressionEvent& event : combined) by_kind[kind_index(event.kind)].push_back(event);
        for (std::size_t kind = 0; kind < kKindCount; ++kind) {
            double previous = 0.0;
            for (const ExpressionEvent& event : by_kind[kind]) {
                start_amounts[kind].push_back(previous);
                previous = event.amount;
            }
        }
    }

    // The index in by_kind[kind] of the last event starting at or before time_s, or -1.
    std::ptrdiff_t last_started(std::size_t kind, double time_s) const {
        const auto& list = by_kind[kind];
        const auto after = std::upper_bound(list.begin(), list.end(), time_s,
                                            [](double t, const ExpressionEvent& e) { return t < e.start_s; });
        return (after - list.begin()) - 1;
    }

    double held_angle_deg(ExpressionEventKind kind, double time_s) const {
        const std::size_t index = kind_index(kind);
        const std::ptrdiff_t k = last_started(index, time_s);
        if (k < 0) return 0.0;
        const ExpressionEvent& event = by_kind[index][static_cast<std::size_t>(k)];
        if (time_s >= event.end_s) return event.amount;
        const double from = start_amounts[index][static_cast<std::size_t>(k)];
        const double fraction = (time_s - event.start_s) / (event.end_s - event.start_s);
        return from + (event.amount - from) * detail::ease_in_out(fraction);
    }

    template <typename Envelope>
    double excursion(ExpressionEventKind kind, double time_s, Envelope envelope) const {
        const std::size_t index = kind_index(kind);
        const std::ptrdiff_t k = last_started(index, time_s);
        if (k < 0) return 0.0;
        const ExpressionEvent& event = by_kind[index][static_cast<std::size_t>(k)];
        if (time_s >= event.end_s) return 0.0;
        return event.amount * envelope((time_s - event.start_s) / (event.end_s - event.start_s));
    }
};

ExpressionSimulator::ExpressionSimulator(const Timeline& timeline, std::uint64_t seed,
                                         const ExpressionStyle& style)
    : impl_(std::make_unique<Impl>()) {
    style.validate();
    detail::check_timeline(timeline);
    impl_->seed = seed;
    impl_->style = style;
    impl_->duration_s = timeline_end_s(timeline);
    const double end_s = impl_->duration_s;
    auto& events = impl_->simulated;

    // A kind switched off is skipped, not drawn and dropped: each kind has its own stream, so the
    // others come out the same either way.
    if (style.is_blink_simulated) {
        detail::Xoshiro256 blink_random(seed, kind_index(ExpressionEventKind::blink));
        simulate_intervals(
            ExpressionEventKind::blink, blink_random, end_s,
            [&] { return blink_random.gamma(style.blink_interval_shape, style.blink_interval_scale_s); },
            style.blink_duration_s, [] { return 1.0; }, events);
    }
    if (style.is_brows_simulated) {
        detail::Xoshiro256 brows_random(seed, kind_index(ExpressionEventKind::brows));
        simulate_intervals(
            ExpressionEventKind::brows, brows_random, end_s,
            [&] { return brows_random.uniform(style.brows_interval_s.min, style.brows_interval_s.max); },
            style.brows_duration_s,
            [&] { return brows_random.uniform(style.brows_amount.min, style.brows_amount.max); }, events);
    }
    if (style.is_tilt_simulated) simulate_head_turns(ExpressionEventKind::tilt, seed, end_s, style.tilt_interval_s,
                                                     style.tilt_duration_s, style.tilt_angle_deg, events);
    if (style.is_turn_simulated) simulate_head_turns(ExpressionEventKind::turn, seed, end_s, style.turn_interval_s,
                                                     style.turn_duration_s, style.turn_angle_deg, events);

    // Thesis 4.5.3: the head goes down before each pause and comes up as it starts. A nod that
    // would start before 0 or before the last nod is up again is left out: pauses that close
    // together get one nod, as a speaker would.
    detail::Xoshiro256 nod_random(seed, kind_index(ExpressionEventKind::nod));
    double nod_free_s = 0.0;
    const std::vector<double> pauses_s =
        style.is_nod_simulated ? pause_starts_s(timeline, style.nod_min_pause_s) : std::vector<double>{};
    for (const double pause_s : pauses_s) {
        const double lead_s = nod_random.uniform(style.nod_lead_s.min, style.nod_lead_s.max);
        const double down_s = nod_random.uniform(style.nod_down_s.min, style.nod_down_s.max);
        const double up_s = nod_random.uniform(style.nod_up_s.min, style.nod_up_s.max);
        const double angle_deg = nod_random.uniform(style.nod_angle_deg.min, style.nod_angle_deg.max);
        const double down_start_s = pause_s - lead_s - down_s;
        if (down_start_s < nod_free_s) continue;
        events.push_back({ExpressionEventKind::nod, down_start_s, pause_s - lead_s, angle_deg});
        events.push_back({ExpressionEventKind::nod, pause_s, pause_s + up_s, 0.0});
        nod_free_s = pause_s + up_s;
    }

    sort_events(events);
    impl_->combined = events;
    impl_->index_events();
}

ExpressionSimulator::~ExpressionSimulator() = default;
ExpressionSimulator::ExpressionSimulator(ExpressionSimulator&&) noexcept = default;
ExpressionSimulator& ExpressionSimulator::operator=(ExpressionSimulator&&) noexcept = default;

std::uint64_t ExpressionSimulator::seed() const {
    return impl_->seed;
}
const ExpressionStyle& ExpressionSimulator::style() const {
    return impl_->style;
}
double ExpressionSimulator::duration_s() const {
    return impl_->duration_s;
}
const std::vector<ExpressionEvent>& ExpressionSimulator::simulated_events() const {
    return impl_->simulated;
}
const std::vector<ExpressionEvent>& ExpressionSimulator::events() const {
    return impl_->combined;
}

void ExpressionSimulator::set_user_events(const std::vector<ExpressionEvent>& events, UserEventMode mode) {
    validate_expression_events(events);
    std::array<bool, kKindCount> is_given{};
    for (const ExpressionEvent& event : events) is_given[kind_index(event.kind)] = true;
    std::vector<ExpressionEvent> combined;
    for (const ExpressionEvent& simulated : impl_->simulated) {
        const bool is_replaced = mode == UserEventMode::replace && is_given[kind_index(simulated.kind)];
        const bool is_covered = std::any_of(events.begin(), events.end(), [&](const ExpressionEvent& user) {
            return user.kind == simulated.kind && overlaps(user, simulated);
        });
        if (!is_replaced && !is_covered) combined.push_back(simulated);
    }
    combined.insert(combined.end(), events.begin(), events.end());
    sort_events(combined);
    impl_->combined = std::move(combined);
    impl_->index_events();
}

Pose ExpressionSimulator::pose_at(double time_s) const {
    Pose pose;
    pose.alpha_deg = impl_->held_angle_deg(ExpressionEventKind::nod, time_s);
    pose.beta_deg = impl_->held_angle_deg(ExpressionEventKind::turn, time_s);
    pose.gamma_deg = impl_->held_angle_deg(ExpressionEventKind::tilt, time_s);
    return pose;
}

Expression ExpressionSimulator::expression_at(double time_s) const {
    Expression expression;
    const double blink = impl_->excursion(ExpressionEventKind::blink, time_s, detail::blink_envelope);
    expression.blink_left = blink;
    expression.blink_right = blink;
    expression.brows = impl_->excursion(ExpressionEventKind::brows, time_s, detail::brows_envelope);
    return expression;
}

}  // namespace v0
}  // namespace talkface

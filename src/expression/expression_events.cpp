// Expression events: names, checks, and the pauses and end of a timeline that events hang on.
#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <string>

#include "common/number_format.hpp"
#include "timing/timeline_checks.hpp"
#include "talkface/errors.hpp"
#include "talkface/expression_simulator.hpp"

namespace talkface {
inline namespace v0 {

namespace {

constexpr std::array<const char*, 5> kKindNames{"blink", "brows", "tilt", "turn", "nod"};

std::string describe_event(const std::vector<ExpressionEvent>& events, std::size_t index) {
    const ExpressionEvent& event = events[index];
    return "event " + std::to_string(index) + " (" + expression_event_kind_name(event.kind) + ", " +
           detail::format_seconds(event.start_s) + "-" + detail::format_seconds(event.end_s) + " s)";
}

bool is_angle(ExpressionEventKind kind) {
    return kind == ExpressionEventKind::tilt || kind == ExpressionEventKind::turn ||
           kind == ExpressionEventKind::nod;
}

}  // namespace

const char* expression_event_kind_name(ExpressionEventKind kind) {
    const auto index = static_cast<std::size_t>(kind);
    return index < kKindNames.size() ? kKindNames[index] : "unknown";
}

ExpressionEventKind expression_event_kind_from_name(std::string_view name) {
    for (std::size_t k = 0; k < kKindNames.size(); ++k) {
        if (name == kKindNames[k]) return static_cast<ExpressionEventKind>(k);
    }
    throw InvalidArgument("event kind \"" + std::string(name) + "\"",
                          "expected one of blink, brows, tilt, turn, nod");
}

void validate_expression_events(const std::vector<ExpressionEvent>& events) {
    for (std::size_t k = 0; k < events.size(); ++k) {
        const ExpressionEvent& event = events[k];
        if (static_cast<std::size_t>(event.kind) >= kKindNames.size()) {
            throw InvalidArgument("event " + std::to_string(k),
                                  "unknown kind " + std::to_string(static_cast<int>(event.kind)));
        }
        if (!std::isfinite(event.start_s) || !std::isfinite(event.end_s) || event.start_s < 0.0) {
            throw InvalidArgument(describe_event(events, k),
                                  "times must be finite seconds from the start of the audio");
        }
        if (event.end_s < event.start_s) {
            throw InvalidArgument(describe_event(events, k), "ends before it starts");
        }
        if (!std::isfinite(event.amount)) {
            throw InvalidArgument(describe_event(events, k), "amount is not a finite number");
        }
        if (is_angle(event.kind) && std::abs(event.amount) > kMaxPoseAngleDeg) {
            throw InvalidArgument(
                describe_event(events, k),
                "angle " + detail::format_shortest(event.amount) + " degrees is beyond +-15 (thesis 1.3.2)");
        }
        if (!is_angle(event.kind) && (event.amount < 0.0 || event.amount > 1.0)) {
            throw InvalidArgument(describe_event(events, k),
                                  "amount " + detail::format_shortest(event.amount) + " is outside 0..1");
        }
    }
    std::vector<std::size_t> order(events.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
        if (events[a].kind != events[b].kind) return events[a].kind < events[b].kind;
        return events[a].start_s < events[b].start_s;
    });
    for (std::size_t k = 1; k < order.size(); ++k) {
        const ExpressionEvent& before = events[order[k - 1]];
        const ExpressionEvent& after = events[order[k]];
        if (before.kind == after.kind && after.start_s < before.end_s) {
            throw InvalidArgument(
                describe_event(events, order[k]),
                "overlaps " + describe_event(events, order[k - 1]) + "; events of one kind must not overlap");
        }
    }
}

std::vector<double> pause_starts_s(const Timeline& timeline, double min_pause_s) {
    detail::check_timeline(timeline);
    std::vector<double> pauses;
    const auto& syllables = timeline.syllables;
    for (std::size_t k = 0; k < syllables.size(); ++k) {
        const bool is_last = k + 1 == syllables.size();
        const bool ends_sentence = is_last || syllables[k + 1].sentence != syllables[k].sentence;
        const bool is_long_pause = !is_last && syllables[k].pause_after &&
                                   syllables[k + 1].start_s - syllables[k].end_s >= min_pause_s;
        if (ends_sentence || is_long_pause) pauses.push_back(syllables[k].end_s);
    }
    if (syllables.empty()) {
        for (const Sentence& sentence : timeline.sentences) {
            if (sentence.end_s > 0.0) pauses.push_back(sentence.end_s);
        }
        std::sort(pauses.begin(), pauses.end());
    }
    return pauses;
}

double timeline_end_s(const Timeline& timeline) {
    double end_s = timeline.duration_s;
    for (const Syllable& syllable : timeline.syllables) end_s = std::max(end_s, syllable.end_s);
    for (const Sentence& sentence : timeline.sentences) end_s = std::max(end_s, sentence.end_s);
    return end_s;
}

}  // namespace v0
}  // namespace talkface

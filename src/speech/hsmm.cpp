#include "speech/hsmm.hpp"

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

#include "speech/avx2_clones.hpp"

namespace talkface::detail {

namespace {

constexpr float kImpossible = -std::numeric_limits<float>::infinity();
// A sentence too long for one search is searched in windows of this many frames, each over the
// states its speech could hold (half as many again as the duration priors expect); only the
// window's first two thirds are kept, up to a syllable's start, where the next window begins.
// The rest is searched again with what follows it, so a window's forced end does not bend the path.
constexpr std::size_t kWindowFrames = 1500;
constexpr double kWindowStateShare = 1.5;
constexpr std::size_t kKeptWindowFrames = 1000;
// How far a window's vowels may be scaled to catch up with the speech (or let it catch up).
constexpr double kMinPace = 0.5;
constexpr double kMaxPace = 2.0;
// The search over the reversed chain (viterbi_align_with_marginals) lets each state start at most
// this many frames from where the path starts it: twice the reach of start_sureness (15 frames),
// so that a start moved to the edge of that reach still has room for the states after it to
// follow; far_start_share weighs every start the band holds (a start 100-300 ms off, where a
// syllable placed a syllable off belongs). Against the whole search: align_bench's tables the same
// on all four corpora; of 4797 confidences of h-reverb, r-reverb and r-music 31 higher, 22 by under
// 0.01, the most by 0.14 (0.32 -> 0.46), none across kLowAlignmentConfidence (session 18, before
// far_start_share).
constexpr std::size_t kMarginalBandFrames = 30;

// Frames [first, end) of a search.
struct FrameBand {
    std::size_t first = 0;
    std::size_t end = 0;
};

// Per frame past its longest explicit duration, what a state with a tail pays: the slope of its
// log-normal prior there, so that the density goes on smoothly as a geometric tail, heavier than
// the log-normal's own (pauses have a long tail; the slope is not weighted by
// PhoneState::duration_weight, so that a speaker's long stop costs no more than it did).
float tail_step(const PhoneState& state, std::size_t longest) {
    const double frames = static_cast<double>(longest);
    const double z = (std::log(frames) - std::log(state.median_frames)) / state.log_sigma;
    return static_cast<float>(-(1.0 + z / state.log_sigma) / frames + state.frame_log_penalty);
}

// What skipping `state` costs; minus infinity where the path must pass it.
float skip_score(const PhoneState& state) {
    return state.is_optional ? 0.0f : static_cast<float>(state.skip_log_penalty);
}

// The row of the prefix sums that scores `phone_class`: kGenericSpeech has the last one.
std::size_t prefix_row(PhoneClass phone_class) { return static_cast<std::size_t>(phone_class); }

// What a state entered at frame t of the whole `emissions` gains (EmissionScores::boundary).
float boundary_bonus(const EmissionScores& emissions, std::size_t t) {
    return emissions.boundary.empty() ? 0.0f : emissions.boundary[t];
}

// `table` at least `size` long; what it holds is left as it is.
void grow_to(std::vector<float>& table, std::size_t size) {
    if (table.size() < size) table.resize(size);
}

// The conversions between the search's float tables and its double prefix sums, in chunks of a
// fixed length: GCC's -O2 vectorizes only loops whose length it knows (its cheapest cost model),
// and these ran one frame at a time, a third of the search's instructions (bench/README.md,
// Session 27). No test for an impossible score is needed: the prefix sums are finite (finite log
// densities, each frame's best subtracted), so an impossible score stays impossible, as before.
constexpr std::size_t kConvertChunk = 8;

// out[t] = values[t] - offsets[t] in double, rounded to float, for t < count.
void subtract_in_double(const float* __restrict values, const double* __restrict offsets,
                        float* __restrict out, std::size_t count) {
    std::size_t t = 0;
    for (; t + kConvertChunk <= count; t += kConvertChunk)
        for (std::size_t k = t; k < t + kConvertChunk; ++k)
            out[k] = static_cast<float>(values[k] - offsets[k]);
    for (; t < count; ++t) out[t] = static_cast<float>(values[t] - offsets[t]);
}

// values[t] = offsets[t] + values[t] in double, rounded to float, for t < count.
void add_in_double(float* __restrict values, const double* __restrict offsets, std::size_t count) {
    std::size_t t = 0;
    for (; t + kConvertChunk <= count; t += kConvertChunk)
        for (std::size_t k = t; k < t + kConvertChunk; ++k)
            values[k] = static_cast<float>(offsets[k] + values[k]);
    for (; t < count; ++t) values[t] = static_cast<float>(offsets[t] + values[t]);
}

// max over i < count of a[i] + b[i], in Eigen's packets: the search's innermost loop, which the
// compiler left scalar (the maximum is exact in any order: the same value as one by one).
float max_of_sums(const float* a, const float* b, std::size_t count) {
    if (count == 0) return kImpossible;
    using Floats = Eigen::Map<const Eigen::ArrayXf>;
    const auto size = static_cast<Eigen::Index>(count);
    return (Floats(a, size) + Floats(b, size)).maxCoeff();
}

// max_of_sums for kSumBlockFrames frames side by side: out[k] = max over i < count of
// a[k + i] + b[i]. The frames' maxima are kept in registers while the durations run, so that each
// sum is one packet's lane, not a reduction per frame (the search's costliest part, bench/README.md
// Session 22); every sum is the same float addition as in max_of_sums, and the maximum exact.
// Where the library has AVX2 clones (avx2_clones.hpp), in vectors of eight floats of GCC's own
// rather than Eigen's packets, which Eigen picks as it is compiled (SSE for the baseline x86-64):
// two SSE halves each in the default clone, one register in the AVX2 one (bench/README.md,
// Session 28: the search 82 -> 52 M instructions on a room's passage).
constexpr std::size_t kSumBlockFrames = 16;
#if TALKFACE_HAS_AVX2_CLONES
typedef float Floats8 __attribute__((vector_size(32)));
TALKFACE_AVX2_CLONES void max_of_sums_block(const float* a, const float* b, std::size_t count, float* out) {
    Floats8 low = {kImpossible, kImpossible, kImpossible, kImpossible,
                   kImpossible, kImpossible, kImpossible, kImpossible};
    Floats8 high = low;
    for (std::size_t i = 0; i < count; ++i) {
        Floats8 low_sum, high_sum;
        std::memcpy(&low_sum, a + i, sizeof low_sum);
        std::memcpy(&high_sum, a + i + 8, sizeof high_sum);
        low_sum += b[i];
        high_sum += b[i];
        low = low > low_sum ? low : low_sum;
        high = high > high_sum ? high : high_sum;
    }
    std::memcpy(out, &low, sizeof low);
    std::memcpy(out + 8, &high, sizeof high);
}
#else
void max_of_sums_block(const float* a, const float* b, std::size_t count, float* out) {
    using Block = Eigen::Array<float, kSumBlockFrames, 1>;
    Block best = Block::Constant(kImpossible);
    for (std::size_t i = 0; i < count; ++i) best = best.max(Eigen::Map<const Block>(a + i) + b[i]);
    Eigen::Map<Block> result(out);
    result = best;
}
#endif

// One search of states [first_state, end_state) over frames [first_frame, end_frame), starting in
// first_state at first_frame, in three steps: the emissions summed per class, the tables filled
// state by state (the way forward), and the best path read back from them (the way back).
// Segments are in the frames of `emissions`, each score multiplied by `emission_weight`.
class SegmentSearch {
public:
    SegmentSearch(const std::vector<PhoneState>& states, std::size_t first_state, std::size_t end_state,
                  const EmissionScores& emissions, std::size_t first_frame, std::size_t end_frame,
                  ViterbiWorkspace& workspace)
        : states_(states), first_state_(first_state), state_count_(end_state - first_state), emissions_(emissions),
          first_frame_(first_frame), frames_(end_frame - first_frame), width_(frames_ + 1), workspace_(workspace) {}

    // Searches only paths on which each state j ends within `bands`[j] (frames of the search),
    // where the way there is needed only near a known path: the work is the bands' width, not the
    // search's. `bands` must outlive fill_tables.
    void limit_finishes(const std::vector<FrameBand>& bands) { finish_bands_ = &bands; }

    // Prefix sums per class: the emission of any span is one subtraction. Each frame's best class
    // is subtracted first (every path pays one emission per frame, so no decision changes): the
    // sums along good paths then stay small, where float keeps its resolution.
    void sum_emissions(double emission_weight) {
        auto& prefix = workspace_.prefix;
        // Generic speech scores each frame as its best class does: its row is all zeros.
        prefix.assign(static_cast<std::size_t>(kPhoneClassCount + 1) * width_, 0.0);
        for (std::size_t t = 0; t < frames_; ++t) {
            const float* row = &emissions_.values[(first_frame_ + t) * kPhoneClassCount];
            const float best = *std::max_element(row, row + kPhoneClassCount);
            for (std::size_t c = 0; c < kPhoneClassCount; ++c)
                prefix[c * width_ + t + 1] = prefix[c * width_ + t] + emission_weight * static_cast<double>(row[c] - best);
        }
    }

    // entry[j][t]: best score of a path whose state j starts at frame t; finish[j][t]: of one whose
    // state j ends just before frame t. Which duration and which skip won is found again on the
    // way back, so only these two tables are kept.
    void fill_tables() {
        auto& entry = workspace_.entry;
        auto& finish = workspace_.finish;
        auto& entry_minus_prefix = workspace_.entry_minus_prefix;
        workspace_.durations.forget_beyond_limit();
        // Every cell of the rows searched is written below: the tables only grow, since a resize
        // down and up again zeroes the grown part for nothing (a sentence's searches alternate
        // between its chain and shorter windows of it).
        grow_to(entry, state_count_ * width_);
        grow_to(finish, state_count_ * width_);
        grow_to(entry_minus_prefix, width_);
        std::fill(entry.begin(), entry.begin() + static_cast<std::ptrdiff_t>(width_), kImpossible);
        entry[0] = 0.0f;
        for (std::size_t j = 0; j < state_count_; ++j) {
            const PhoneState& state = states_[first_state_ + j];
            float* entry_row = &entry[j * width_];
            if (j > 0) {
                const float* previous_finish = &finish[(j - 1) * width_];
                const float* previous_entry = &entry[(j - 1) * width_];
                const float skip = skip_score(states_[first_state_ + j - 1]);
                // A skipped state passes on the bonus its predecessor's finish already got at t. In
                // Eigen's packets (its max is std::max's, lane by lane).
                using Row = Eigen::Map<Eigen::ArrayXf>;
                using ConstRow = Eigen::Map<const Eigen::ArrayXf>;
                const auto size = static_cast<Eigen::Index>(width_);
                Row entries(entry_row, size);
                entries = ConstRow(previous_finish, size);
                if (!emissions_.boundary.empty())
                    entries += ConstRow(&emissions_.boundary[first_frame_], size);
                if (skip != kImpossible) entries = entries.max(ConstRow(previous_entry, size) + skip);
            }
            const std::size_t first_entry = static_cast<std::size_t>(
                std::find_if(entry_row, entry_row + width_, [](float v) { return v != kImpossible; }) -
                entry_row);
            // Before its first entry a state's entry_minus_prefix is impossible: only the frames a
            // duration from the first finish reaches back to are set so.
            const std::vector<float>& duration_score = prepare_state(j, first_entry);
            const std::size_t longest = longest_duration(state, frames_);
            std::fill(entry_minus_prefix.begin() +
                          static_cast<std::ptrdiff_t>(first_entry - std::min(first_entry, longest + 1)),
                      entry_minus_prefix.begin() + static_cast<std::ptrdiff_t>(first_entry), kImpossible);
            const std::size_t shortest = longest + 1 - duration_score.size();
            const double* class_prefix = &workspace_.prefix[prefix_row(state.phone_class) * width_];
            float* finish_row = &finish[j * width_];
            const std::size_t first_finish = duration_score.empty() ? width_ : std::min(width_, first_entry + shortest);
            const FrameBand band = finish_bands_ ? (*finish_bands_)[j] : FrameBand{0, width_};
            const std::size_t from = std::max(first_finish, band.first);
            const std::size_t to = std::max(from, std::min(width_, band.end));
            std::fill(finish_row, finish_row + from, kImpossible);
            std::fill(finish_row + to, finish_row + width_, kImpossible);
            // tail: the best entry_minus_prefix[t - d] + (d - longest) * step over d > longest,
            // carried over the frames before the band too.
            const bool has_tail = state.has_tail && !duration_score.empty();
            const float step = has_tail ? tail_step(state, longest) : 0.0f;
            float tail = kImpossible;
            if (has_tail)
                for (std::size_t t = std::max(first_finish, longest + 1); t < from; ++t)
                    tail = std::max(tail, entry_minus_prefix[t - longest - 1]) + step;
            // Each finish's best entry less the prefix first, then the prefix added back.
            for (std::size_t t = from; t < to;) {
                // d runs from min(longest, t) down to shortest: entries t - d, durations reversed.
                if (t >= longest && t + kSumBlockFrames <= to) {
                    max_of_sums_block(&entry_minus_prefix[t - longest], duration_score.data(),
                                      duration_score.size(), &finish_row[t]);
                    t += kSumBlockFrames;
                } else {
                    const std::size_t skipped = t >= longest ? 0 : longest - t;
                    finish_row[t] = max_of_sums(&entry_minus_prefix[t + skipped - longest],
                                                &duration_score[skipped], duration_score.size() - skipped);
                    ++t;
                }
            }
            if (has_tail)
                for (std::size_t t = std::max(from, longest + 1); t < to; ++t) {
                    tail = std::max(tail, entry_minus_prefix[t - longest - 1]) + step;
                    finish_row[t] = std::max(finish_row[t], tail + duration_score[0]);
                }
            add_in_double(&finish_row[from], &class_prefix[from], to - from);
        }
    }

    // The best path, read back from the last frame. With `is_open_end` it may stop in any state at
    // the last frame (a window of a longer search); otherwise it ends after the last state. Empty
    // if no path fits.
    std::vector<StateSegment> trace_back(bool is_open_end) {
        const auto& entry = workspace_.entry;
        const auto& finish = workspace_.finish;
        std::size_t j = state_count_ - 1;
        std::size_t t = frames_;
        bool is_skipped = false;
        if (is_open_end) {
            for (std::size_t k = 0; k < state_count_; ++k)
                if (finish[k * width_ + t] > finish[j * width_ + t]) j = k;
            if (finish[j * width_ + t] == kImpossible) return {};
        } else {
            const float skip = skip_score(states_[first_state_ + j]);
            is_skipped = skip != kImpossible && entry[j * width_ + t] + skip > finish[j * width_ + t];
            if (!is_skipped && finish[j * width_ + t] == kImpossible) return {};
        }
        std::vector<StateSegment> segments;
        for (;;) {
            if (!is_skipped) {
                const std::size_t best_frames = best_duration(j, t);
                segments.push_back({first_state_ + j, first_frame_ + t - best_frames, first_frame_ + t});
                t -= best_frames;
            }
            if (j == 0) break;
            const float skip = skip_score(states_[first_state_ + j - 1]);
            const float arrived = finish[(j - 1) * width_ + t] + boundary_bonus(emissions_, first_frame_ + t);
            is_skipped = skip != kImpossible && entry[(j - 1) * width_ + t] + skip > arrived;
            --j;
        }
        std::reverse(segments.begin(), segments.end());
        return segments;
    }

private:
    // Fills entry_minus_prefix for state j over frames [first, end) (all of them by default);
    // returns its duration scores (DurationTables::of).
    const std::vector<float>& prepare_state(std::size_t j, std::size_t first = 0,
                                            std::size_t end = kAllFrames) {
        const PhoneState& state = states_[first_state_ + j];
        const double* class_prefix = &workspace_.prefix[prefix_row(state.phone_class) * width_];
        const float* entry_row = &workspace_.entry[j * width_];
        auto& entry_minus_prefix = workspace_.entry_minus_prefix;
        if (first < std::min(end, width_))
            subtract_in_double(&entry_row[first], &class_prefix[first], &entry_minus_prefix[first],
                               std::min(end, width_) - first);
        return workspace_.durations.of(state, frames_);
    }
    static constexpr std::size_t kAllFrames = std::numeric_limits<std::size_t>::max();

    // How many frames state j held on the best path that ends it just before frame t: the
    // duration the way forward chose there, found again.
    std::size_t best_duration(std::size_t j, std::size_t t) {
        const auto& entry_minus_prefix = workspace_.entry_minus_prefix;
        // Only the entries a duration ending at t reaches back to: the way back reads one frame a
        // state, and the whole row for each cost a twelfth as much as the way forward.
        const PhoneState& state = states_[first_state_ + j];
        const std::size_t reach = state.has_tail ? t : std::min(t, std::min(state.max_frames, frames_));
        const std::vector<float>& duration_score = prepare_state(j, t - reach, t);
        const std::size_t longest = longest_duration(state, frames_);
        const std::size_t shortest = longest + 1 - duration_score.size();
        float best = kImpossible;
        std::size_t best_frames = shortest;
        for (std::size_t d = shortest; d <= std::min(longest, t); ++d) {
            const float total = entry_minus_prefix[t - d] + duration_score[longest - d];
            if (total > best) {
                best = total;
                best_frames = d;
            }
        }
        if (states_[first_state_ + j].has_tail && !duration_score.empty()) {
            const float step = tail_step(states_[first_state_ + j], longest);
            for (std::size_t d = longest + 1; d <= t; ++d) {
                const float total = entry_minus_prefix[t - d] + duration_score[0] + static_cast<float>(d - longest) * step;
                if (total > best) {
                    best = total;
                    best_frames = d;
                }
            }
        }
        return best_frames;
    }

    const std::vector<PhoneState>& states_;
    std::size_t first_state_;
    std::size_t state_count_;
    const EmissionScores& emissions_;
    std::size_t first_frame_;
    std::size_t frames_;
    std::size_t width_;
    ViterbiWorkspace& workspace_;
    const std::vector<FrameBand>* finish_bands_ = nullptr;
};

// The best path of one search (SegmentSearch); empty if no path fits.
std::vector<StateSegment> search(const std::vector<PhoneState>& states, std::size_t first_state, std::size_t end_state,
                                 const EmissionScores& emissions, double emission_weight, std::size_t first_frame,
                                 std::size_t end_frame, bool is_open_end, ViterbiWorkspace& workspace) {
    SegmentSearch segment_search(states, first_state, end_state, emissions, first_frame, end_frame, workspace);
    segment_search.sum_emissions(emission_weight);
    segment_search.fill_tables();
    return segment_search.trace_back(is_open_end);
}

// Frames the priors expect of states [first, end): the sum of the medians of those a path must
// pass, consonants and vowels apart.
struct ExpectedFrames {
    double fixed = 0.0;
    double stretching = 0.0;
};

ExpectedFrames expected_frames(const std::vector<PhoneState>& states, std::size_t first, std::size_t end) {
    ExpectedFrames expected;
    for (std::size_t s = first; s < end; ++s) {
        if (states[s].is_optional) continue;
        (states[s].stretches ? expected.stretching : expected.fixed) += states[s].median_frames;
    }
    return expected;
}

}  // namespace

std::vector<StateSegment> viterbi_align(const std::vector<PhoneState>& states, const EmissionScores& emissions,
                                        ViterbiWorkspace& workspace, std::size_t stop_frame, double emission_weight) {
    const std::size_t frames = emissions.frame_count;
    // Frames of audio per frame the priors expect, over the whole sentence (above 1 by its pauses).
    const ExpectedFrames whole = expected_frames(states, 0, states.size());
    const double frames_per_expected = static_cast<double>(frames) / std::max(whole.fixed + whole.stretching, 1.0);
    std::vector<StateSegment> path;
    std::vector<PhoneState> window_states;
    std::size_t first_state = 0;
    std::size_t first_frame = 0;
    while (first_frame < stop_frame) {
        const std::size_t remaining_frames = frames - first_frame;
        if ((states.size() - first_state) * (remaining_frames + 1) <= kMaxSearchCells) {
            const auto rest = search(states, first_state, states.size(), emissions, emission_weight, first_frame, frames, false, workspace);
            if (rest.empty()) return {};
            path.insert(path.end(), rest.begin(), rest.end());
            return path;
        }
        // The window keeps pace with the speech: its vowels are scaled so that the rest of the text
        // would fill the rest of the audio at the sentence's share of pauses. A window whose open
        // end lags or leads by a syllable is thus pulled back by the next, and small errors do not
        // add up over an hour.
        const ExpectedFrames rest = expected_frames(states, first_state, states.size());
        const double pace = std::clamp(
            (static_cast<double>(remaining_frames) / frames_per_expected - rest.fixed) / std::max(rest.stretching, 1.0),
            kMinPace, kMaxPace);
        std::size_t end_state = first_state;
        double window_expected = 0.0;
        while (end_state < states.size() && window_expected < kWindowStateShare * kWindowFrames) {
            const PhoneState& state = states[end_state];
            if (!state.is_optional) window_expected += state.median_frames * (state.stretches ? pace : 1.0);
            ++end_state;
        }
        const bool reaches_end = end_state == states.size();
        // Speech far longer than the rest of the text cannot be aligned to it: no window needed.
        if (reaches_end && remaining_frames > 4 * kWindowFrames) return {};
        const std::size_t end_frame = reaches_end ? frames : std::min(frames, first_frame + kWindowFrames);
        window_states.assign(states.begin() + static_cast<std::ptrdiff_t>(first_state),
                             states.begin() + static_cast<std::ptrdiff_t>(end_state));
        scale_vowels(window_states, pace);
        auto window = search(window_states, 0, window_states.size(), emissions, emission_weight, first_frame, end_frame,
                             !reaches_end, workspace);
        if (window.empty()) return {};
        for (auto& segment : window) segment.state += first_state;
        if (reaches_end) {
            path.insert(path.end(), window.begin(), window.end());
            return path;
        }
        // Keep the window up to the last syllable that starts in its kept part.
        std::size_t kept = 0;
        std::size_t previous_syllable = states[window.front().state].syllable;
        for (std::size_t k = 1; k < window.size() && window[k].first_frame <= first_frame + kKeptWindowFrames; ++k) {
            const PhoneState& state = states[window[k].state];
            if (is_pause(state.role)) continue;
            if (state.syllable != previous_syllable) kept = k;
            previous_syllable = state.syllable;
        }
        if (kept == 0) return {};
        path.insert(path.end(), window.begin(), window.begin() + static_cast<std::ptrdiff_t>(kept));
        first_state = window[kept].state;
        first_frame = window[kept].first_frame;
    }
    return path;
}

std::vector<StateSegment> viterbi_align_with_marginals(const std::vector<PhoneState>& states,
                                                       const EmissionScores& emissions,
                                                       ViterbiWorkspace& workspace,
                                                       EntryMaxMarginals& marginals) {
    marginals.values.clear();
    std::vector<StateSegment> path = viterbi_align(states, emissions, workspace);
    const std::size_t frames = emissions.frame_count;
    const std::size_t width = frames + 1;
    if (path.empty() || states.size() * width > kMaxSearchCells) return path;
    // Searched whole: the workspace holds the search's entry table, the best way to each (state, frame).
    marginals.width = width;
    marginals.values.assign(workspace.entry.begin(),
                            workspace.entry.begin() + static_cast<std::ptrdiff_t>(states.size() * width));
    // The same search over the reversed chain and frames: its finish[j'][t'] is the best way from
    // state S-1-j' entered at frame T-t' to the end. Each state's duration scores do not depend on
    // the direction, and a boundary bonus is paid by the state entered at that frame either way.
    const std::vector<PhoneState> reversed_states(states.rbegin(), states.rend());
    EmissionScores reversed;
    reversed.frame_count = frames;
    reversed.values.resize(frames * kPhoneClassCount);
    for (std::size_t t = 0; t < frames; ++t)
        std::copy_n(&emissions.values[(frames - 1 - t) * kPhoneClassCount], kPhoneClassCount,
                    &reversed.values[t * kPhoneClassCount]);
    if (!emissions.boundary.empty())
        reversed.boundary.assign(emissions.boundary.rbegin(),
                                 emissions.boundary.rbegin() + static_cast<std::ptrdiff_t>(width));
    // Each reversed state ends where its forward state starts on the path (a skipped one where the
    // path passes it), within kMarginalBandFrames.
    const std::size_t last = states.size() - 1;
    std::vector<FrameBand> bands(states.size());
    std::size_t passed = 0;
    auto segment = path.begin();
    for (std::size_t j = 0; j < states.size(); ++j) {
        if (segment != path.end() && segment->state == j) passed = segment->first_frame;
        const std::size_t reversed_end = frames - passed;
        bands[last - j] = {reversed_end > kMarginalBandFrames ? reversed_end - kMarginalBandFrames : 0,
                           reversed_end + kMarginalBandFrames + 1};
        if (segment != path.end() && segment->state == j) passed = (segment++)->end_frame;
    }
    SegmentSearch backward(reversed_states, 0, states.size(), reversed, 0, frames, workspace);
    backward.limit_finishes(bands);
    backward.sum_emissions(1.0);
    backward.fill_tables();
    for (std::size_t j = 0; j < states.size(); ++j)
        for (std::size_t t = 0; t < width; ++t)
            marginals.values[j * width + t] += workspace.finish[(last - j) * width + frames - t];
    return path;
}

}  // namespace talkface::detail

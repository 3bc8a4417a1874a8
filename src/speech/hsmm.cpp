#include "speech/hsmm.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

namespace talkface::detail {

namespace {

constexpr float kImpossible = -std::numeric_limits<float>::infinity();

// log of a log-normal density at d frames, up to a constant shared by every path.
double log_normal_duration(double frames, double median_frames, double log_sigma) {
    const double z = (std::log(frames) - std::log(median_frames)) / log_sigma;
    return -std::log(frames) - 0.5 * z * z - std::log(log_sigma);
}

}  // namespace

std::vector<StateSegment> viterbi_align(const std::vector<PhoneState>& states, const EmissionScores& emissions) {
    const std::size_t frames = emissions.frame_count;
    const std::size_t state_count = states.size();
    const std::size_t width = frames + 1;
    // Prefix sums per class: the emission of any span is one subtraction.
    std::vector<double> prefix(static_cast<std::size_t>(kPhoneClassCount) * width, 0.0);
    for (int c = 0; c < kPhoneClassCount; ++c) {
        double* row = &prefix[static_cast<std::size_t>(c) * width];
        for (std::size_t t = 0; t < frames; ++t) row[t + 1] = row[t] + emissions.at(t, c);
    }
    // entry[j][t]: best score of a path whose state j starts at frame t; finish[j][t]: of one whose
    // state j ends just before frame t. Float: scores stay within a few 1e5, where float
    // resolution (~0.01) cannot change a decision that matters, and halves the memory.
    std::vector<float> entry(state_count * width, kImpossible);
    std::vector<float> finish(state_count * width, kImpossible);
    std::vector<std::uint16_t> held_frames(state_count * width, 0);
    std::vector<std::uint8_t> entered_by_skip(state_count * width, 0);
    std::vector<double> duration_score;
    entry[0] = 0.0f;
    for (std::size_t j = 0; j < state_count; ++j) {
        const PhoneState& state = states[j];
        float* entry_row = &entry[j * width];
        if (j > 0) {
            const float* previous_finish = &finish[(j - 1) * width];
            const float* previous_entry = &entry[(j - 1) * width];
            for (std::size_t t = 0; t <= frames; ++t) {
                entry_row[t] = previous_finish[t];
                if (states[j - 1].is_optional && previous_entry[t] > entry_row[t]) {
                    entry_row[t] = previous_entry[t];
                    entered_by_skip[j * width + t] = 1;
                }
            }
        }
        const std::size_t max_frames = std::min<std::size_t>(std::min(state.max_frames, frames), 65535);
        const std::size_t min_frames = std::max<std::size_t>(state.min_frames, 1);
        duration_score.assign(max_frames + 1, 0.0);
        const bool is_flat = state.role == StateRole::edge_silence;
        for (std::size_t d = min_frames; d <= max_frames; ++d)
            duration_score[d] = (is_flat ? 0.0 : log_normal_duration(static_cast<double>(d), state.median_frames, state.log_sigma)) +
                                state.entry_log_penalty;
        const double* class_prefix = &prefix[static_cast<std::size_t>(state.phone_class) * width];
        float* finish_row = &finish[j * width];
        std::uint16_t* held_row = &held_frames[j * width];
        for (std::size_t t = min_frames; t <= frames; ++t) {
            double best = kImpossible;
            std::size_t best_frames = 0;
            const std::size_t longest = std::min(max_frames, t);
            for (std::size_t d = min_frames; d <= longest; ++d) {
                const float start_score = entry_row[t - d];
                if (start_score == kImpossible) continue;
                const double total = start_score + (class_prefix[t] - class_prefix[t - d]) + duration_score[d];
                if (total > best) {
                    best = total;
                    best_frames = d;
                }
            }
            finish_row[t] = static_cast<float>(best);
            held_row[t] = static_cast<std::uint16_t>(best_frames);
        }
    }
    // The path ends after the last state, or skips it if it is optional.
    std::size_t j = state_count - 1;
    std::size_t t = frames;
    bool skips_last = states[j].is_optional && entry[j * width + t] > finish[j * width + t];
    if (!skips_last && finish[j * width + t] == kImpossible) return {};
    std::vector<StateSegment> segments;
    bool is_skipped = skips_last;
    for (;;) {
        if (!is_skipped) {
            const std::size_t d = held_frames[j * width + t];
            segments.push_back({j, t - d, t});
            t -= d;
        }
        if (j == 0) break;
        is_skipped = entered_by_skip[j * width + t] != 0;
        --j;
    }
    std::reverse(segments.begin(), segments.end());
    return segments;
}

}  // namespace talkface::detail

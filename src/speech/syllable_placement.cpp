#include "speech/syllable_placement.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "speech/alignment_confidence.hpp"

namespace talkface::detail {

namespace {

// Silence before a burst (a pause and the closure together) from which on the closure is taken
// for part of a pause: a stop's closure lasts under 0.2 s.
constexpr std::size_t kPauseBeforeBurstFrames = 20;

}  // namespace

void place_syllables(const SentenceChain& chain, const std::vector<StateSegment>& path,
                     const std::vector<std::vector<StateSegment>>& other_paths, const EmissionScores& scores,
                     const FeatureTrack& track, Timeline& result, std::vector<double>& evidence) {
    // The last frame may run past the audio's last sample: no time is later than the audio's end.
    auto time_s = [&](std::size_t frame) {
        return std::min(track.duration_s, frame_time_s(chain.searched.first_frame + frame));
    };
    std::vector<SyllableFrames> frames(chain.syllables.size());
    for (std::size_t local = 0; local < chain.syllables.size(); ++local) {
        Syllable& syllable = result.syllables[chain.syllable_indices[local]];
        std::size_t first = 0, end = 0;
        std::optional<std::size_t> final_first;
        bool has_start = false;
        for (std::size_t p = 0; p < path.size(); ++p) {
            const PhoneState& state = chain.states[path[p].state];
            if (state.syllable != local || is_pause(state.role)) continue;
            std::size_t segment_first = path[p].first_frame;
            // SPEC: after a pause the closure cannot be told from the pause; the syllable starts
            // at the burst. A pause the transcript does not mark counts when it is longer than
            // any closure (a sentence end in a transcript without punctuation).
            if (state.role == StateRole::closure && p > 0) {
                const StateSegment& before = path[p - 1];
                const StateRole role = chain.states[before.state].role;
                const std::size_t silence = before.end_frame - before.first_frame + path[p].end_frame - path[p].first_frame;
                if (role == StateRole::comma_pause || (role == StateRole::short_pause && silence >= kPauseBeforeBurstFrames))
                    segment_first = path[p].end_frame;
            }
            if (!has_start) {
                first = segment_first;
                has_start = true;
            }
            end = path[p].end_frame;
            if (state.role == StateRole::final && !final_first) final_first = path[p].first_frame;
        }
        if (local + 1 == chain.syllables.size()) {
            const std::size_t offset = chain.searched.first_frame;
            const std::size_t trimmed = end_before_tail(track, offset + first, offset + end) - offset;
            end = std::max(trimmed, final_first.value_or(first) + 1);
        }
        syllable.start_s = time_s(first);
        syllable.end_s = time_s(std::max(end, first + 1));
        syllable.final_start_s = time_s(final_first.value_or(first));
        frames[local] = {first, std::max(end, first + 1)};
    }
    std::vector<double> fits = syllable_fits(chain, path, scores, frames);
    const std::vector<double> timing = syllable_timing(chain, path, scores, frames);
    for (std::size_t local = 0; local < fits.size(); ++local) fits[local] += timing[local];
    const auto placed = syllable_evidence(fits);
    const auto steadiness = syllable_steadiness(chain, path, other_paths);
    for (std::size_t local = 0; local < chain.syllables.size(); ++local)
        evidence[chain.syllable_indices[local]] = placed[local] + steadiness[local];
}

std::vector<AlignedStretch> stretches_of(const SentenceChain& chain, const std::vector<StateSegment>& path) {
    std::vector<AlignedStretch> stretches;
    for (const auto& segment : path) {
        const PhoneState& state = chain.states[segment.state];
        const bool is_pause_state = is_pause(state.role);
        const std::size_t syllable = chain.syllable_indices[state.syllable];
        const std::size_t first = chain.searched.first_frame + segment.first_frame;
        const std::size_t end = chain.searched.first_frame + segment.end_frame;
        if (!stretches.empty() && stretches.back().is_pause == is_pause_state && stretches.back().syllable == syllable) {
            stretches.back().end_frame = end;
        } else {
            stretches.push_back({first, end, is_pause_state, syllable});
        }
    }
    return stretches;
}

FrameSpan aligned_span(const Timeline& result, const SentenceChain& chain, std::size_t k) {
    FrameSpan span{std::numeric_limits<std::size_t>::max(), 0};
    for (const std::size_t i : chain.syllable_indices) {
        const Syllable& syllable = result.syllables[i];
        if (syllable.sentence != k) continue;
        span.first_frame = std::min(span.first_frame, static_cast<std::size_t>(std::lround(syllable.start_s / kFrameStepS)));
        span.end_frame = std::max(span.end_frame, static_cast<std::size_t>(std::lround(syllable.end_s / kFrameStepS)));
    }
    return span;
}

}  // namespace talkface::detail

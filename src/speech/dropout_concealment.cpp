#include "speech/dropout_concealment.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "speech/sentence_cutter.hpp"

namespace talkface::detail {

namespace {

// Whether the frames `span` of a dropout lie inside the speech of `loudness`, after its start and
// before its end, with speech frames either side, which the concealment draws from. Speech on one
// side only is a sound's end or start: a closure's silence (a codec writes zeros there as well:
// AMR-NB at 4.75 kb/s, a 20 ms frame of them inside espeak-ng's closure before 究 jiu1, which drawn
// over took the syllable's onset 40 ms late) or a drum's cut into a pause.
bool is_inside_speech(const LoudnessProfile& loudness, const FrameSpan& span) {
    return span.first_frame > loudness.speech_first_frame && span.end_frame < loudness.speech_end_frame &&
           is_speech_frame(loudness, span.first_frame - 1) && is_speech_frame(loudness, span.end_frame);
}

// The frames whose window holds kTakenShare of the dropout's zeros.
FrameSpan taken_frames(const Dropout& dropout, std::size_t frames) {
    const auto zeros = static_cast<double>(dropout.end_sample - dropout.first_sample);
    const auto overlap = [&](std::size_t t) {
        // Frame t's window is [t * kHopSamples - kWindowLeadSamples, ... + kWindowSamples).
        const auto start = static_cast<double>(t * kHopSamples) - static_cast<double>(kWindowLeadSamples);
        const double first = std::max(start, static_cast<double>(dropout.first_sample));
        const double end =
            std::min(start + static_cast<double>(kWindowSamples), static_cast<double>(dropout.end_sample));
        return end - first;
    };
    FrameSpan span{frames, frames};
    // Frames from two before the one whose 10 ms the dropout starts in reach into it.
    const std::size_t from = std::max<std::size_t>(dropout.first_sample / kHopSamples, 2) - 2;
    for (std::size_t t = from; t < frames && t * kHopSamples < dropout.end_sample + kWindowLeadSamples; ++t) {
        if (overlap(t) < kTakenShare * zeros) continue;
        if (span.first_frame == frames) span.first_frame = t;
        span.end_frame = t + 1;
    }
    if (span.first_frame == frames) return {0, 0};
    return span;
}

}  // namespace

void conceal_dropouts(FeatureTrack& track) {
    if (track.dropouts.empty()) return;
    const std::size_t frames = track.frame_count;
    const LoudnessProfile loudness = measure_loudness(track);
    std::vector<bool> taken(frames, false);
    for (const Dropout& dropout : track.dropouts) {
        const FrameSpan span = taken_frames(dropout, frames);
        if (span.length() == 0 || !is_inside_speech(loudness, span)) continue;
        std::fill(taken.begin() + static_cast<std::ptrdiff_t>(span.first_frame),
                  taken.begin() + static_cast<std::ptrdiff_t>(span.end_frame), true);
    }
    // Dropouts whose frames meet are drawn over as one, from the frame before the first to the
    // frame after the last.
    for (std::size_t first = 1; first < frames;) {
        if (!taken[first]) {
            ++first;
            continue;
        }
        std::size_t end = first;
        while (end < frames && taken[end]) ++end;
        const std::size_t before = first - 1;
        const auto steps = static_cast<float>(end - before);
        for (std::size_t t = first; t < end; ++t) {
            const float along = static_cast<float>(t - before) / steps;
            for (int column = 0; column < kFeatureCount; ++column) {
                const float from = track.at(before, column), to = track.at(end, column);
                track.values[t * kFeatureCount + static_cast<std::size_t>(column)] =
                    from + (to - from) * along;
            }
        }
        first = end;
    }
}

}  // namespace talkface::detail

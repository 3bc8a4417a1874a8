#include "speech/dropout_concealment.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "speech/sentence_cutter.hpp"

namespace talkface::detail {

namespace {

// How far from a dropout (0.1 s, half a syllable) and how close to the level of loud speech
// (speech_level_db) the speech on its one speaking side must come for it to be a syllable's.
constexpr std::size_t kSyllableReachFrames = 10;
constexpr float kSyllableBelowLevelDb = 10.0f;

// Whether the frames `span` of a dropout cut the voice inside the speech of `loudness`, after its
// start and before its end: with speech frames either side, or on one side only where a syllable
// lies, its speech coming within kSyllableBelowLevelDb of the level of loud speech within
// kSyllableReachFrames. Speech on one side only is a syllable's start or end cut (8 of the person's
// 13 dropouts in the sweep; left as they were, the syllables were taken to their edges, 新 xin1 76
// ms early, 陸 lu4 62 ms late), or a drum's cut between its hits in the voice's pauses, the next
// hit on one side (bench/ m-drums: 16 in its tuning passages, 12 of them with no sound within 0.1 s
// of the cut closer than 12-25 dB to loud speech, the other 4 where the voice starts; drawn over
// all, they filled the voice's pauses: tuning 87.9 -> 82.7% within 50 ms). With speech on neither
// side it lies in a pause. A codec's pause frames, zeros inside a closure with its ringing either
// side, are no dropout (outside_codec_pauses).
bool cuts_voice(const LoudnessProfile& loudness, const FrameSpan& span) {
    if (span.first_frame <= loudness.speech_first_frame || span.end_frame >= loudness.speech_end_frame)
        return false;
    const bool is_speech_before = is_speech_frame(loudness, span.first_frame - 1);
    const bool is_speech_after = is_speech_frame(loudness, span.end_frame);
    if (is_speech_before == is_speech_after) return is_speech_before;
    float loudest_db = loudness.activity_db[is_speech_before ? span.first_frame - 1 : span.end_frame];
    for (std::size_t k = 1; k < kSyllableReachFrames; ++k) {
        if (is_speech_before && k < span.first_frame)
            loudest_db = std::max(loudest_db, loudness.activity_db[span.first_frame - 1 - k]);
        if (is_speech_after && span.end_frame + k < loudness.activity_db.size())
            loudest_db = std::max(loudest_db, loudness.activity_db[span.end_frame + k]);
    }
    return loudest_db >= loudness.speech_level_db - kSyllableBelowLevelDb;
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

LoudnessProfile conceal_dropouts(FeatureTrack& track) {
    LoudnessProfile loudness = measure_loudness(track);
    const std::size_t frames = track.frame_count;
    std::vector<bool> taken(frames, false);
    for (const Dropout& dropout : track.dropouts) {
        const FrameSpan span = taken_frames(dropout, frames);
        if (span.length() == 0 || !cuts_voice(loudness, span)) continue;
        std::fill(taken.begin() + static_cast<std::ptrdiff_t>(span.first_frame),
                  taken.begin() + static_cast<std::ptrdiff_t>(span.end_frame), true);
    }
    if (std::find(taken.begin(), taken.end(), true) == taken.end()) return loudness;
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
    return measure_loudness(track);
}

}  // namespace talkface::detail

#include "speech/lead_noise.hpp"

#include <algorithm>
#include <iterator>

namespace talkface::detail {

namespace {

// A codec's hiss before a short line (short_kinds_bench's p-fast-combo) stands 12-20 dB under the
// line's loudest frame, a lifted lead-in's (p-agc) 17-23 dB, and the line's own syllables, neutral
// tones and quiet initials included, reach within 12 dB of it in their loudest frames.
constexpr float kOwnVoiceBelowLoudestDb = 12.0F;
// 0.15 s: a quiet initial (s-, f-, h-) or a stop's closure at a bare line's start is mostly shorter,
// and the noise before a line the cutter found no pause before is 0.3-0.6 s (bench/README.md
// session 36 (short4)). Measured on short_kinds_bench's tuning lines (bench/README.md, session 37
// (short5)).
constexpr std::size_t kMinLeadNoiseFrames = 15;
// What the first syllable keeps of its voice at least, so that its sound still counts in the fit.
constexpr std::size_t kMinKeptVoiceFrames = 3;

}  // namespace

bool is_lone_syllable(const std::vector<AlignedStretch>& stretches) {
    const auto first = std::find_if(stretches.begin(), stretches.end(),
                                    [](const AlignedStretch& stretch) { return !stretch.is_pause; });
    return first != stretches.end() &&
           std::all_of(stretches.begin(), stretches.end(), [&](const AlignedStretch& stretch) {
               return stretch.is_pause || stretch.syllable == first->syllable;
           });
}

FrameSpan own_voice_extent(const LoudnessProfile& loudness, const FrameSpan& span) {
    if (span.end_frame <= span.first_frame) return {span.first_frame, span.first_frame};
    if (loudness.activity_db.size() < span.end_frame) return span;
    const auto first = loudness.activity_db.begin() + static_cast<std::ptrdiff_t>(span.first_frame);
    const auto end = loudness.activity_db.begin() + static_cast<std::ptrdiff_t>(span.end_frame);
    const float level = *std::max_element(first, end) - kOwnVoiceBelowLoudestDb;
    const auto is_voice = [&](float db) { return db >= level; };
    const auto onset = std::find_if(first, end, is_voice);
    const auto last =
        std::find_if(std::make_reverse_iterator(end), std::make_reverse_iterator(first), is_voice);
    return {static_cast<std::size_t>(onset - loudness.activity_db.begin()),
            static_cast<std::size_t>(last.base() - loudness.activity_db.begin())};
}

OwnVoiceShare own_voice_share(const std::vector<StateSegment>& path,
                              const std::vector<AlignedStretch>& stretches, const LoudnessProfile& loudness,
                              std::size_t first_scored_frame) {
    OwnVoiceShare share{path, stretches, false};
    const auto first = std::find_if(stretches.begin(), stretches.end(),
                                    [](const AlignedStretch& stretch) { return !stretch.is_pause; });
    if (first == stretches.end()) return share;
    float loudest = loudness.activity_db[first->first_frame];
    for (const auto& stretch : stretches) {
        if (stretch.is_pause) continue;
        for (std::size_t t = stretch.first_frame; t < stretch.end_frame; ++t)
            loudest = std::max(loudest, loudness.activity_db[t]);
    }
    if (first->end_frame - first->first_frame < kMinLeadNoiseFrames + kMinKeptVoiceFrames) return share;
    const auto is_noise = [&](std::size_t t) {
        return loudness.activity_db[t] < loudest - kOwnVoiceBelowLoudestDb;
    };
    std::size_t onset = first->first_frame;
    while (onset < first->end_frame - kMinKeptVoiceFrames && is_noise(onset)) ++onset;
    if (onset - first->first_frame < kMinLeadNoiseFrames) onset = first->first_frame;
    std::size_t end = first->end_frame;
    if (is_lone_syllable(stretches)) {
        while (end > onset + kMinKeptVoiceFrames && is_noise(end - 1)) --end;
        if (first->end_frame - end < kMinLeadNoiseFrames) end = first->end_frame;
    }
    if (onset == first->first_frame && end == first->end_frame) return share;
    share.has_noise = true;
    share.path.clear();
    for (StateSegment segment : path) {
        segment.first_frame = std::max(segment.first_frame, onset - first_scored_frame);
        if (end < first->end_frame) segment.end_frame = std::min(segment.end_frame, end - first_scored_frame);
        if (segment.end_frame > segment.first_frame) share.path.push_back(segment);
    }
    share.stretches.clear();
    std::copy_if(stretches.begin(), stretches.end(), std::back_inserter(share.stretches),
                 [&](const AlignedStretch& stretch) {
                     return stretch.is_pause || stretch.syllable != first->syllable;
                 });
    return share;
}

}  // namespace talkface::detail

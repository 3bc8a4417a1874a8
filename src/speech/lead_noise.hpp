// The noise a short line's first syllable holds before the line's own voice (issue 13). Where the
// cutter finds no pause before a line (a codec's hiss, a gain's lift, other voices as loud as a
// pause allows), the line's span runs from the recording's first frame and its first syllable is
// drawn over the 0.3-0.6 s of noise before the voice: on models learned from the line itself the
// free sounds fit that noise better than the syllable does, and its length is the noise's, so a
// right line of a few syllables was refused by its own fit or its syllables' spread (bench/
// short_kinds_bench.py: 13 of the 14 such right lines, bench/README.md session 36 (short4)). The
// recording's own evidence tells that noise from the voice: it never comes near the line's loudest
// frame. A bare line (cut to its sound) has none, and keeps every frame of its fit and spread.
#ifndef TALKFACE_SPEECH_LEAD_NOISE_HPP
#define TALKFACE_SPEECH_LEAD_NOISE_HPP

#include <cstddef>
#include <vector>

#include "speech/alignment_checks.hpp"
#include "speech/hsmm.hpp"
#include "speech/sentence_cutter.hpp"

namespace talkface::detail {

// A sentence's path and stretches as the checks of its own fit and rhythm judge them: with the
// noise before its voice (lead_noise.hpp) left out of the path, and the first syllable, whose length
// the noise made, out of the stretches. A line of one syllable the cutter found no pause around
// holds the noise after its voice too (a codec's hiss fills the 1.32 s of 走！ through a lossy
// stream, its voice 0.3 s of it: bench/README.md, session 38 (short6)), and that is left out of
// its path as well. Unchanged (`has_noise` false) where the syllables hold no such noise.
struct OwnVoiceShare {
    std::vector<StateSegment> path;
    std::vector<AlignedStretch> stretches;
    bool has_noise = false;
};

// The noise before the voice: the frames from the first syllable's start up to the first frame
// within kOwnVoiceBelowLoudestDb of the sentence's loudest syllable frame in `loudness` (all but the
// syllable's last kMinKeptVoiceFrames where none is), where they are at least kMinLeadNoiseFrames long;
// for a line of one syllable, the frames after its last such frame on the same terms as well.
// `path` is in frames of the scores, which start at frame `first_scored_frame` of the recording; `stretches`
// (stretches_of) are the same path in the recording's frames.
OwnVoiceShare own_voice_share(const std::vector<StateSegment>& path,
                              const std::vector<AlignedStretch>& stretches, const LoudnessProfile& loudness,
                              std::size_t first_scored_frame);

// Whether the sentence's `stretches` (stretches_of) hold one syllable alone, its pauses aside: a line
// of one syllable, whose noise after its voice is left out as well as before it.
bool is_lone_syllable(const std::vector<AlignedStretch>& stretches);

// The frames of `span` from its first to its last within kOwnVoiceBelowLoudestDb of its loudest
// frame in `loudness`: the voice's own extent, without the hiss or other voices the span holds
// around it where the cutter found no pause there. Empty for an empty span; the whole span where
// `loudness` holds no activity for it.
FrameSpan own_voice_extent(const LoudnessProfile& loudness, const FrameSpan& span);

}  // namespace talkface::detail

#endif

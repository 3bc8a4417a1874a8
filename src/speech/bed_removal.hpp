// Music that plays on under a voice's first words (a podcast's bed, music_bed.hpp) taken out of the
// features the models read (issue 13). Under the bed every frame of the first sentence is the voice
// and the music together, while the models are learned mostly on the clean sentences after it: a
// closure or a weak onset, where the music rules, fits no class of the voice, and a free sequence
// of sounds takes whichever fits the notes, so that the right text's sentence under the bed fit
// its speech 0.16-0.82 per frame worse than free sounds (bench/README.md, session 30). The bed's
// notes change every bar, so its spectrum heard alone before the voice says little of what it adds
// to a frame a few seconds later (a pad's or a piano's mean spectrum against its frames: 40 dB
// apart in some bands, session 33); what it adds now shows in the voice's gaps around the frame.
#ifndef TALKFACE_SPEECH_BED_REMOVAL_HPP
#define TALKFACE_SPEECH_BED_REMOVAL_HPP

#include <cstddef>

#include "speech/frame_features.hpp"
#include "speech/sentence_cutter.hpp"

namespace talkface::detail {

// What the bed adds to a band in a frame is read as the least the band holds over the frames within
// kBedLevelHalfWindow of it (minimum statistics, as a noise tracker reads noise under speech): 200
// ms either way holds a closure, a pause or a weak onset of the voice's, where the bed shows
// through, in any run of two or three syllables.
constexpr std::size_t kBedLevelHalfWindow = 20;

// Whether `loudness` found music under the first words (LoudnessProfile::voice_under_music).
inline bool has_music_bed(const LoudnessProfile& loudness) {
    return loudness.voice_under_music.length() > 0;
}

// `track` with the bed of `loudness` (has_music_bed) taken out of the levels the models read (the
// mel bands behind the cepstra, as the cepstra keep them, and the band levels) from the voice's
// entry to the bed's end: each band's power less the least it holds within kBedLevelHalfWindow
// (the music alone before the entry counted among those frames), never below what the band holds
// in the recording's pauses outside the bed (its lower median there: a closure under the bed reads
// as a pause does) nor kDryFloorDb under the frame (late_reverb.hpp: a frame the bed takes whole
// keeps a trace of itself, where a pause of digital silence would leave no level to read). The
// music alone before the voice is left as heard: no sentence lies there, and taken out too it
// read as a pause to the models learned on the recording (4 more right passages of the intro set's
// beds refused, and a missing sentence's long pause shortened past what check_missing_text
// catches: bench/README.md, session 34). The other columns and the pitch are the track's.
FeatureTrack without_music_bed(const FeatureTrack& track, const LoudnessProfile& loudness);

}  // namespace talkface::detail

#endif

// Drums under a voice (issue 13): a kit's hits in the pauses between sentences are as loud, band
// by band, as the speech's quieter frames, and they change as much as a voice does, so neither
// loudness nor change (held_music.hpp) tells them from speech, and the cutter misses sentence ends.
// What a beat has that a voice lacks is repetition: the bar one or two bars earlier or later holds
// the same hits at the same places. Where a frame is no louder than the quietest of those frames a
// whole number of bars away, the accompaniment explains it, whatever its loudness or change; a
// syllable is not repeated a bar on, so speech over the beat stands out from it.
#ifndef TALKFACE_SPEECH_REPEATING_ACCOMPANIMENT_HPP
#define TALKFACE_SPEECH_REPEATING_ACCOMPANIMENT_HPP

#include <cstddef>
#include <vector>

#include "speech/frame_features.hpp"

namespace talkface::detail {

// The repeat is looked for between 0.2 and 2 s (a bar or beat from 30 to 300 beats a minute). The
// onsets of the high band (a kit's hi-hat and snare, a voice's fricatives) correlate with
// themselves one period and two periods on by at least kBeatCorrelation on average where a beat
// repeats; a voice's onsets, alone or over noise, a piano or a sung line, by 0.15 at most
// (bench/README.md, session 12).
constexpr std::size_t kShortestRepeatFrames = 20;
constexpr std::size_t kLongestRepeatFrames = 200;
constexpr double kBeatCorrelation = 0.18;
// The frames that predict frame t: those kRepeatsEachSide periods either side of it, each the
// loudest within a frame of where the period puts it (the period is known to a fraction of a frame,
// a hit lasts a few). The onsets may repeat with the hi-hat's eighth notes while a kick and a snare
// repeat only every second or fourth of them: the period's multiples predict too, each on its own.
constexpr std::size_t kRepeatsEachSide = 2;
constexpr double kRepeatMultiples[] = {1.0, 2.0, 4.0};
// A frame no more than this louder than the quietest of its predictions is the accompaniment's.
// Where a multiple has only one prediction inside the recording (a long period's fourth multiple
// runs past its ends), the quietest is that frame; where it is as loud as the median speech frame it
// is a syllable's, no hit, and the multiple predicts nothing: else every quieter frame a whole
// number of bars from a syllable reads as a hit (bench/ human r-music tuning-008's 故事, taken for
// the beat by one frame of sentence 5 four bars on: bench/README.md, session 37 (music)).
constexpr float kRepeatMarginDb = 1.5f;

// The repeat of the recording's accompaniment in frames (fractional), or 0 where its high band's
// onsets (`high_floor_db` the band's floor of sound: digital silence is no onset) do not repeat.
double accompaniment_period_frames(const FeatureTrack& track, float high_floor_db);

// Per frame: whether it belongs to a run of frames at or above `threshold_db` of the loudness
// profile's smoothed activity, between two frames below it (or the recording's ends), that the
// accompaniment repeating every `period_frames` explains in whole: each frame is no more than
// kRepeatMarginDb louder than the quietest of its predictions (a multiple's lone prediction as loud
// as the median speech frame predicting nothing), and quieter than the median speech frame. A hit
// of the beat inside a pause, not a syllable's frame that the beat happens to match (a stretch of
// speech is never all explained). All false when the period is 0.
std::vector<bool> repeated_hits_between_pauses(const std::vector<float>& activity_db, float threshold_db,
                                               double period_frames);

}  // namespace talkface::detail

#endif

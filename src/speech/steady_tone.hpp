// A steady tone is no speech (issue 13): a phone's or a recorder's beep before the speech (two
// 80 ms tones of 880 Hz), a test tone, a dial tone. It is as loud as the voice and too long for a
// click, so the sentence cutter took it for the first syllable, and the search put the first one
// or two syllables on it (bench/README.md, sweep, session 17). What a voice never holds is a
// frame's whole power on one spectral line for long at one level: a vowel spreads its power over the
// harmonics of its pitch, which glide, and under its formants, which move, and where one harmonic
// takes nearly all of it (a low voice's nasal) it does so for a few frames, swelling or decaying;
// a sine keeps all of it within the window's main lobe (kLineHalfBins) of one bin, at one level,
// from frame to frame.
#ifndef TALKFACE_SPEECH_STEADY_TONE_HPP
#define TALKFACE_SPEECH_STEADY_TONE_HPP

#include <cstddef>
#include <vector>

#include "speech/frame_features.hpp"

namespace talkface::detail {

// A frame is on a tone's line when at least kToneLineShare of its power lies there; a tone is
// kShortestToneFrames such frames or more in a row whose strongest bins lie within kToneBinSpread
// of each other and whose levels lie within kToneLevelSpreadDb. A beep's level is flat; speaker 3's
// nasals and held first tones put 0.95 of a frame's power on the fundamental for 3-5 frames,
// decaying 0.4-0.7 dB a frame (bench/README.md, sweep, session 17), and no frame of espeak-ng's
// voice does.
// And the line lies above kLowestToneHz, a speaking voice's highest pitch: where a voice puts a
// frame's power on one line it is its fundamental, boosted by a low first formant (/i/ and /u/, and
// nasals): another voice (bench/ w-clean) holds 一 yi1 at 250 Hz for 6 frames within 0.9 dB. Beeps,
// test tones and a tuning fork's 440 Hz lie above it.
constexpr double kLowestToneHz = 400.0;
constexpr float kToneLineShare = 0.95f;
constexpr std::size_t kShortestToneFrames = 6;
constexpr float kToneBinSpread = 1.0f;
constexpr float kToneLevelSpreadDb = 1.0f;
// A tone's first and last frames hold it in part of their window only (its edges splatter the
// line): up to kToneEdgeFrames frames either side of a tone whose strongest bin is the tone's and
// at least kToneEdgeLineShare of whose power lies on it belong to the tone.
constexpr std::size_t kToneEdgeFrames = 2;
constexpr float kToneEdgeLineShare = 0.5f;

// Per frame of `track`: whether it belongs to a steady tone.
std::vector<bool> steady_tone_frames(const FeatureTrack& track);

}  // namespace talkface::detail

#endif

// Noise a phone's automatic gain control lifts in the pauses (issues 12 and 13): the gain drops
// under each loud syllable and recovers over the next second, so the noise just after a syllable
// is the quietest sound of the recording and the same noise further into a pause stands up to
// 12 dB above it. The floors of measure_loudness are one percentile of the whole recording, the
// noise at the lowest gain: the pause between two sentences read as quiet speech, and p-agc (sox
// compand over pink noise) refused two of its 18 tuning passages, the combinations of street noise,
// the AGC and a codec at tempo 1.3-1.5 nine (bench/README.md, session 27). A floor followed over
// time finds the lift (in the spirit of minimum statistics: a low order statistic over a window);
// what tells the lift from speech is its spectrum: the gain lifts every band alike, so the lifted
// noise keeps the floor's shape, where a voice fills its bands unevenly.
#ifndef TALKFACE_SPEECH_LIFTED_NOISE_HPP
#define TALKFACE_SPEECH_LIFTED_NOISE_HPP

#include <array>
#include <cstddef>
#include <vector>

#include "speech/frame_features.hpp"
#include "speech/sentence_cutter.hpp"

namespace talkface::detail {

// The floor followed over time: each band's kLiftFloorPercentile over the kLiftHalfFrames frames
// either side of a frame, which must follow the lift inside one pause (a comma's 0.3 s at tempo
// 1.5, the AGC's 0.8 s release): over 1.5 s either side it holds the gain's lows from the sentences
// around a pause, and p-fast-combo's tuning passages read 53.3% within 50 ms where 0.5 s gives
// 78.8%. It moves slowly, so it is taken every kLiftStrideFrames frames and held between.
constexpr std::size_t kLiftHalfFrames = 50;
constexpr double kLiftFloorPercentile = 0.05;
constexpr std::size_t kLiftStrideFrames = 10;
// Lifted noise holds its bands the same dB above their floors within kLiftShapeDb: p-agc's pink
// noise in its pauses 1-4 dB apart, a vowel or a fricative 10 dB and more (at 2 dB p-agc and
// p-fast-combo read as without the lift, at 7 dB p-babble loses 3 points).
constexpr float kLiftShapeDb = 4.0f;
// A gain lifts the noise, never to the speech's level: p-agc's pauses stand 7-12 dB over the
// floors, 22 dB under its loud speech; p-fast-combo's street noise comes within 9 dB of it
// (tuning-003: at 12 dB its pause between sentences 2 and 3 was not lifted, and it was refused).
constexpr float kLiftBelowSpeechDb = 6.0f;

// Frame `t`'s kLowBandDb, kMidBandDb and kHighBandDb above the whole recording's floors
// (`low_floor_db`, `mid_floor_db`, `high_floor_db`), in that order.
std::array<float, 3> bands_above_floors(const FeatureTrack& track, std::size_t t, float low_floor_db,
                                        float mid_floor_db, float high_floor_db);

// Whether bands above their floors (a frame's, bands_above_floors, or their medians over a stretch)
// stand within kLiftShapeDb of each other: the floor's shape, which a gain's lift keeps.
bool keeps_floor_shape(const std::array<float, 3>& above_db);

// Per frame of `track`, how far a gain has lifted the noise above the whole recording's floors
// (`low_floor_db`, `mid_floor_db`, `high_floor_db` of kLowBandDb, kMidBandDb, kHighBandDb): the
// rise of the floor followed over time that all three bands share, where the frame is the noise at
// that gain, and 0 elsewhere. A frame is the noise when its bands keep the floor's shape
// (kLiftShapeDb) and none comes within kLiftBelowSpeechDb of `speech_level_db` (the loud speech's
// level above the floors, LoudnessProfile::speech_level_db), in runs of such frames at least
// `min_run_frames` long (a pause's length): babble's frames match the floor's shape now and then,
// a frame or a few at a time, and taking those for pauses cut sentences in p-babble. Only the frames
// of `voice` (the speech as the edge-music rules set it apart, measure_loudness) are lifted: a
// phone's AGC lifts the quiet inside a music bed too, and read as pauses it split the bed (session
// 28's AGC'd intros, r-clean-bed held out 48.1 -> 31.9% within 50 ms). Nothing is lifted where a
// floor is digital silence: there is no noise for a gain to lift, and every sound whose bands stand
// alike keeps that "shape" (a sung intro's quiet notes 107 dB over it read as lifted noise, and
// session 27's lift put the intro in the first sentence: bench/README.md, sessions 27 and 28).
std::vector<float> noise_lift_db(const FeatureTrack& track, float low_floor_db, float mid_floor_db,
                                 float high_floor_db, float speech_level_db, std::size_t min_run_frames,
                                 const FrameSpan& voice);

}  // namespace talkface::detail

#endif

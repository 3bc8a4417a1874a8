// Noise a phone's automatic gain control lifts before the first words (issues 12 and 13): the gain
// starts high and climbs further until the first loud syllable pulls it down, so a short line's
// lead-in stands 10-20 dB over the noise after the line (its lowest gain, the recording's floors).
// noise_lift_db follows the floor over 1 s either side of a frame, which on a recording of 1-2 s
// reaches the noise after the line and finds no lift, and its shape test frame by frame breaks the
// lead-in into runs shorter than a pause; the lead-in was read as the line, and its first syllables
// were spread over it from the recording's start (short_kinds_bench, tuning: p-fast-combo's first
// syllable 380 ms early, median; bench/README.md, session 30).
#ifndef TALKFACE_SPEECH_LIFTED_LEAD_IN_HPP
#define TALKFACE_SPEECH_LIFTED_LEAD_IN_HPP

#include <optional>

#include "speech/frame_features.hpp"
#include "speech/lifted_noise.hpp"
#include "speech/sentence_cutter.hpp"

namespace talkface::detail {

// The noise a gain lifted from the recording's start up to the first words, measured on the
// stretch itself: its level is the median of its first `min_run_frames` frames' loudest band above
// the floors (`low_floor_db`, `mid_floor_db`, `high_floor_db`), and it ends where a voice's uneven
// bands start (three frames in a row out of the floor's shape by kLiftShapeDb, that begin
// `min_run_frames` frames mostly out of it: the noise's own ripple comes back to it) or a frame's
// loudest band stands kLiftBelowSpeechDb over that level (a syllable's rise; the gain's climb toward
// the line stays within it), there before the frames just before the rise that break the floor's
// shape (a quiet initial's, under the noise's level). It is the lifted noise only where it is at least `min_run_frames` long,
// its bands keep the floor's shape (each band's median above its floor within kLiftShapeDb of the
// others', and at least half its frames on their own: other voices and music fill their bands
// unevenly) and the floors are no digital silence.
std::optional<FrameSpan> lifted_lead_in(const FeatureTrack& track, float low_floor_db, float mid_floor_db,
                                        float high_floor_db, std::size_t min_run_frames);

}  // namespace talkface::detail

#endif

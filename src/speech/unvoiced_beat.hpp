// Drums before the voice comes in or after it ends (issue 13): a podcast's or a video's intro on a
// kit alone. Its hits change as a voice does (held_music.hpp's measure reads 0.73-0.95 on them) and
// stand as loud as the speech, so neither loudness nor change sets them apart; what a kit lacks is
// voicing. A voice's voiced frames put most of their power in the low band (80-900 Hz), where
// its harmonics lie, while a hi-hat's and a snare's noise lies in the high band (2500-8000 Hz), and
// a kick's falling sine puts all of its power in one spectral line. (voiced_share.hpp hears the
// pitch itself, but from the samples, which the sentence cutter no longer has.)
#ifndef TALKFACE_SPEECH_UNVOICED_BEAT_HPP
#define TALKFACE_SPEECH_UNVOICED_BEAT_HPP

#include <cstddef>
#include <vector>

#include "speech/frame_features.hpp"

namespace talkface::detail {

// A frame whose kLineShare is this or more holds one spectral line: a sine (a kick, a tom), not a
// voice's several harmonics.
constexpr double kLoneLineShare = 0.9;

// The share of the loud, sounding frames in [first, end) (held_music.hpp's is_loud_sounding_frame,
// loud_change_share's frames) that sound voiced: the low band louder than the high band, the power
// not in one line. 0 where no frame is loud.
double loud_voiced_share(const FeatureTrack& track, const std::vector<float>& activity_db, float threshold_db,
                         std::size_t first, std::size_t end);

// Whether loud frames whose voiced share (loud_voiced_share) is `beat_share` are a beat set apart
// from a voice whose own is `voice_share`. On the intros of bench/make_intros.py a kit alone reads
// 0-0.07, 0.14-0.35 under white noise 20 dB down, and the speech after it 0.70-0.93 (bench/README.md,
// session 27); a voice's unvoiced consonants and a whisper read low, so the voice left must be
// voiced and the beat under half of it.
constexpr double kBeatVoicedShare = 0.4;
constexpr double kVoiceVoicedShare = 0.6;
constexpr double kBeatToVoiceVoicing = 0.5;
inline bool is_beat_beside_voice(double beat_share, double voice_share) {
    return beat_share < kBeatVoicedShare && voice_share >= kVoiceVoicedShare &&
           beat_share < kBeatToVoiceVoicing * voice_share;
}

}  // namespace talkface::detail

#endif

// Music that holds its notes through the pauses (issue 13): chords, a pad, a piano's decay under
// a voice at 15-20 dB are as loud, band by band, as the quieter half of the speech, so loudness
// alone takes the pauses between sentences for speech, and the cutter misses sentence ends. What
// tells them apart is change (changing_spectrum.hpp): a voice changes most of its power every few
// tens of milliseconds, a held note hardly any. Noise changes half of its power whatever its
// colour, so where the quiet of a recording changes as noise does, nothing here applies, and a
// recording under steady noise is cut as before.
#ifndef TALKFACE_SPEECH_HELD_MUSIC_HPP
#define TALKFACE_SPEECH_HELD_MUSIC_HPP

#include <vector>

#include "speech/frame_features.hpp"

namespace talkface::detail {

// A frame counts as held music when, over the frames within kHeldMusicHalfWindow of it, less
// than kHeldMusicChangeShare of the band's power changes, and it is quieter than the median speech
// frame (a vowel held on one pitch is among the loudest frames of its sentence; the music under a
// voice at 15-20 dB is not). 150 ms either way: longer than a steady vowel, shorter than the
// 0.4 s and more that separate two sentences.
constexpr std::size_t kHeldMusicHalfWindow = 15;
constexpr double kHeldMusicChangeShare = 0.35;
// Noise changes 0.5 of its power (changing_spectrum.hpp); quiet that changes less than this is
// held sound: music, or a hum.
constexpr double kNoiseChangeShare = 0.45;

// Per frame of `track`: whether it is held music, given the loudness profile's smoothed activity
// and its speech threshold. All false when the recording's quiet frames (below the threshold, with
// any sound in the band) change as noise does, or when it has none.
std::vector<bool> held_music_frames(const FeatureTrack& track, const std::vector<float>& activity_db, float threshold_db);

}  // namespace talkface::detail

#endif

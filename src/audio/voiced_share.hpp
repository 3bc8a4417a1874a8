// How much of a sound is voiced: periodic at a pitch a voice has. The second witness of a file's
// several sound tracks (ffmpeg_source.cpp): a drum kit alone leaves as many low-energy frames as
// speech does, but its strokes are noise and falling thuds, while speech is voiced a syllable at a
// time.
#ifndef TALKFACE_AUDIO_VOICED_SHARE_HPP
#define TALKFACE_AUDIO_VOICED_SHARE_HPP

#include <vector>

namespace talkface::detail {

// The share of the 40 ms frames of `samples` (mono, at `sample_rate_hz`; one every 20 ms) whose
// normalised autocorrelation reaches 0.5 at a lag of a pitch between 70 and 400 Hz, past its first
// fall to zero. The samples are first averaged down to about 8 kHz (a pitch needs no more), so that
// a minute costs little at any rate. A frame under -60 dBFS is no voice; 0 for samples shorter than
// a frame.
double voiced_share(const std::vector<float>& samples, int sample_rate_hz);

}  // namespace talkface::detail

#endif

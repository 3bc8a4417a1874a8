// How much of a sound is voiced: periodic at a pitch a voice has. The second witness of a file's
// several sound tracks (ffmpeg_source.cpp): a drum kit alone leaves as many low-energy frames as
// speech does, but its strokes are noise and falling thuds, while speech is voiced a syllable at a
// time.
#ifndef TALKFACE_AUDIO_VOICED_SHARE_HPP
#define TALKFACE_AUDIO_VOICED_SHARE_HPP

#include <cstddef>
#include <vector>

namespace talkface::detail {

// Samples averaged down as they come, by the whole number that brings their rate nearest above
// 8 kHz (a pitch needs no more), so that a minute costs little at any rate: what voiced_share hears.
class PitchRateSignal {
public:
    explicit PitchRateSignal(int sample_rate_hz);
    void add(const float* samples, std::size_t count);
    const std::vector<double>& samples() const { return samples_; }
    double rate_hz() const { return rate_hz_; }

private:
    std::size_t factor_;
    double rate_hz_;
    double sum_ = 0.0;
    std::size_t summed_ = 0;
    std::vector<double> samples_;
};

// The share of the 40 ms frames of `signal` (one every 20 ms) whose normalised autocorrelation
// reaches 0.5 at a lag of a pitch between 70 and 400 Hz, past its first fall to zero. A frame under
// -60 dBFS is no voice; 0 for a signal shorter than a frame.
double voiced_share(const PitchRateSignal& signal);

}  // namespace talkface::detail

#endif

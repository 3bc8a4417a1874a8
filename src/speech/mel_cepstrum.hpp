// The DCT of frame_features' cepstra and its inverse over the mel bands, as far as the cepstra
// keep it: the bands read from a frame's cepstra give those cepstra back. What a stage takes out of
// a frame's power (a room's ringing, late_reverb.hpp; a music bed, bed_removal.hpp) it takes out of
// these bands, and the cepstra are made again from what is left.
#ifndef TALKFACE_SPEECH_MEL_CEPSTRUM_HPP
#define TALKFACE_SPEECH_MEL_CEPSTRUM_HPP

#include <array>
#include <cstddef>

#include "speech/frame_features.hpp"

namespace talkface::detail {

class MelCepstrum {
public:
    MelCepstrum() {
        for (std::size_t c = 0; c < kCepstrumCount; ++c)
            for (std::size_t m = 0; m < kMelFilters; ++m) cosine_[c][m] = mel_cepstrum_cosine(c, m);
    }

    void to_bands(const float* cepstrum, std::array<double, kMelFilters>& log_mel) const {
        for (std::size_t m = 0; m < kMelFilters; ++m) {
            double sum = cepstrum[0] / 2.0;
            for (std::size_t c = 1; c < kCepstrumCount; ++c) sum += cepstrum[c] * cosine_[c][m];
            log_mel[m] = 2.0 * sum / kMelFilters;
        }
    }

    void to_cepstrum(const std::array<double, kMelFilters>& log_mel, float* cepstrum) const {
        for (std::size_t c = 0; c < kCepstrumCount; ++c) {
            double sum = 0.0;
            for (std::size_t m = 0; m < kMelFilters; ++m) sum += cosine_[c][m] * log_mel[m];
            cepstrum[c] = static_cast<float>(sum);
        }
    }

private:
    std::array<std::array<double, kMelFilters>, kCepstrumCount> cosine_{};
};

}  // namespace talkface::detail

#endif

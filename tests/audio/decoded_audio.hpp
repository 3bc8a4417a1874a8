// What the audio tests compare decoded recordings by: every sample, read in blocks as the aligner
// reads them, and the loudness envelope whose best lag says whether a codec's delay was left in.
#ifndef TALKFACE_TESTS_AUDIO_DECODED_AUDIO_HPP
#define TALKFACE_TESTS_AUDIO_DECODED_AUDIO_HPP

#include <cmath>
#include <cstddef>
#include <vector>

#include "audio/audio_source.hpp"

namespace talkface::test {

// Every sample of a source, mixed to mono, read in blocks as the aligner reads them.
inline std::vector<float> read_all(detail::AudioSource& source) {
    std::vector<float> samples;
    std::vector<float> block(1000);
    while (const std::size_t got = source.read(block.data(), block.size())) samples.insert(samples.end(), block.begin(), block.begin() + got);
    return samples;
}

// Loudness in 5 ms steps: comparable across sample rates and lossy codecs.
inline std::vector<double> envelope(const std::vector<float>& samples, int rate_hz) {
    std::vector<double> energy(samples.size() * 200 / static_cast<std::size_t>(rate_hz) + 1, 0.0);
    for (std::size_t i = 0; i < samples.size(); ++i)
        energy[i * 200 / static_cast<std::size_t>(rate_hz)] += static_cast<double>(samples[i]) * samples[i] / rate_hz;
    return energy;
}

// The shift (in 5 ms steps, -20..20) that best lines `decoded`'s loudness up with `reference`'s.
inline int best_lag(const std::vector<double>& reference, const std::vector<double>& decoded) {
    int best = 0;
    double best_score = -1.0;
    for (int lag = -20; lag <= 20; ++lag) {
        double score = 0.0;
        for (std::size_t i = 0; i < reference.size(); ++i) {
            const long j = static_cast<long>(i) + lag;
            if (j >= 0 && j < static_cast<long>(decoded.size())) score += std::sqrt(reference[i] * decoded[static_cast<std::size_t>(j)]);
        }
        if (score > best_score) best_score = score, best = lag;
    }
    return best;
}

}  // namespace talkface::test

#endif

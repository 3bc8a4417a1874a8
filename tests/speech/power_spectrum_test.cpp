#include <doctest/doctest.h>
#include <unsupported/Eigen/FFT>

#include <array>
#include <complex>
#include <cstdint>
#include <cstring>
#include <vector>

#include "speech/power_spectrum.hpp"

using namespace talkface::detail;

namespace {

// Frames of the kinds the features see: speech-like loud noise, a faint hiss (the dither alone),
// digital silence, a full-scale square wave; each 400 windowed samples zero-padded to 512.
std::vector<std::vector<float>> test_frames() {
    std::uint64_t state = 0x243F6A8885A308D3ull;
    auto uniform = [&] {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        return static_cast<float>(state >> 40) / 16777216.0f - 0.5f;
    };
    std::vector<std::vector<float>> frames;
    for (int f = 0; f < 400; ++f) {
        std::vector<float> frame(PowerSpectrum::kSize, 0.0f);
        const int kind = f % 4;
        for (std::size_t i = 0; i < 400; ++i) {
            if (kind == 0) frame[i] = uniform();
            if (kind == 1) frame[i] = 1e-5f * uniform();
            if (kind == 3) frame[i] = (i / 20) % 2 == 0 ? 1.0f : -1.0f;
        }
        frames.push_back(frame);
    }
    return frames;
}

}  // namespace

TEST_SUITE("power spectrum") {
    // The features, and every alignment, were computed with Eigen's FFT before this class: it must
    // give the same numbers to the last bit, not nearly the same.
    TEST_CASE("the same bits as std::norm of Eigen's FFT (kissfft), half spectrum") {
        const PowerSpectrum spectrum;
        Eigen::FFT<float> fft;
        fft.SetFlag(Eigen::FFT<float>::HalfSpectrum);
        std::vector<std::complex<float>> eigen_bins;
        std::array<float, PowerSpectrum::kBins> power{};
        std::size_t differing = 0;
        for (const auto& frame : test_frames()) {
            fft.fwd(eigen_bins, frame);
            REQUIRE(eigen_bins.size() == PowerSpectrum::kBins);
            spectrum.compute(frame.data(), power.data());
            for (std::size_t k = 0; k < PowerSpectrum::kBins; ++k) {
                const float expected = std::norm(eigen_bins[k]);
                if (std::memcmp(&expected, &power[k], sizeof expected) != 0) ++differing;
            }
        }
        CHECK(differing == 0);
    }

    TEST_CASE("a cosine's power stands in its own bin") {
        const PowerSpectrum spectrum;
        std::vector<float> frame(PowerSpectrum::kSize);
        for (std::size_t i = 0; i < frame.size(); ++i) frame[i] = static_cast<float>(std::cos(2.0 * M_PI * 32.0 * static_cast<double>(i) / 512.0));
        std::array<float, PowerSpectrum::kBins> power{};
        spectrum.compute(frame.data(), power.data());
        CHECK(power[32] == doctest::Approx(256.0 * 256.0).epsilon(1e-4));
        for (std::size_t k = 0; k < PowerSpectrum::kBins; ++k)
            if (k != 32) CHECK(power[k] < 1e-3f);
    }
}

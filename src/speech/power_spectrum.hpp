// The power spectrum of a 512-sample frame, the frame features' (frame_features.hpp) two per 10 ms.
#ifndef TALKFACE_SPEECH_POWER_SPECTRUM_HPP
#define TALKFACE_SPEECH_POWER_SPECTRUM_HPP

#include <array>
#include <cstddef>
#include <cstdint>

namespace talkface::detail {

// |X_k|^2 of the real FFT of kSize samples, k = 0 .. kSize / 2: the same numbers, bit for bit, as
// std::norm of Eigen::FFT<float>'s half spectrum, which computed them before (Eigen 3.4's kissfft:
// the frame as a 256-point complex FFT in four radix-4 stages, then split into the real frame's
// spectrum). The same operations on the same numbers in the same order, only laid out as arrays of
// real and of imaginary parts, stage by stage, which the compiler vectorizes: a quarter of Eigen's
// instructions (bench/README.md, session 10), and no feature and so no alignment moves by a bit.
class PowerSpectrum {
public:
    static constexpr std::size_t kSize = 512;
    static constexpr std::size_t kBins = kSize / 2 + 1;

    PowerSpectrum();

    // `frame`: kSize samples; `power`: kBins values.
    void compute(const float* frame, float* power) const;

private:
    static constexpr std::size_t kHalf = kSize / 2;     // the complex FFT's points
    static constexpr std::size_t kQuarter = kHalf / 4;  // a radix-4 stage's widest butterfly span
    static constexpr std::size_t kStages = 3;           // butterfly spans 4, 16 and 64 (span 1 needs no table)
    // Per stage of span m, the twiddles of its butterflies' second, third and fourth inputs:
    // e^(-2 pi i j k / (4 m)) for j = 1, 2, 3 and k < m.
    std::array<std::array<std::array<float, kQuarter>, 3>, kStages> twiddle_re_{};
    std::array<std::array<std::array<float, kQuarter>, 3>, kStages> twiddle_im_{};
    // The split of the complex FFT into the real frame's spectrum: e^(-i pi (k / kHalf + 1/2)), k = 1 .. kHalf / 2.
    std::array<float, kHalf / 2> split_re_{};
    std::array<float, kHalf / 2> split_im_{};
    std::array<std::uint8_t, kQuarter> digits_reversed_{};  // 0..63 with its three base-4 digits reversed
};

}  // namespace talkface::detail

#endif

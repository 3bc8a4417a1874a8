#include "speech/power_spectrum.hpp"

#include <cmath>
#include <complex>
#include <type_traits>

#include "speech/avx2_clones.hpp"

namespace talkface::detail {

namespace {

// e^(-2 pi i index / n) in float: the cosine and sine (double) of the angle within its quarter turn,
// then whole quarter turns, exactly, as Eigen's kissfft has its roots of unity (0 is exact at a
// quarter turn; the double cosine of pi / 2 is not).
std::complex<float> unit_root(std::size_t index, std::size_t n) {
    const std::size_t quarter = n / 4;
    const double angle = 2.0 * M_PI * static_cast<double>(index % quarter) / static_cast<double>(n);
    std::complex<float> root(static_cast<float>(std::cos(angle)), -static_cast<float>(std::sin(angle)));
    for (std::size_t turn = 0; turn < index / quarter; ++turn) root = {root.imag(), -root.real()};  // times -i
    return root;
}

// kissfft's forward radix-4 butterfly, in place on (a, b, c, d): b, c and d are first multiplied by
// their twiddles w1, w2, w3 as the compiler multiplies std::complex<float> (re re - im im, re im + im re).
inline void butterfly(float& a_re, float& a_im, float& b_re, float& b_im, float& c_re, float& c_im, float& d_re,
                      float& d_im, float w1_re, float w1_im, float w2_re, float w2_im, float w3_re, float w3_im) {
    const float b_turned_re = b_re * w1_re - b_im * w1_im;
    const float b_turned_im = b_re * w1_im + b_im * w1_re;
    const float c_turned_re = c_re * w2_re - c_im * w2_im;
    const float c_turned_im = c_re * w2_im + c_im * w2_re;
    const float d_turned_re = d_re * w3_re - d_im * w3_im;
    const float d_turned_im = d_re * w3_im + d_im * w3_re;
    const float a_minus_c_re = a_re - c_turned_re, a_minus_c_im = a_im - c_turned_im;
    const float a_plus_c_re = a_re + c_turned_re, a_plus_c_im = a_im + c_turned_im;
    const float b_plus_d_re = b_turned_re + d_turned_re, b_plus_d_im = b_turned_im + d_turned_im;
    // (b - d) times -i
    const float b_minus_d_re = b_turned_im - d_turned_im, b_minus_d_im = -(b_turned_re - d_turned_re);
    c_re = a_plus_c_re - b_plus_d_re;
    c_im = a_plus_c_im - b_plus_d_im;
    a_re = a_plus_c_re + b_plus_d_re;
    a_im = a_plus_c_im + b_plus_d_im;
    b_re = a_minus_c_re + b_minus_d_re;
    b_im = a_minus_c_im + b_minus_d_im;
    d_re = a_minus_c_re - b_minus_d_re;
    d_im = a_minus_c_im - b_minus_d_im;
}

// One radix-4 stage over `count` points: butterflies of span kSpan on groups of 4 kSpan points, the
// k-th of a group on points k, k + kSpan, k + 2 kSpan, k + 3 kSpan with twiddles w1[k], w2[k], w3[k].
// Inlined into each of compute's clones, so that the AVX2 one runs the stages in AVX2 too.
template <std::size_t kSpan>
[[gnu::always_inline]] inline void radix4_stage(std::size_t count, float* __restrict re, float* __restrict im,
                                                const float* __restrict w1_re, const float* __restrict w1_im,
                                                const float* __restrict w2_re, const float* __restrict w2_im,
                                                const float* __restrict w3_re,
                                                const float* __restrict w3_im) {
    for (std::size_t group = 0; group < count; group += 4 * kSpan) {
        float* r = re + group;
        float* i = im + group;
        for (std::size_t k = 0; k < kSpan; ++k)
            butterfly(r[k], i[k], r[k + kSpan], i[k + kSpan], r[k + 2 * kSpan], i[k + 2 * kSpan], r[k + 3 * kSpan],
                      i[k + 3 * kSpan], w1_re[k], w1_im[k], w2_re[k], w2_im[k], w3_re[k], w3_im[k]);
    }
}

}  // namespace

PowerSpectrum::PowerSpectrum() {
    for (std::size_t stage = 0, span = 4; stage < kStages; ++stage, span *= 4) {
        for (std::size_t j = 0; j < 3; ++j) {
            for (std::size_t k = 0; k < span; ++k) {
                const std::complex<float> root = unit_root((j + 1) * k, 4 * span);
                twiddle_re_[stage][j][k] = root.real();
                twiddle_im_[stage][j][k] = root.imag();
            }
        }
    }
    // Computed in float, as Eigen's kissfft computes them.
    const float pi = std::acos(-1.0f);
    for (std::size_t k = 1; k <= kHalf / 2; ++k) {
        const std::complex<float> root =
            std::exp(std::complex<float>(0.0f, -pi * (static_cast<float>(k) / static_cast<float>(kHalf) + 0.5f)));
        split_re_[k - 1] = root.real();
        split_im_[k - 1] = root.imag();
    }
    for (std::size_t h = 0; h < kQuarter; ++h)
        digits_reversed_[h] = static_cast<std::uint8_t>(((h & 3) << 4) | (((h >> 2) & 3) << 2) | (h >> 4));
}

// Its stages and split are lane by lane: the AVX2 clone (avx2_clones.hpp) takes eight lanes where
// SSE takes four, the same numbers to the bit (bench/README.md, Session 28).
TALKFACE_AVX2_CLONES void PowerSpectrum::compute(const float* frame, float* power) const {
    // The real frame as kHalf complex points z[n] = frame[2 n] + i frame[2 n + 1].
    std::array<float, kHalf> z_re, z_im;
    for (std::size_t n = 0; n < kHalf; ++n) {
        z_re[n] = frame[2 * n];
        z_im[n] = frame[2 * n + 1];
    }
    // kissfft's first butterflies (its recursion's deepest): 4-point DFTs of z[h], z[h + 64],
    // z[h + 128], z[h + 192], their twiddles all 1 and multiplied all the same. Their outputs go
    // where its recursion puts them: output j of butterfly h at 4 reversed(h) + j.
    for (std::size_t h = 0; h < kQuarter; ++h)
        butterfly(z_re[h], z_im[h], z_re[h + kQuarter], z_im[h + kQuarter], z_re[h + 2 * kQuarter], z_im[h + 2 * kQuarter],
                  z_re[h + 3 * kQuarter], z_im[h + 3 * kQuarter], 1.0f, 0.0f, 1.0f, 0.0f, 1.0f, 0.0f);
    std::array<float, kHalf> re, im;
    for (std::size_t h = 0; h < kQuarter; ++h) {
        const std::size_t at = 4 * digits_reversed_[h];
        re[at] = z_re[h];
        re[at + 1] = z_re[h + kQuarter];
        re[at + 2] = z_re[h + 2 * kQuarter];
        re[at + 3] = z_re[h + 3 * kQuarter];
        im[at] = z_im[h];
        im[at + 1] = z_im[h + kQuarter];
        im[at + 2] = z_im[h + 2 * kQuarter];
        im[at + 3] = z_im[h + 3 * kQuarter];
    }
    const auto stage = [&](auto span, std::size_t s) __attribute__((always_inline)) {
        radix4_stage<decltype(span)::value>(kHalf, re.data(), im.data(), twiddle_re_[s][0].data(), twiddle_im_[s][0].data(),
                                            twiddle_re_[s][1].data(), twiddle_im_[s][1].data(), twiddle_re_[s][2].data(),
                                            twiddle_im_[s][2].data());
    };
    stage(std::integral_constant<std::size_t, 4>(), 0);
    stage(std::integral_constant<std::size_t, 16>(), 1);
    stage(std::integral_constant<std::size_t, 64>(), 2);

    // The real frame's spectrum from the complex one F: with G = conj F[kHalf - k],
    // X[k] = ((F[k] + G) + (F[k] - G) e^(-i pi (k / kHalf + 1/2))) / 2 for k = 1 .. kHalf / 2, and
    // X[kHalf - k] the conjugate of ((F[k] + G) - (F[k] - G) e^(...)) / 2, written after X[k] (at
    // k = kHalf / 2 the two are one bin, and the second is kept). A conjugate's power is its own.
    // The powers go to arrays of this function's own first, which the compiler knows no other
    // pointer reaches: written straight to `power`, the loop stayed scalar.
    constexpr std::size_t kPairs = kHalf / 2;
    std::array<float, kPairs> mirror_re, mirror_im, lower_power, upper_power;
    for (std::size_t k = 1; k <= kPairs; ++k) {
        mirror_re[k - 1] = re[kHalf - k];
        mirror_im[k - 1] = -im[kHalf - k];
    }
    for (std::size_t p = 0; p < kPairs; ++p) {
        const float sum_re = re[p + 1] + mirror_re[p], sum_im = im[p + 1] + mirror_im[p];
        const float difference_re = re[p + 1] - mirror_re[p], difference_im = im[p + 1] - mirror_im[p];
        const float turned_re = difference_re * split_re_[p] - difference_im * split_im_[p];
        const float turned_im = difference_re * split_im_[p] + difference_im * split_re_[p];
        const float lower_re = (sum_re + turned_re) * 0.5f, lower_im = (sum_im + turned_im) * 0.5f;
        const float upper_re = (sum_re - turned_re) * 0.5f, upper_im = (sum_im - turned_im) * 0.5f;
        lower_power[p] = lower_re * lower_re + lower_im * lower_im;
        upper_power[p] = upper_re * upper_re + upper_im * upper_im;
    }
    for (std::size_t p = 0; p < kPairs; ++p) power[p + 1] = lower_power[p];
    for (std::size_t p = 0; p < kPairs; ++p) power[kHalf - 1 - p] = upper_power[p];
    // Bin 0 and bin kHalf (Nyquist) are real.
    const float dc = re[0] + im[0];
    const float nyquist = re[0] - im[0];
    power[0] = dc * dc;
    power[kHalf] = nyquist * nyquist;
}

}  // namespace talkface::detail

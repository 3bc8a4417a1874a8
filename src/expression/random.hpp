// The simulation's random numbers, written out so that a seed gives the same numbers with every
// compiler and standard library (<random>'s engines are portable, its distributions are not).
#ifndef TALKFACE_EXPRESSION_RANDOM_HPP
#define TALKFACE_EXPRESSION_RANDOM_HPP

#include <array>
#include <cmath>
#include <cstdint>

namespace talkface::detail {

// splitmix64 (Steele, Lea and Flood 2014; Vigna's reference code): spreads a seed over the state
// of the main generator, so that nearby seeds give unrelated streams.
inline std::uint64_t splitmix64_next(std::uint64_t& state) {
    state += 0x9E3779B97F4A7C15ULL;
    std::uint64_t z = state;
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    return z ^ (z >> 31);
}

// xoshiro256** 1.0 (Blackman and Vigna 2018, prng.di.unimi.it): small, fast, and passes BigCrush.
class Xoshiro256 {
public:
    // `stream` picks an independent sequence for the same seed (one per event kind).
    Xoshiro256(std::uint64_t seed, std::uint64_t stream) {
        std::uint64_t mix = seed ^ (0xD1B54A32D192ED03ULL * (stream + 1));
        for (auto& word : state_) word = splitmix64_next(mix);
    }

    std::uint64_t next() {
        const std::uint64_t result = rotl(state_[1] * 5, 7) * 9;
        const std::uint64_t t = state_[1] << 17;
        state_[2] ^= state_[0];
        state_[3] ^= state_[1];
        state_[1] ^= state_[2];
        state_[0] ^= state_[3];
        state_[2] ^= t;
        state_[3] = rotl(state_[3], 45);
        return result;
    }

    // Uniform on the open interval (0, 1): the top 53 bits, centred in their cell, so that
    // ln(U) is always finite.
    double uniform_open() { return (static_cast<double>(next() >> 11) + 0.5) * 0x1.0p-53; }

    // Uniform on [min, max].
    double uniform(double min, double max) { return min + (max - min) * uniform_open(); }

    // Gamma(shape, scale) for an integer shape: the sum of `shape` exponential waits, drawn as
    // -scale ln(U1 ... U_shape) (thesis 4.3). shape <= 16 keeps the product above 2^-900.
    double gamma(int shape, double scale) {
        double product = 1.0;
        for (int k = 0; k < shape; ++k) product *= uniform_open();
        return -scale * std::log(product);
    }

    // +1 or -1 with equal chance.
    double sign() { return (next() >> 63) != 0 ? 1.0 : -1.0; }

private:
    static std::uint64_t rotl(std::uint64_t x, int k) { return (x << k) | (x >> (64 - k)); }
    std::array<std::uint64_t, 4> state_{};
};

}  // namespace talkface::detail

#endif

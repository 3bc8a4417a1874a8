// xorshift64 (Marsaglia 2003, shifts 13, 7, 17), the generator of the features' dither
// (frame_features.cpp), and its jump ahead: the step is linear over GF(2), so the state n steps on
// is a fixed 64 x 64 bit matrix times the state. Two frames' draws are made at once, two states
// stepped side by side: in the two lanes of a vector where the compiler has GCC's vector extension
// (GCC, Clang), one after the other where it does not (MSVC); the same numbers either way.
#ifndef TALKFACE_SPEECH_XORSHIFT_HPP
#define TALKFACE_SPEECH_XORSHIFT_HPP

#include <array>
#include <cstddef>
#include <cstdint>

namespace talkface::detail {

// One step of each state in `state`: a std::uint64_t, or a vector of them (GCC's vector extension),
// whose lanes step apart.
template <typename State>
constexpr State xorshift64(State state) {
    state ^= state << 13;
    state ^= state >> 7;
    state ^= state << 17;
    return state;
}

// `steps` steps at once: column j of the matrix is where the state with only bit j set goes.
class XorshiftJump {
public:
    constexpr explicit XorshiftJump(std::size_t steps) {
        for (std::size_t j = 0; j < 64; ++j) {
            std::uint64_t state = std::uint64_t{1} << j;
            for (std::size_t n = 0; n < steps; ++n) state = xorshift64(state);
            columns_[j] = state;
        }
    }

    // The state `steps` steps after `state`.
    constexpr std::uint64_t apply(std::uint64_t state) const {
        std::uint64_t jumped = 0;
        for (std::size_t j = 0; j < 64; ++j) jumped ^= columns_[j] & (std::uint64_t{0} - ((state >> j) & 1u));
        return jumped;
    }

private:
    std::array<std::uint64_t, 64> columns_{};
};

// Two xorshift64 states stepped together, portably: one after the other.
class XorshiftPair {
public:
    XorshiftPair(std::uint64_t first, std::uint64_t second) : first_(first), second_(second) {}
    void step() {
        first_ = xorshift64(first_);
        second_ = xorshift64(second_);
    }
    // Both states shifted right by `bits`, as a pair.
    XorshiftPair shifted_right(unsigned bits) const { return {first_ >> bits, second_ >> bits}; }
    std::uint64_t first() const { return first_; }
    std::uint64_t second() const { return second_; }

private:
    std::uint64_t first_, second_;
};

#if defined(__GNUC__)
// The same in the two lanes of one 128-bit vector (SSE2 on x86-64, NEON on ARM): one step for both.
class XorshiftVectorPair {
public:
    XorshiftVectorPair(std::uint64_t first, std::uint64_t second) : lanes_{first, second} {}
    void step() { lanes_ = xorshift64(lanes_); }
    // Both lanes shifted right by `bits` at once.
    XorshiftVectorPair shifted_right(unsigned bits) const {
        XorshiftVectorPair shifted = *this;
        shifted.lanes_ = lanes_ >> bits;
        return shifted;
    }
    std::uint64_t first() const { return lanes_[0]; }
    std::uint64_t second() const { return lanes_[1]; }

private:
    typedef std::uint64_t Lanes __attribute__((vector_size(16)));
    Lanes lanes_;
};
using FastXorshiftPair = XorshiftVectorPair;
#else
using FastXorshiftPair = XorshiftPair;
#endif

// The draws of two frames of one xorshift64 sequence, `draws_per_frame` = 2 N each, N samples of
// two draws: draws[f][k][i] is the top 24 bits of draw 2 i + k of frame f (k = 0, 1). `state` is
// frame 0's first state, `jump` the map from a frame's first state to the next's (2 N steps).
// Returns the state frame 2 starts from. `Pair` steps the two frames' states side by side.
template <typename Pair, std::size_t N>
std::uint64_t draw_two_frames(std::uint64_t state, const XorshiftJump& jump,
                              std::array<std::array<std::array<std::uint32_t, N>, 2>, 2>& draws) {
    Pair pair(state, jump.apply(state));
    for (std::size_t i = 0; i < N; ++i) {
        for (std::size_t k = 0; k < 2; ++k) {
            pair.step();
            const Pair top24 = pair.shifted_right(40);
            draws[0][k][i] = static_cast<std::uint32_t>(top24.first());
            draws[1][k][i] = static_cast<std::uint32_t>(top24.second());
        }
    }
    return pair.second();
}

}  // namespace talkface::detail

#endif

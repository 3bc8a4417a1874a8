// xorshift64 (Marsaglia 2003, shifts 13, 7, 17), the generator of the features' dither
// (frame_features.cpp), and its jump ahead: the step is linear over GF(2), so the state n steps on
// is a fixed 64 x 64 bit matrix times the state.
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

}  // namespace talkface::detail

#endif

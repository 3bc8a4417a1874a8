// A moving test pattern for the video tests: a grey-blue ramp with a red square that moves one
// step right per frame, so a decoded frame tells which frame it is.
#ifndef TALKFACE_TESTS_VIDEO_TEST_PATTERN_HPP
#define TALKFACE_TESTS_VIDEO_TEST_PATTERN_HPP

#include <cstdint>
#include <vector>

namespace talkface_test {

struct Rgba {
    std::uint8_t r, g, b, a;
};

inline constexpr int kSquarePx = 32;
inline constexpr int kStepPx = 4;

// The square's left edge in frame `index`.
inline int square_left(long index, int width) { return static_cast<int>((16 + index * kStepPx) % (width - kSquarePx)); }

// Frame `index` of width x height, RGBA rows. `alpha`: the ramp is transparent (alpha 0), the
// square opaque.
inline std::vector<std::uint8_t> test_pattern(long index, int width, int height, bool alpha = false) {
    std::vector<std::uint8_t> pixels(static_cast<std::size_t>(width) * height * 4);
    const int left = square_left(index, width);
    const int top = height / 2 - kSquarePx / 2;
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            std::uint8_t* p = &pixels[(static_cast<std::size_t>(y) * width + x) * 4];
            const bool is_square = x >= left && x < left + kSquarePx && y >= top && y < top + kSquarePx;
            if (is_square) {
                p[0] = 220, p[1] = 30, p[2] = 40, p[3] = 255;
            } else {
                p[0] = 40;
                p[1] = static_cast<std::uint8_t>(60 + 120 * y / height);
                p[2] = 160;
                p[3] = alpha ? 0 : 255;
            }
        }
    }
    return pixels;
}

inline Rgba pixel_at(const std::vector<std::uint8_t>& rgba, int width, int x, int y) {
    const std::uint8_t* p = &rgba[(static_cast<std::size_t>(y) * width + x) * 4];
    return {p[0], p[1], p[2], p[3]};
}

}  // namespace talkface_test

#endif

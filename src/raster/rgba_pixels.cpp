#include "raster/rgba_pixels.hpp"

#include <algorithm>
#include <cstring>

namespace talkface::detail {

PixelBox united(const PixelBox& a, const PixelBox& b) {
    if (a.is_empty()) return b;
    if (b.is_empty()) return a;
    const int x0 = std::min(a.x, b.x);
    const int y0 = std::min(a.y, b.y);
    const int x1 = std::max(a.x + a.width, b.x + b.width);
    const int y1 = std::max(a.y + a.height, b.y + b.height);
    return {x0, y0, x1 - x0, y1 - y0};
}

void argb32_to_rgba(const std::uint8_t* argb, std::size_t argb_stride, std::uint8_t* rgba, std::size_t rgba_stride,
                    const PixelBox& box, bool is_premultiplied) {
    // Pixels go through a buffer on the stack in chunks: no allocation, and a loop over words.
    constexpr std::size_t kChunk = 256;
    std::uint32_t words[kChunk];
    for (int row = box.y; row < box.y + box.height; ++row) {
        const std::uint8_t* source = argb + static_cast<std::size_t>(row) * argb_stride + 4 * static_cast<std::size_t>(box.x);
        std::uint8_t* out = rgba + static_cast<std::size_t>(row) * rgba_stride + 4 * static_cast<std::size_t>(box.x);
        for (std::size_t done = 0, count = static_cast<std::size_t>(std::max(0, box.width)); done < count;) {
            const std::size_t n = std::min(kChunk, count - done);
            std::memcpy(words, source + 4 * done, 4 * n);
            // 0xAARRGGBB in memory order B, G, R, A (cairo's native-endian words on a little-endian
            // machine) becomes R, G, B, A: R and B swap places. One pass the compiler vectorizes;
            // the pixels of an edge against nothing are unpremultiplied after.
            bool has_partial_alpha = false;
            for (std::size_t i = 0; i < n; ++i) {
                const std::uint32_t word = words[i];
                const std::uint32_t alpha = word >> 24;
                has_partial_alpha |= alpha != 0 && alpha != 0xff;
                words[i] = (word & 0xff00ff00u) | ((word >> 16) & 0xffu) | ((word & 0xffu) << 16);
            }
            if (has_partial_alpha && !is_premultiplied) {
                for (std::size_t i = 0; i < n; ++i) {
                    const std::uint32_t word = words[i];
                    const std::uint32_t a = word >> 24;
                    if (a == 0 || a == 0xff) continue;
                    // Rounded to nearest: c * 255 / a.
                    auto straight = [a](std::uint32_t c) { return (c * 255 + a / 2) / a; };
                    words[i] = (a << 24) | (straight((word >> 16) & 0xff) << 16) |
                               (straight((word >> 8) & 0xff) << 8) | straight(word & 0xff);
                }
            }
            std::memcpy(out + 4 * done, words, 4 * n);
            done += n;
        }
    }
}

void rgba_to_argb32(const std::uint8_t* rgba, std::size_t rgba_stride, std::uint8_t* argb, std::size_t argb_stride,
                    int width, int height) {
    for (int row = 0; row < height; ++row) {
        const std::uint8_t* in = rgba + static_cast<std::size_t>(row) * rgba_stride;
        std::uint8_t* out_row = argb + static_cast<std::size_t>(row) * argb_stride;
        for (int column = 0; column < width; ++column, in += 4) {
            const std::uint32_t a = in[3];
            auto premultiplied = [a](std::uint32_t c) { return (c * a + 127) / 255; };
            const std::uint32_t pixel =
                (a << 24) | (premultiplied(in[0]) << 16) | (premultiplied(in[1]) << 8) | premultiplied(in[2]);
            std::memcpy(out_row + 4 * static_cast<std::size_t>(column), &pixel, 4);
        }
    }
}

}  // namespace talkface::detail

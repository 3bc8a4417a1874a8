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
    for (int row = box.y; row < box.y + box.height; ++row) {
        const std::uint8_t* source_row = argb + static_cast<std::size_t>(row) * argb_stride;
        std::uint8_t* out = rgba + static_cast<std::size_t>(row) * rgba_stride + 4 * static_cast<std::size_t>(box.x);
        for (int column = box.x; column < box.x + box.width; ++column, out += 4) {
            std::uint32_t pixel;
            std::memcpy(&pixel, source_row + 4 * static_cast<std::size_t>(column), 4);
            const std::uint32_t a = pixel >> 24;
            std::uint32_t r = (pixel >> 16) & 0xff, g = (pixel >> 8) & 0xff, b = pixel & 0xff;
            if (!is_premultiplied && a != 0xff && a != 0) {
                // Rounded to nearest: c * 255 / a.
                r = (r * 255 + a / 2) / a;
                g = (g * 255 + a / 2) / a;
                b = (b * 255 + a / 2) / a;
            }
            out[0] = static_cast<std::uint8_t>(r);
            out[1] = static_cast<std::uint8_t>(g);
            out[2] = static_cast<std::uint8_t>(b);
            out[3] = static_cast<std::uint8_t>(a);
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

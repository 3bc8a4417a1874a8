// Pixels between cairo's layout and the callers': cairo's ARGB32 is one native-endian 32-bit word a
// pixel, premultiplied; callers get R, G, B, A bytes, straight or premultiplied.
#ifndef TALKFACE_RASTER_RGBA_PIXELS_HPP
#define TALKFACE_RASTER_RGBA_PIXELS_HPP

#include <cstddef>
#include <cstdint>

namespace talkface::detail {

// A box of whole pixels: columns x .. x + width - 1, rows y .. y + height - 1.
struct PixelBox {
    int x = 0, y = 0, width = 0, height = 0;
    bool is_empty() const { return width <= 0 || height <= 0; }
};

// The smallest box holding both.
PixelBox united(const PixelBox& a, const PixelBox& b);

// Copies `box` of cairo ARGB32 pixels (`argb`, rows `argb_stride` bytes apart) into RGBA bytes
// (`rgba`, rows `rgba_stride` apart, the same coordinates), unpremultiplied unless `is_premultiplied`.
void argb32_to_rgba(const std::uint8_t* argb, std::size_t argb_stride, std::uint8_t* rgba, std::size_t rgba_stride,
                    const PixelBox& box, bool is_premultiplied);

// Copies straight-alpha RGBA bytes into cairo ARGB32 (premultiplied), `width` x `height` pixels.
void rgba_to_argb32(const std::uint8_t* rgba, std::size_t rgba_stride, std::uint8_t* argb, std::size_t argb_stride,
                    int width, int height);

}  // namespace talkface::detail

#endif

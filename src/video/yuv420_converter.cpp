#include "video/yuv420_converter.hpp"

#include <algorithm>
#include <cstring>

namespace talkface::detail {

namespace {

// BT.709 (Kr 0.2126, Kb 0.0722) in limited range: Y 16..235, U and V 16..240, as the encoder's
// colour tags say. 16 fraction bits; a chroma sample is the mean of its 2x2 pixels, whose sum
// takes 2 more.
constexpr double kKr = 0.2126, kKb = 0.0722, kKg = 1.0 - kKr - kKb;
constexpr double kLumaScale = 219.0 / 255.0, kChromaScale = 224.0 / 255.0;
constexpr int kShift = 16;

constexpr int fixed(double value) { return static_cast<int>(value * (1 << kShift) + (value < 0 ? -0.5 : 0.5)); }

constexpr int kYr = fixed(kKr * kLumaScale), kYg = fixed(kKg * kLumaScale), kYb = fixed(kKb * kLumaScale);
constexpr int kUr = fixed(-kKr / (2.0 * (1.0 - kKb)) * kChromaScale);
constexpr int kUg = fixed(-kKg / (2.0 * (1.0 - kKb)) * kChromaScale);
constexpr int kUb = fixed(0.5 * kChromaScale);
constexpr int kVr = fixed(0.5 * kChromaScale);
constexpr int kVg = fixed(-kKg / (2.0 * (1.0 - kKr)) * kChromaScale);
constexpr int kVb = fixed(-kKb / (2.0 * (1.0 - kKr)) * kChromaScale);
constexpr int kLumaOffset = (16 << kShift) + (1 << (kShift - 1));
constexpr int kChromaOffset = (128 << (kShift + 2)) + (1 << (kShift + 1));

inline std::uint8_t luma(const std::uint8_t* p) {
    return static_cast<std::uint8_t>((kYr * p[0] + kYg * p[1] + kYb * p[2] + kLumaOffset) >> kShift);
}

// The first byte where `a` and `b` (`bytes` long, known to differ) differ, compared a word at a time.
std::size_t first_difference(const std::uint8_t* a, const std::uint8_t* b, std::size_t bytes) {
    std::size_t at = 0;
    for (; at + 8 <= bytes; at += 8) {
        std::uint64_t x, y;
        std::memcpy(&x, a + at, 8);
        std::memcpy(&y, b + at, 8);
        if (x != y) break;
    }
    while (a[at] == b[at]) ++at;
    return at;
}

// One past the last byte where `a` and `b` (`bytes` long, known to differ) differ.
std::size_t end_of_difference(const std::uint8_t* a, const std::uint8_t* b, std::size_t bytes) {
    std::size_t end = bytes;
    for (; end >= 8; end -= 8) {
        std::uint64_t x, y;
        std::memcpy(&x, a + end - 8, 8);
        std::memcpy(&y, b + end - 8, 8);
        if (x != y) break;
    }
    while (a[end - 1] == b[end - 1]) --end;
    return end;
}

}  // namespace

Yuv420Converter::Yuv420Converter(int width, int height, bool with_alpha)
    : width_(width), height_(height), with_alpha_(with_alpha),
      last_(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4) {}

PixelBox Yuv420Converter::find_change(const std::uint8_t* rgba, std::size_t stride_bytes) const {
    if (!has_last_) return {0, 0, width_, height_};
    const std::size_t row_bytes = 4 * static_cast<std::size_t>(width_);
    int top = height_, bottom = -1;
    std::size_t left = row_bytes, right = 0;
    for (int y = 0; y < height_; ++y) {
        const std::uint8_t* row = rgba + y * stride_bytes;
        const std::uint8_t* last = last_.data() + y * row_bytes;
        if (std::memcmp(row, last, row_bytes) == 0) continue;
        top = std::min(top, y);
        bottom = y;
        // Only bytes outside the columns found so far can widen the box.
        if (left > 0 && std::memcmp(row, last, left) != 0) left = first_difference(row, last, left);
        if (right < row_bytes && std::memcmp(row + right, last + right, row_bytes - right) != 0) {
            right += end_of_difference(row + right, last + right, row_bytes - right);
        }
    }
    if (bottom < 0) return {};
    // Whole 2x2 blocks: a chroma sample covers four pixels.
    const int x0 = static_cast<int>(left / 4) & ~1;
    const int x1 = std::min(width_, (static_cast<int>((right + 3) / 4) + 1) & ~1);
    const int y0 = top & ~1;
    const int y1 = std::min(height_, (bottom + 2) & ~1);
    return {x0, y0, x1 - x0, y1 - y0};
}

PixelBox Yuv420Converter::convert(const std::uint8_t* rgba, std::size_t stride_bytes, const Yuv420Planes& planes) {
    const PixelBox box = find_change(rgba, stride_bytes);
    if (box.is_empty()) return box;
    const std::size_t row_bytes = 4 * static_cast<std::size_t>(width_);
    for (int y = box.y; y < box.y + box.height; y += 2) {
        const std::uint8_t* top = rgba + y * stride_bytes;
        const std::uint8_t* under = top + stride_bytes;
        std::uint8_t* luma_top = planes.data[0] + y * planes.linesize[0];
        std::uint8_t* luma_under = luma_top + planes.linesize[0];
        std::uint8_t* u = planes.data[1] + (y / 2) * planes.linesize[1];
        std::uint8_t* v = planes.data[2] + (y / 2) * planes.linesize[2];
        for (int x = box.x; x < box.x + box.width; x += 2) {
            const std::uint8_t* a = top + 4 * x;
            const std::uint8_t* b = under + 4 * x;
            luma_top[x] = luma(a);
            luma_top[x + 1] = luma(a + 4);
            luma_under[x] = luma(b);
            luma_under[x + 1] = luma(b + 4);
            const int r = a[0] + a[4] + b[0] + b[4];
            const int g = a[1] + a[5] + b[1] + b[5];
            const int bl = a[2] + a[6] + b[2] + b[6];
            u[x / 2] = static_cast<std::uint8_t>((kUr * r + kUg * g + kUb * bl + kChromaOffset) >> (kShift + 2));
            v[x / 2] = static_cast<std::uint8_t>((kVr * r + kVg * g + kVb * bl + kChromaOffset) >> (kShift + 2));
        }
        if (with_alpha_) {
            for (int row = 0; row < 2; ++row) {
                const std::uint8_t* source = (row == 0 ? top : under) + 4 * box.x;
                std::uint8_t* alpha = planes.data[3] + (y + row) * planes.linesize[3] + box.x;
                for (int x = 0; x < box.width; ++x) alpha[x] = source[4 * x + 3];
            }
        }
        for (int row = 0; row < 2; ++row) {
            std::memcpy(last_.data() + (y + row) * row_bytes + 4 * box.x, (row == 0 ? top : under) + 4 * box.x,
                        4 * static_cast<std::size_t>(box.width));
        }
    }
    has_last_ = true;
    return box;
}

}  // namespace talkface::detail

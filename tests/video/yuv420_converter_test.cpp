// Yuv420Converter: BT.709 limited range, and a picture updated where frames changed equal to one
// converted whole.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdint>
#include <vector>

#include "video/yuv420_converter.hpp"

using talkface::detail::PixelBox;
using talkface::detail::Yuv420Converter;
using talkface::detail::Yuv420Planes;

namespace {

struct Picture {
    int width, height;
    std::vector<std::uint8_t> y, u, v, a;
    Picture(int w, int h)
        : width(w), height(h), y(std::size_t(w) * h), u(std::size_t(w / 2) * (h / 2)), v(u.size()), a(y.size()) {}
    Yuv420Planes planes() {
        Yuv420Planes planes;
        planes.data[0] = y.data();
        planes.data[1] = u.data();
        planes.data[2] = v.data();
        planes.data[3] = a.data();
        planes.linesize[0] = planes.linesize[3] = width;
        planes.linesize[1] = planes.linesize[2] = width / 2;
        return planes;
    }
};

std::vector<std::uint8_t> flat(int width, int height, std::uint8_t r, std::uint8_t g, std::uint8_t b) {
    std::vector<std::uint8_t> rgba(std::size_t(width) * height * 4);
    for (std::size_t i = 0; i < rgba.size(); i += 4) {
        rgba[i] = r;
        rgba[i + 1] = g;
        rgba[i + 2] = b;
        rgba[i + 3] = 255;
    }
    return rgba;
}

void paint(std::vector<std::uint8_t>& rgba, int width, int x0, int y0, int x1, int y1, std::uint32_t seed) {
    for (int y = y0; y < y1; ++y) {
        for (int x = x0; x < x1; ++x) {
            seed = seed * 1664525u + 1013904223u;
            std::uint8_t* p = &rgba[(std::size_t(y) * width + x) * 4];
            p[0] = std::uint8_t(seed >> 24);
            p[1] = std::uint8_t(seed >> 16);
            p[2] = std::uint8_t(seed >> 8);
            p[3] = std::uint8_t(seed);
        }
    }
}

}  // namespace

TEST_CASE("BT.709 limited range: white, black, red and blue") {
    struct Case {
        std::uint8_t r, g, b;
        int y, u, v;
    };
    for (const Case& c : {Case{255, 255, 255, 235, 128, 128}, Case{0, 0, 0, 16, 128, 128},
                          Case{255, 0, 0, 63, 102, 240}, Case{0, 0, 255, 32, 240, 118}}) {
        CAPTURE(int(c.r));
        CAPTURE(int(c.b));
        Picture picture(4, 2);
        Yuv420Converter converter(4, 2, false);
        const std::vector<std::uint8_t> rgba = flat(4, 2, c.r, c.g, c.b);
        converter.convert(rgba.data(), 16, picture.planes());
        CHECK(int(picture.y[5]) == c.y);
        CHECK(int(picture.u[1]) == c.u);
        CHECK(int(picture.v[1]) == c.v);
    }
}

TEST_CASE("every sample is the exact BT.709 value rounded, chroma the mean of its 2x2 pixels") {
    // What a decoder reading the stream's tags (BT.709, limited range) inverts: a bias here moves
    // every colour of the video (the fixed-point coefficients may only decide exact halves).
    const int width = 32, height = 16;
    std::vector<std::uint8_t> rgba(std::size_t(width) * height * 4);
    paint(rgba, width, 0, 0, width, height, 7);
    Picture picture(width, height);
    Yuv420Converter(width, height, true).convert(rgba.data(), width * 4, picture.planes());
    const double kr = 0.2126, kb = 0.0722, kg = 1.0 - kr - kb;
    auto at = [&](int x, int y, int c) { return double(rgba[(std::size_t(y) * width + x) * 4 + c]); };
    auto luma = [&](int x, int y) { return kr * at(x, y, 0) + kg * at(x, y, 1) + kb * at(x, y, 2); };
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            CHECK(std::abs(picture.y[std::size_t(y) * width + x] - (16.0 + 219.0 / 255.0 * luma(x, y))) <= 0.51);
            CHECK(int(picture.a[std::size_t(y) * width + x]) == int(at(x, y, 3)));
        }
    }
    for (int y = 0; y < height; y += 2) {
        for (int x = 0; x < width; x += 2) {
            double u = 0.0, v = 0.0;
            for (int k = 0; k < 4; ++k) {
                const int px = x + k % 2, py = y + k / 2;
                u += (at(px, py, 2) - luma(px, py)) / (2.0 * (1.0 - kb)) / 4.0;
                v += (at(px, py, 0) - luma(px, py)) / (2.0 * (1.0 - kr)) / 4.0;
            }
            const std::size_t chroma = std::size_t(y / 2) * (width / 2) + x / 2;
            CHECK(std::abs(picture.u[chroma] - (128.0 + 224.0 / 255.0 * u)) <= 0.51);
            CHECK(std::abs(picture.v[chroma] - (128.0 + 224.0 / 255.0 * v)) <= 0.51);
        }
    }
}

TEST_CASE("a picture updated where frames changed equals the frame converted whole") {
    const int width = 64, height = 48;
    Picture kept(width, height);
    Yuv420Converter converter(width, height, true);
    std::vector<std::uint8_t> rgba = flat(width, height, 30, 60, 90);
    const PixelBox first = converter.convert(rgba.data(), width * 4, kept.planes());
    CHECK(first.width == width);
    CHECK(first.height == height);
    CHECK(converter.convert(rgba.data(), width * 4, kept.planes()).is_empty());
    // Changes at odd and even edges, at the frame's borders, one pixel alone.
    const int boxes[][4] = {{5, 7, 20, 19}, {0, 0, 1, 1}, {63, 47, 64, 48}, {10, 0, 11, 48}, {0, 30, 64, 31}};
    std::uint32_t seed = 1;
    for (const auto& box : boxes) {
        CAPTURE(box[0]);
        CAPTURE(box[1]);
        paint(rgba, width, box[0], box[1], box[2], box[3], seed++);
        const PixelBox changed = converter.convert(rgba.data(), width * 4, kept.planes());
        CHECK(changed.x <= box[0]);
        CHECK(changed.y <= box[1]);
        CHECK(changed.x + changed.width >= box[2]);
        CHECK(changed.y + changed.height >= box[3]);
        CHECK(changed.width <= box[2] - box[0] + 2);
        CHECK(changed.height <= box[3] - box[1] + 2);
        Picture whole(width, height);
        Yuv420Converter fresh(width, height, true);
        fresh.convert(rgba.data(), width * 4, whole.planes());
        CHECK(kept.y == whole.y);
        CHECK(kept.u == whole.u);
        CHECK(kept.v == whole.v);
        CHECK(kept.a == whole.a);
    }
}

// FrameRenderer against the SVG it stands for: each state drawn by SvgAnimator, rasterised by
// rsvg-convert (librsvg), and compared with the frame pixel by pixel.
#include <doctest/doctest.h>

#include <cairo.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <vector>

#include "common/test_paths.hpp"
#include "talkface/errors.hpp"
#include "talkface/face_model.hpp"
#include "talkface/frame_renderer.hpp"
#include "talkface/mouth_shape.hpp"
#include "talkface/svg_animator.hpp"

using namespace talkface;

namespace {

struct Image {
    int width = 0, height = 0;
    std::vector<std::uint8_t> rgba;  // straight alpha
};

// TALKFACE_RASTER_DUMP=DIR keeps the frames and the references as PNG files there, to look at.
void dump_png(const Image& image, const std::string& name) {
    const char* folder = std::getenv("TALKFACE_RASTER_DUMP");
    if (folder == nullptr) return;
    cairo_surface_t* surface = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, image.width, image.height);
    std::uint8_t* data = cairo_image_surface_get_data(surface);
    const int stride = cairo_image_surface_get_stride(surface);
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            const std::uint8_t* p = &image.rgba[(static_cast<std::size_t>(y) * image.width + x) * 4];
            const std::uint32_t a = p[3];
            auto pre = [a](std::uint32_t c) { return (c * a + 127) / 255; };
            const std::uint32_t pixel = (a << 24) | (pre(p[0]) << 16) | (pre(p[1]) << 8) | pre(p[2]);
            std::memcpy(data + y * stride + 4 * x, &pixel, 4);
        }
    }
    cairo_surface_mark_dirty(surface);
    cairo_surface_write_to_png(surface, (std::string(folder) + "/" + name + ".png").c_str());
    cairo_surface_destroy(surface);
}

Image read_png(const std::string& path) {
    cairo_surface_t* surface = cairo_image_surface_create_from_png(path.c_str());
    REQUIRE(cairo_surface_status(surface) == CAIRO_STATUS_SUCCESS);
    cairo_surface_t* argb = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, cairo_image_surface_get_width(surface),
                                                       cairo_image_surface_get_height(surface));
    cairo_t* cairo = cairo_create(argb);
    cairo_set_source_surface(cairo, surface, 0, 0);
    cairo_paint(cairo);
    cairo_destroy(cairo);
    cairo_surface_flush(argb);
    Image image;
    image.width = cairo_image_surface_get_width(argb);
    image.height = cairo_image_surface_get_height(argb);
    image.rgba.resize(static_cast<std::size_t>(image.width) * image.height * 4);
    const std::uint8_t* data = cairo_image_surface_get_data(argb);
    const int stride = cairo_image_surface_get_stride(argb);
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            std::uint32_t pixel;
            std::memcpy(&pixel, data + y * stride + 4 * x, 4);
            const std::uint32_t a = pixel >> 24;
            auto straight = [a](std::uint32_t c) { return a == 0 ? 0u : (c * 255 + a / 2) / a; };
            std::uint8_t* p = &image.rgba[(static_cast<std::size_t>(y) * image.width + x) * 4];
            p[0] = static_cast<std::uint8_t>(straight((pixel >> 16) & 0xff));
            p[1] = static_cast<std::uint8_t>(straight((pixel >> 8) & 0xff));
            p[2] = static_cast<std::uint8_t>(straight(pixel & 0xff));
            p[3] = static_cast<std::uint8_t>(a);
        }
    }
    cairo_surface_destroy(argb);
    cairo_surface_destroy(surface);
    return image;
}

// rsvg-convert's rendering of the state's SVG, at the document's size. The document's background
// covers its viewBox, a frame's the whole frame: what the viewBox leaves is given the background
// colour.
Image rasterise_svg(const SvgAnimator& animator, const FaceState& state, const std::string& name) {
    const std::string svg_path = test::output_path(name + ".svg");
    const std::string png_path = test::output_path(name + "-rsvg.png");
    animator.write_svg(svg_path, state);
    const std::string command = std::string(TALKFACE_RSVG_CONVERT) + " -o '" + png_path + "' '" + svg_path + "'";
    REQUIRE(std::system(command.c_str()) == 0);
    Image image = read_png(png_path);
    if (const std::optional<Rgb> background = animator.options().background) {
        for (std::size_t i = 0; i < image.rgba.size(); i += 4) {
            const int a = image.rgba[i + 3];
            const std::uint8_t colour[] = {background->r, background->g, background->b};
            for (int c = 0; c < 3; ++c)
                image.rgba[i + c] = static_cast<std::uint8_t>((image.rgba[i + c] * a + colour[c] * (255 - a) + 127) / 255);
            image.rgba[i + 3] = 255;
        }
    }
    return image;
}

// How far two images are apart: the mean absolute difference of a channel, and the share of
// pixels where some channel differs by more than 64 of 255 (what an eye sees as another colour;
// antialiased edges differ by less).
struct Difference {
    double mean = 0.0;
    double share_far = 0.0;
};

Difference difference(const Image& a, const Image& b) {
    REQUIRE(a.width == b.width);
    REQUIRE(a.height == b.height);
    double total = 0.0;
    std::size_t far = 0;
    const std::size_t pixels = static_cast<std::size_t>(a.width) * a.height;
    for (std::size_t i = 0; i < pixels; ++i) {
        int largest = 0;
        for (int c = 0; c < 4; ++c) {
            const int d = std::abs(static_cast<int>(a.rgba[4 * i + c]) - static_cast<int>(b.rgba[4 * i + c]));
            total += d;
            largest = std::max(largest, d);
        }
        if (largest > 64) ++far;
    }
    return {total / (4.0 * static_cast<double>(pixels)), static_cast<double>(far) / static_cast<double>(pixels)};
}

// The tolerance of a frame against rsvg-convert's picture of the same SVG. Measured (librsvg 2.54,
// which draws with cairo too): a mean of 0.007-0.018 of 255 and no far pixel at all, at every size,
// state and face here; what differs is the last bit of an antialiased edge's coverage. The limits
// leave room for another librsvg; a mouth shape or a turn of 12 degrees is far beyond them.
constexpr double kMaxMeanDifference = 0.25;
constexpr double kMaxShareFar = 0.0005;

Image frame_of(FrameRenderer& renderer, const FaceState& state) {
    Image image;
    image.width = renderer.width_px();
    image.height = renderer.height_px();
    image.rgba = renderer.render_frame_rgba(state);
    return image;
}

std::vector<FaceState> test_states(const FaceModel& face) {
    std::vector<FaceState> states;
    const double poses[][3] = {{0, 0, 0}, {10, -12, 5}, {-15, 15, -15}, {5, 14, 0}, {-8, -15, 12}};
    const MouthShape mouths[] = {MouthShape::a, MouthShape::o, MouthShape::m, MouthShape::i, MouthShape::u};
    for (std::size_t i = 0; i < 5; ++i) {
        FaceState state;
        state.pose = {poses[i][0], poses[i][1], poses[i][2]};
        state.mouth = mouth_controls(face, mouths[i]);
        state.expression.blink_left = i == 1 ? 0.6 : i == 3 ? 1.0 : 0.0;
        state.expression.blink_right = i == 3 ? 1.0 : 0.0;
        state.expression.smile = i == 2 ? 0.8 : 0.0;
        state.expression.brows = i == 4 ? 1.0 : 0.0;
        states.push_back(state);
    }
    return states;
}

}  // namespace

TEST_SUITE("FrameRenderer") {
    TEST_CASE("frames match rsvg-convert's pictures of the same states' SVG, at several sizes") {
        // The SVG documents are made at the frame's size: their viewBox is fitted and centred into it
        // (preserveAspectRatio's default), as FrameLayout::face places the face.
        const int sizes[][2] = {{200, 260}, {318, 378}, {640, 480}, {900, 1200}};
        for (const char* face_file : {"", "samples/faces/female.xml"}) {
            const FaceModel face = *face_file ? FaceModel::load(test::source_path(face_file)) : FaceModel::default_face();
            const std::vector<FaceState> states = test_states(face);
            for (const auto& size : sizes) {
              // The flat look at one size: the same shapes, other paints.
              for (const FaceLook look : {FaceLook::outlined, FaceLook::flat}) {
                if (look == FaceLook::flat && size[0] != 318) continue;
                SvgOptions svg_options;
                svg_options.width_px = size[0];
                svg_options.height_px = size[1];
                svg_options.look = look;
                const SvgAnimator animator(face, svg_options);
                FrameOptions options;
                options.look = look;
                options.layout = FrameLayout::face;
                options.background = svg_options.background;
                options.width_px = size[0];
                options.height_px = size[1];
                FrameRenderer renderer(face, options);
                for (std::size_t i = 0; i < states.size(); ++i) {
                    const std::string name = std::string("raster-") + (*face_file ? "female" : "default") + "-" +
                                             face_look_name(look) + "-" + std::to_string(size[0]) + "-" +
                                             std::to_string(i);
                    CAPTURE(name);
                    const Image frame = frame_of(renderer, states[i]);
                    const Image reference = rasterise_svg(animator, states[i], name);
                    dump_png(frame, name);
                    dump_png(reference, name + "-rsvg");
                    const Difference d = difference(frame, reference);
                    CAPTURE(d.mean);
                    CAPTURE(d.share_far);
                    if (std::getenv("TALKFACE_RASTER_DUMP") != nullptr)
                        MESSAGE(name << ": mean " << d.mean << ", far " << d.share_far);
                    CHECK(d.mean < kMaxMeanDifference);
                    CHECK(d.share_far < kMaxShareFar);
                }
              }
            }
        }
    }

    TEST_CASE("the comparison tells another mouth shape and a turned head apart") {
        const FaceModel face = FaceModel::default_face();
        SvgOptions svg_options;
        svg_options.width_px = 400;
        svg_options.height_px = 470;
        const SvgAnimator animator(face, svg_options);
        FrameOptions options;
        options.layout = FrameLayout::face;
        options.background = svg_options.background;
        options.width_px = 400;
        options.height_px = 470;
        FrameRenderer renderer(face, options);
        FaceState open;
        open.mouth = mouth_controls(face, MouthShape::a);
        FaceState closed;
        closed.mouth = mouth_controls(face, MouthShape::m);
        FaceState turned = open;
        turned.pose.beta_deg = 12.0;
        const Image reference = rasterise_svg(animator, open, "raster-apart");
        CHECK(difference(frame_of(renderer, open), reference).share_far < kMaxShareFar);
        CHECK(difference(frame_of(renderer, closed), reference).share_far > kMaxShareFar);
        CHECK(difference(frame_of(renderer, turned), reference).share_far > kMaxShareFar);
    }

    TEST_CASE("a frame drawn after others is the frame a new renderer draws") {
        const FaceModel face = FaceModel::default_face();
        const std::vector<FaceState> states = test_states(face);
        FrameOptions options;  // the announcer layout at 1280x720
        FrameRenderer running(face, options);
        for (int round = 0; round < 2; ++round) {
            for (std::size_t i = 0; i < states.size(); ++i) {
                CAPTURE(i);
                const std::vector<std::uint8_t> frame = running.render_frame_rgba(states[i]);
                FrameRenderer fresh(face, options);
                CHECK(frame == fresh.render_frame_rgba(states[i]));
                CHECK(frame == running.render_frame_rgba(states[i]));  // held: the same again
            }
        }
    }

    TEST_CASE("frames of a held head, where only the mouth, the lids and the brows move, are whole frames") {
        const FaceModel face = FaceModel::default_face();
        FrameOptions options;
        options.width_px = 640;
        options.height_px = 360;
        FrameRenderer running(face, options);
        FaceState state;
        state.pose = {4.0, -6.0, 2.0};
        std::vector<FaceState> sequence;
        for (const MouthShape shape : {MouthShape::a, MouthShape::o, MouthShape::m, MouthShape::i, MouthShape::e}) {
            state.mouth = mouth_controls(face, shape);
            sequence.push_back(state);
        }
        state.expression.blink_left = state.expression.blink_right = 0.7;
        sequence.push_back(state);
        state.expression.blink_left = state.expression.blink_right = 0.0;
        state.expression.brows = 0.8;
        sequence.push_back(state);
        state.pose.beta_deg = 3.0;  // and the head moves again
        sequence.push_back(state);
        state.mouth = mouth_controls(face, MouthShape::u);
        sequence.push_back(state);
        for (std::size_t i = 0; i < sequence.size(); ++i) {
            CAPTURE(i);
            FrameRenderer fresh(face, options);
            CHECK(running.render_frame_rgba(sequence[i]) == fresh.render_frame_rgba(sequence[i]));
        }
    }

    TEST_CASE("the announcer layout stands the face on the frame's bottom edge over the background") {
        const FaceModel face = FaceModel::default_face();
        FrameOptions options;
        FrameRenderer renderer(face, options);
        const Image frame = frame_of(renderer, FaceState{});
        dump_png(frame, "raster-announcer");
        auto pixel = [&](int x, int y) { return &frame.rgba[(static_cast<std::size_t>(y) * frame.width + x) * 4]; };
        const Rgb stage = *options.background;
        CHECK(pixel(5, 5)[0] == stage.r);
        CHECK(pixel(5, 5)[2] == stage.b);
        CHECK(pixel(1274, 715)[1] == stage.g);
        // The shirt at the bottom in the middle, the skin of the face above it.
        CHECK(pixel(640, 710)[0] == options.clothes.r);
        CHECK(pixel(640, 710)[2] == options.clothes.b);
        CHECK(pixel(640, 710)[3] == 255);
        const Rgb skin = face.colors().skin;
        bool has_skin = false;
        for (int y = 200; y < 500 && !has_skin; ++y) has_skin = pixel(640, y)[0] == skin.r && pixel(640, y)[1] == skin.g;
        CHECK(has_skin);
    }

    TEST_CASE("a transparent frame: alpha 0 off the face, premultiplied is straight times alpha") {
        const FaceModel face = FaceModel::default_face();
        FrameOptions options;
        options.width_px = 320;
        options.height_px = 240;
        options.background.reset();
        FrameRenderer straight(face, options);
        options.alpha = AlphaMode::premultiplied;
        FrameRenderer premultiplied(face, options);
        FaceState state;
        state.pose.beta_deg = 9.0;
        const std::vector<std::uint8_t> s = straight.render_frame_rgba(state);
        const std::vector<std::uint8_t> p = premultiplied.render_frame_rgba(state);
        CHECK(s[3] == 0);
        std::size_t partial = 0;
        for (std::size_t i = 0; i < s.size(); i += 4) {
            const int a = s[i + 3];
            REQUIRE(p[i + 3] == a);
            if (a != 0 && a != 255) ++partial;
            for (int c = 0; c < 3; ++c) CHECK(std::abs(p[i + c] - (s[i + c] * a + 127) / 255) <= 1);
        }
        CHECK(partial > 100);  // antialiased edges against nothing
    }

    TEST_CASE("a background picture covers the frame, under the face") {
        const FaceModel face = FaceModel::default_face();
        FrameOptions options;
        options.width_px = 640;
        options.height_px = 360;
        FrameRenderer renderer(face, options);
        std::vector<std::uint8_t> picture(4 * 4 * 3, 0);
        for (std::size_t i = 0; i < picture.size(); i += 4) {
            picture[i] = 200;
            picture[i + 3] = 255;
        }
        renderer.set_background_image(picture.data(), 4, 3, 16);
        const std::vector<std::uint8_t> frame = renderer.render_frame_rgba(FaceState{});
        CHECK(frame[0] == 200);
        CHECK(frame[1] == 0);
        CHECK(frame[frame.size() - 4] == 200);
        CHECK_THROWS_WITH_AS(renderer.set_background_image(picture.data(), 4, 3, 8),
                             doctest::Contains("stride_bytes"), InvalidArgument);
    }

    TEST_CASE("rows are written at the caller's stride and the padding is left alone") {
        const FaceModel face = FaceModel::default_face();
        FrameOptions options;
        options.width_px = 50;
        options.height_px = 40;
        FrameRenderer renderer(face, options);
        const std::size_t stride = 4 * 50 + 12;
        std::vector<std::uint8_t> buffer(stride * 40, 0xab);
        renderer.render_frame_rgba(FaceState{}, buffer.data(), stride);
        const std::vector<std::uint8_t> packed = renderer.render_frame_rgba(FaceState{});
        for (int row = 0; row < 40; ++row) {
            CAPTURE(row);
            CHECK(std::equal(packed.begin() + row * 200, packed.begin() + row * 200 + 200, buffer.begin() + row * stride));
            CHECK(buffer[row * stride + 200] == 0xab);
            CHECK(buffer[row * stride + stride - 1] == 0xab);
        }
    }

    TEST_CASE("options and buffers out of range are refused, naming them") {
        const FaceModel face = FaceModel::default_face();
        auto with = [](auto change) {
            FrameOptions options;
            change(options);
            return options;
        };
        CHECK_THROWS_WITH_AS(FrameRenderer(face, with([](FrameOptions& o) { o.width_px = 0; })),
                             doctest::Contains("width_px"), InvalidArgument);
        CHECK_THROWS_WITH_AS(FrameRenderer(face, with([](FrameOptions& o) { o.width_px = 7681; })),
                             doctest::Contains("1..7680"), InvalidArgument);
        CHECK_THROWS_WITH_AS(FrameRenderer(face, with([](FrameOptions& o) { o.height_px = 4321; })),
                             doctest::Contains("height_px"), InvalidArgument);
        CHECK_THROWS_WITH_AS(FrameRenderer(face, with([](FrameOptions& o) { o.stroke_width_in_d = 0.0; })),
                             doctest::Contains("stroke_width_in_d"), InvalidArgument);
        CHECK_THROWS_WITH_AS(FrameRenderer(face, with([](FrameOptions& o) { o.face_d_px = -1.0; })),
                             doctest::Contains("face_d_px"), InvalidArgument);
        CHECK_THROWS_WITH_AS(FrameRenderer(face, with([](FrameOptions& o) { o.layout = static_cast<FrameLayout>(7); })),
                             doctest::Contains("layout"), InvalidArgument);
        FrameOptions small;
        small.width_px = 8;
        small.height_px = 8;
        FrameRenderer renderer(face, small);
        std::vector<std::uint8_t> buffer(8 * 32);
        CHECK_THROWS_WITH_AS(renderer.render_frame_rgba(FaceState{}, nullptr, 32), doctest::Contains("rgba"),
                             InvalidArgument);
        CHECK_THROWS_WITH_AS(renderer.render_frame_rgba(FaceState{}, buffer.data(), 31),
                             doctest::Contains("stride_bytes"), InvalidArgument);
        FaceState bad;
        bad.pose.alpha_deg = 40.0;
        CHECK_THROWS_AS(renderer.render_frame_rgba(bad, buffer.data(), 32), InvalidArgument);
    }
}

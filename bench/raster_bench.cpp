// The raster renderer's speed and the choice of 2D library (issue 16): frames of a spoken
// animation at 1280x720, 30 fps, in the announcer layout, drawn by
//   FrameRenderer          cairo, the static layers cached, only the head's region drawn again;
//   cairo, whole frames    the same drawing model, every layer drawn on a cleared frame;
//   OpenCV fillPoly        the same model flattened to polygons, cv::fillPoly and cv::polylines
//                          with LINE_AA (no gradients or clip paths: OpenCV has neither),
// and, for a few frames, how far each picture is from rsvg-convert's of the same state's SVG (the
// reference the tests hold FrameRenderer to).
//
//   raster_bench [AUDIO TRANSCRIPT] [--size WxH] [--fps N] [--seconds S]
//
// Default speech: samples/speech/demo.ogg, repeated until S seconds of frames (60) were drawn.
// One thread. Prints frames per second and the real-time factor at the animation's frame rate.
#include <cairo.h>

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <string>
#include <vector>

#include <talkface/talkface.hpp>

#include "raster/cairo_drawing.hpp"
#include "raster/frame_layout.hpp"
#include "render/face_canvas.hpp"
#include "render/layers.hpp"

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

[[noreturn]] void usage(const std::string& why) {
    std::cerr << "raster_bench: " << why << "\nusage: raster_bench [AUDIO TRANSCRIPT] [--size WxH] [--fps N] [--seconds S]\n";
    std::exit(2);
}

// The drawing model of one state in image pixels, as FrameRenderer builds it.
struct StateLayers {
    talkface::detail::Layer hair, clothes, face;
};

struct Scene {
    talkface::FaceModel face;
    talkface::FrameOptions options;
    talkface::detail::CanvasBox canvas;
    talkface::detail::FramePlacement placement;
    talkface::detail::FacePaints paints;
    talkface::detail::LayerStyle style;

    Scene(talkface::FaceModel model, const talkface::FrameOptions& frame_options)
        : face(std::move(model)), options(frame_options) {
        canvas = talkface::detail::fit_face_canvas(face);
        placement = talkface::detail::place_face(face, canvas, options);
        const talkface::ProjectedFace neutral = talkface::project_face(face, talkface::FaceState{});
        style = {2, options.stroke_width_in_d * neutral.d};
        paints = talkface::detail::make_face_paints(neutral, style);
    }

    StateLayers layers(const talkface::FaceState& state) const {
        const talkface::ProjectedFace projected = talkface::project_face(face, state);
        return {talkface::detail::draw_hair_layer(projected, paints),
                talkface::detail::draw_clothes_layer(projected, canvas, options.clothes, style),
                talkface::detail::draw_face_layer(projected, paints)};
    }
};

// Every layer drawn on a cleared frame: no cache, no dirty region.
void draw_whole_cairo(const Scene& scene, const talkface::FaceState& state, cairo_surface_t* surface) {
    const StateLayers layers = scene.layers(state);
    cairo_t* cairo = cairo_create(surface);
    const talkface::Rgb background = *scene.options.background;
    cairo_set_source_rgb(cairo, background.r / 255.0, background.g / 255.0, background.b / 255.0);
    cairo_paint(cairo);
    cairo_matrix_t matrix;
    cairo_matrix_init(&matrix, scene.placement.scale, 0, 0, scene.placement.scale, scene.placement.offset.x,
                      scene.placement.offset.y);
    cairo_set_matrix(cairo, &matrix);
    for (const talkface::detail::Layer* layer : {&layers.hair, &layers.clothes, &layers.face})
        talkface::detail::draw_layer(cairo, *layer);
    cairo_destroy(cairo);
    cairo_surface_flush(surface);
}

// --- OpenCV: the model flattened --------------------------------------------------------------

constexpr int kShift = 4;  // fixed-point bits of OpenCV's subpixel coordinates
constexpr int kCurveSteps = 12;

cv::Point fixed(const Scene& scene, talkface::Point2 p) {
    const talkface::Point2 q = scene.placement.apply(p);
    return {static_cast<int>(std::lround(q.x * (1 << kShift))), static_cast<int>(std::lround(q.y * (1 << kShift)))};
}

// Subpaths as polygons; `closed` says which end with a close.
void flatten(const Scene& scene, const talkface::detail::Path& path, std::vector<std::vector<cv::Point>>& polygons,
             std::vector<bool>& closed) {
    using talkface::detail::PathVerb;
    std::size_t next = 0;
    talkface::Point2 pen{0, 0};
    for (const PathVerb verb : path.verbs) {
        const auto& p = path.points;
        switch (verb) {
            case PathVerb::move:
                polygons.emplace_back();
                closed.push_back(false);
                pen = p[next];
                polygons.back().push_back(fixed(scene, pen));
                break;
            case PathVerb::line:
                pen = p[next];
                polygons.back().push_back(fixed(scene, pen));
                break;
            case PathVerb::cubic:
            case PathVerb::quadratic: {
                const bool is_cubic = verb == PathVerb::cubic;
                const talkface::Point2 a = pen, b = p[next], c = is_cubic ? p[next + 1] : p[next],
                                       d = is_cubic ? p[next + 2] : p[next + 1];
                for (int step = 1; step <= kCurveSteps; ++step) {
                    const double t = static_cast<double>(step) / kCurveSteps, u = 1.0 - t;
                    talkface::Point2 q;
                    if (is_cubic) {
                        q = {u * u * u * a.x + 3 * u * u * t * b.x + 3 * u * t * t * c.x + t * t * t * d.x,
                             u * u * u * a.y + 3 * u * u * t * b.y + 3 * u * t * t * c.y + t * t * t * d.y};
                    } else {
                        q = {u * u * a.x + 2 * u * t * b.x + t * t * d.x, u * u * a.y + 2 * u * t * b.y + t * t * d.y};
                    }
                    polygons.back().push_back(fixed(scene, q));
                }
                pen = d;
                break;
            }
            case PathVerb::close: closed.back() = true; break;
        }
        next += static_cast<std::size_t>(talkface::detail::points_of(verb));
    }
}

cv::Scalar bgr(const talkface::detail::Paint& paint, const talkface::detail::Layer& layer) {
    talkface::Rgb colour = paint.colour;
    if (paint.kind == talkface::detail::PaintKind::gradient) {
        // No gradients in OpenCV: the middle stop's colour.
        const auto& stops = layer.definitions[paint.gradient].gradient.stops;
        colour = stops[stops.size() / 2].colour;
    }
    return {static_cast<double>(colour.b), static_cast<double>(colour.g), static_cast<double>(colour.r), 255};
}

void draw_opencv_shape(const Scene& scene, const talkface::detail::Layer& layer, const talkface::detail::Shape& shape,
                       cv::Mat& image) {
    using talkface::detail::ShapeKind;
    using talkface::detail::PaintKind;
    if (shape.kind == ShapeKind::group) {
        for (const auto& child : shape.children) draw_opencv_shape(scene, layer, child, image);  // unclipped
        return;
    }
    std::vector<std::vector<cv::Point>> polygons;
    std::vector<bool> closed;
    if (shape.kind == ShapeKind::circle) {
        const cv::Point centre = fixed(scene, shape.centre);
        const int radius = static_cast<int>(std::lround(shape.radius * scene.placement.scale * (1 << kShift)));
        if (shape.paint.fill.kind != PaintKind::none)
            cv::circle(image, centre, radius, bgr(shape.paint.fill, layer), cv::FILLED, cv::LINE_AA, kShift);
        return;
    }
    const talkface::detail::Path& path =
        shape.kind == ShapeKind::reference ? layer.definitions[shape.definition].outline : shape.path;
    flatten(scene, path, polygons, closed);
    if (shape.paint.fill.kind != PaintKind::none)
        cv::fillPoly(image, polygons, bgr(shape.paint.fill, layer), cv::LINE_AA, kShift);
    if (shape.paint.stroke.kind != PaintKind::none && shape.paint.stroke_width > 0.0) {
        const int thickness = std::max(1, static_cast<int>(std::lround(shape.paint.stroke_width * scene.placement.scale)));
        for (std::size_t i = 0; i < polygons.size(); ++i)
            cv::polylines(image, polygons[i], closed[i], bgr(shape.paint.stroke, layer), thickness, cv::LINE_AA, kShift);
    }
}

void draw_whole_opencv(const Scene& scene, const talkface::FaceState& state, cv::Mat& image) {
    const StateLayers layers = scene.layers(state);
    const talkface::Rgb background = *scene.options.background;
    image.setTo(cv::Scalar(background.b, background.g, background.r, 255));
    for (const talkface::detail::Layer* layer : {&layers.hair, &layers.clothes, &layers.face})
        for (const auto& shape : layer->elements) draw_opencv_shape(scene, *layer, shape, image);
}

// --- the reference ------------------------------------------------------------------------------

// rsvg-convert's picture of the state's SVG on a stage like the announcer's: the face's own SVG
// scaled and placed as FrameLayout::announcer places it, over the background, as RGBA.
std::vector<std::uint8_t> reference_rgba(const Scene& scene, const talkface::FaceState& state, int index) {
    talkface::SvgOptions svg_options;
    svg_options.background.reset();
    const std::string face_svg = talkface::SvgAnimator(scene.face, svg_options).render_svg(state);
    const std::string inner = face_svg.substr(face_svg.find("<svg"));
    const auto& box = scene.placement.canvas_in_frame;
    char place[200];
    std::snprintf(place, sizeof place, "<svg x=\"%.4f\" y=\"%.4f\" width=\"%.4f\" height=\"%.4f\" ", box.x, box.y,
                  box.width, box.height);
    // The face document's own width and height give way to the place on the stage.
    std::string nested = inner;
    const std::size_t w = nested.find(" width=\"");
    nested.erase(w, nested.find('"', w + 8) + 1 - w);
    const std::size_t h = nested.find(" height=\"");
    nested.erase(h, nested.find('"', h + 9) + 1 - h);
    nested.replace(0, 5, place);
    const talkface::Rgb bg = *scene.options.background;
    char head[300];
    std::snprintf(head, sizeof head,
                  "<svg xmlns=\"http://www.w3.org/2000/svg\" xmlns:xlink=\"http://www.w3.org/1999/xlink\" width=\"%d\" "
                  "height=\"%d\"><rect width=\"%d\" height=\"%d\" fill=\"#%02x%02x%02x\"/>",
                  scene.options.width_px, scene.options.height_px, scene.options.width_px, scene.options.height_px, bg.r,
                  bg.g, bg.b);
    const std::string svg_path = "/tmp/talkface-raster-bench-" + std::to_string(index) + ".svg";
    const std::string png_path = "/tmp/talkface-raster-bench-" + std::to_string(index) + ".png";
    std::FILE* file = std::fopen(svg_path.c_str(), "w");
    std::fputs((head + nested + "</svg>\n").c_str(), file);
    std::fclose(file);
    if (std::system(("rsvg-convert -o " + png_path + " " + svg_path).c_str()) != 0) return {};
    cairo_surface_t* png = cairo_image_surface_create_from_png(png_path.c_str());
    std::vector<std::uint8_t> rgba(static_cast<std::size_t>(scene.options.width_px) * scene.options.height_px * 4);
    const unsigned char* data = cairo_image_surface_get_data(png);
    const int stride = cairo_image_surface_get_stride(png);
    for (int y = 0; y < scene.options.height_px; ++y) {
        for (int x = 0; x < scene.options.width_px; ++x) {
            std::uint32_t pixel;
            std::memcpy(&pixel, data + y * stride + 4 * x, 4);
            std::uint8_t* out = &rgba[(static_cast<std::size_t>(y) * scene.options.width_px + x) * 4];
            out[0] = static_cast<std::uint8_t>(pixel >> 16);
            out[1] = static_cast<std::uint8_t>(pixel >> 8);
            out[2] = static_cast<std::uint8_t>(pixel);
            out[3] = static_cast<std::uint8_t>(pixel >> 24);
        }
    }
    cairo_surface_destroy(png);
    std::remove(svg_path.c_str());
    std::remove(png_path.c_str());
    return rgba;
}

// Mean |difference| of the R, G, B channels (opaque frames), and the share of pixels off by > 64.
void compare(const std::vector<std::uint8_t>& a, const std::vector<std::uint8_t>& b, double& mean, double& far) {
    double total = 0.0;
    std::size_t far_pixels = 0;
    for (std::size_t i = 0; i < a.size(); i += 4) {
        int largest = 0;
        for (int c = 0; c < 3; ++c) {
            const int d = std::abs(a[i + c] - b[i + c]);
            total += d;
            largest = std::max(largest, d);
        }
        if (largest > 64) ++far_pixels;
    }
    mean = total / (3.0 * a.size() / 4.0);
    far = static_cast<double>(far_pixels) / (a.size() / 4.0);
}

}  // namespace

int main(int argc, char** argv) {
    std::string audio = std::string(TALKFACE_SOURCE_DIR) + "/samples/speech/demo.ogg";
    std::string transcript = std::string(TALKFACE_SOURCE_DIR) + "/samples/speech/demo.txt";
    talkface::FrameOptions options;
    double fps = 30.0;
    double seconds = 60.0;
    std::vector<std::string> positional;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if (arg == "--size" && i + 1 < argc) {
            if (std::sscanf(argv[++i], "%dx%d", &options.width_px, &options.height_px) != 2) usage("--size WxH");
        } else if (arg == "--fps" && i + 1 < argc) {
            fps = std::atof(argv[++i]);
        } else if (arg == "--seconds" && i + 1 < argc) {
            seconds = std::atof(argv[++i]);
        } else if (!arg.empty() && arg[0] == '-') {
            usage("unknown option " + arg);
        } else {
            positional.push_back(arg);
        }
    }
    if (positional.size() == 2) {
        audio = positional[0];
        transcript = positional[1];
    } else if (!positional.empty()) {
        usage("give both AUDIO and TRANSCRIPT, or neither");
    }
    const talkface::FaceModel face = talkface::FaceModel::default_face();
    const talkface::Timeline timeline = talkface::SpeechAligner().align_file(audio, talkface::load_transcript(transcript));
    const talkface::ExpressionSimulator simulator(timeline, 1);
    talkface::LipSyncOptions lip_sync;
    lip_sync.fps = fps;
    const talkface::Animation animation = talkface::animate(face, timeline, simulator, lip_sync);
    const std::size_t wanted = static_cast<std::size_t>(seconds * fps);
    std::printf("raster_bench: %zu frames of a %.1f s animation at %.0f fps, drawn until %zu frames (%.0f s), %dx%d, "
                "announcer layout, one thread\n\n",
                animation.frames.size(), animation.duration_s, fps, wanted, seconds, options.width_px, options.height_px);
    auto frame_at = [&](std::size_t k) -> const talkface::FaceState& { return animation.frames[k % animation.frames.size()]; };

    std::vector<std::uint8_t> rgba(static_cast<std::size_t>(options.width_px) * options.height_px * 4);
    talkface::FrameRenderer renderer(face, options);
    auto start = Clock::now();
    for (std::size_t k = 0; k < wanted; ++k) renderer.render_frame_rgba(frame_at(k), rgba.data(), renderer.stride_bytes());
    const double renderer_s = seconds_since(start);

    const Scene scene(face, options);
    cairo_surface_t* surface = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, options.width_px, options.height_px);
    const std::size_t whole_frames = std::min<std::size_t>(wanted, 600);
    start = Clock::now();
    for (std::size_t k = 0; k < whole_frames; ++k) draw_whole_cairo(scene, frame_at(k), surface);
    const double cairo_s = seconds_since(start);

    cv::Mat image(options.height_px, options.width_px, CV_8UC4);
    start = Clock::now();
    for (std::size_t k = 0; k < whole_frames; ++k) draw_whole_opencv(scene, frame_at(k), image);
    const double opencv_s = seconds_since(start);

    // Quality: a few frames spread over the animation, against rsvg-convert.
    double renderer_mean = 0, renderer_far = 0, opencv_mean = 0, opencv_far = 0;
    const int samples = 4;
    int compared = 0;
    talkface::FrameRenderer fresh(face, options);
    for (int s = 0; s < samples; ++s) {
        const talkface::FaceState& state = animation.frames[(s * 2 + 1) * animation.frames.size() / (2 * samples)];
        const std::vector<std::uint8_t> reference = reference_rgba(scene, state, s);
        if (reference.empty()) continue;
        ++compared;
        double mean = 0, far = 0;
        compare(fresh.render_frame_rgba(state), reference, mean, far);
        renderer_mean += mean;
        renderer_far += far;
        draw_whole_opencv(scene, state, image);
        std::vector<std::uint8_t> opencv_rgba(rgba.size());
        for (std::size_t i = 0; i < opencv_rgba.size(); i += 4) {
            opencv_rgba[i] = image.data[i + 2];
            opencv_rgba[i + 1] = image.data[i + 1];
            opencv_rgba[i + 2] = image.data[i];
            opencv_rgba[i + 3] = 255;
        }
        compare(opencv_rgba, reference, mean, far);
        opencv_mean += mean;
        opencv_far += far;
    }
    auto row = [&](const char* name, std::size_t frames, double s, double mean, double far) {
        const double per_second = static_cast<double>(frames) / s;
        std::printf("%-34s %8.1f %9.2f %8.1fx", name, per_second, 1000.0 / per_second, per_second / fps);
        if (compared > 0 && mean >= 0) {
            std::printf(" %10.3f %10.4f%%\n", mean / compared, 100.0 * far / compared);
        } else {
            std::printf(" %10s %11s\n", "-", "-");
        }
    };
    std::printf("%-34s %8s %9s %9s %10s %11s\n", "renderer", "frames/s", "ms/frame", "x real", "mean diff", "far pixels");
    row("FrameRenderer (cairo, cached)", wanted, renderer_s, renderer_mean, renderer_far);
    row("cairo, whole frames", whole_frames, cairo_s, -1, 0);
    row("OpenCV fillPoly LINE_AA, whole", whole_frames, opencv_s, opencv_mean, opencv_far);
    std::printf("\nmean diff: mean |difference| of R, G, B (0..255) against rsvg-convert's picture of the same\n"
                "state's SVG, over %d frames; far pixels: a channel off by more than 64. x real: frames drawn per\n"
                "second over the animation's %.0f frames per second.\n", compared, fps);
    cairo_surface_destroy(surface);
    return 0;
}

// The document around the Lottie layers: the composition (frame rate, frames, size), and each
// layer's transform from the face's image pixels onto the canvas, as the SVG's viewBox maps them
// (uniformly scaled, centred). Layers are listed top first, as Lottie paints them.
//
// As in the SVG keyframes encoding, the head's tilt is taken out first (head_tilt.hpp): the hair
// and face layers turn by the tilt's key frames about O, and are drawn turned back by it, so that
// what only the tilt moves holds still in its own numbers.
#include "render/lottie_animation.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

#include "common/json.hpp"
#include "common/number_format.hpp"
#include "render/animation_frame.hpp"
#include "render/head_tilt.hpp"
#include "render/lottie_layer_encoder.hpp"
#include "render/progress_report.hpp"
#include "talkface/errors.hpp"

namespace talkface::detail {

namespace {

// Drawing the frames is most of the work; encoding is the rest.
constexpr double kFramesShare = 0.8;
constexpr std::size_t kProgressEveryFrames = 50;
// The bodymovin schema version whose fields are written (lottie-web 5.7 and later read it).
constexpr const char* kLottieVersion = "5.7.4";
constexpr int kTransformDecimals = 4;
constexpr int kAngleDecimals = 3;  // as head_tilt.cpp writes the SVG's

}  // namespace

std::string render_lottie(const FaceModel& face, const SvgOptions& svg_options, const SvgCanvas& canvas,
                          const Animation& animation, const LottieOptions& options, const ProgressCallback& progress) {
    check_animation_input(animation, options.tolerance_px);
    const std::size_t frame_count = animation.frames.size();
    // A digit fewer than SvgOptions::decimals asks of an SVG coordinate (2: a tenth of a pixel, at
    // most 0.05 px off, where the SVG's keyframes round to 0.06 px): a sixth of the document less,
    // no visible change. Where the document enlarges the canvas, a digit comes back for every
    // tenfold, never more than SvgOptions::decimals.
    const CanvasBox& box = canvas.box;
    const double scale = std::min(canvas.width_px / box.width, canvas.height_px / box.height);
    const int decimals = std::clamp(svg_options.decimals - 1 + static_cast<int>(std::ceil(std::log10(std::max(scale, 1.0)))),
                                    0, svg_options.decimals);
    // Paint order (thesis 6.3.1): background, hair, clothes, face. The background and the clothes
    // hold still (the body does not turn with the head): each is drawn once.
    LottieLayerEncoder background("background", options.tolerance_px, decimals, 1);
    LottieLayerEncoder hair("hair", options.tolerance_px, decimals, frame_count);
    LottieLayerEncoder clothes("clothes", options.tolerance_px, decimals, 1);
    LottieLayerEncoder face_layer("face", options.tolerance_px, decimals, frame_count);
    background.add(draw_background_layer(canvas.box, svg_options.background));
    FacePaints paints;
    HeadTilt tilt;
    const FaceState* previous = nullptr;
    double previous_angle_deg = 0.0;
    for (std::size_t frame = 0; frame < frame_count; ++frame) {
        if (frame % kProgressEveryFrames == 0) {
            report_progress(progress, kFramesShare * static_cast<double>(frame) / static_cast<double>(frame_count),
                            "frames", frame);
        }
        const FaceState& state = animation.frames[frame];
        const double angle_deg = tilt.angle_deg.empty() ? 0.0 : tilt.angle_deg[frame];
        if (is_held_frame(state, angle_deg, previous, previous_angle_deg)) {
            hair.add_repeat();
            face_layer.add_repeat();
            continue;
        }
        previous = &state;
        const ProjectedFace projected = project_animation_frame(face, animation, frame);
        if (frame == 0) {
            const LayerStyle style{decimals, svg_options.stroke_width_in_d * projected.d, svg_options.look};
            paints = make_face_paints(projected, style);
            clothes.add(svg_options.draw_clothes ? draw_clothes_layer(projected, canvas.box, svg_options.clothes, style)
                                                 : Layer());
            tilt = plan_head_tilt_on_canvas(animation, projected.origin, canvas.box, options.tolerance_px);
        }
        previous_angle_deg = tilt.angle_deg[frame];
        paints.view = ViewMap(tilt.origin, previous_angle_deg, 1.0);
        hair.add(draw_hair_layer(projected, paints));
        face_layer.add(draw_face_layer(projected, paints));
    }
    report_progress(progress, kFramesShare, "encoding", frame_count);

    // The canvas box onto the document's size, as a viewBox with preserveAspectRatio's default
    // (xMidYMid meet) maps it.
    const double offset_x = 0.5 * (canvas.width_px - scale * box.width);
    const double offset_y = 0.5 * (canvas.height_px - scale * box.height);
    const std::string out_point = std::to_string(frame_count);
    const auto number = [](double value) { return format_fixed(value, kTransformDecimals); };
    const std::string scale_text = "\"s\":{\"a\":0,\"k\":[" + number(100.0 * scale) + "," + number(100.0 * scale) + ",100]}";
    const std::string opaque = "\"o\":{\"a\":0,\"k\":100}";
    // The body's layers: image pixels, the canvas's corner at the document's.
    const std::string body_transform = "{" + opaque + ",\"r\":{\"a\":0,\"k\":0},\"p\":{\"a\":0,\"k\":[" +
                                       number(offset_x) + "," + number(offset_y) + ",0]},\"a\":{\"a\":0,\"k\":[" +
                                       number(box.x) + "," + number(box.y) + ",0]}," + scale_text + "}";
    // The head's: drawn about O turned back by the tilt, turned by it here (Lottie's rotation, as
    // SVG's, is clockwise on the screen for a positive angle).
    const std::string rotation = lottie_scalar_property(tilt.keys, tilt.held_angle_deg, kAngleDecimals);
    const std::string head_transform = "{" + opaque + ",\"r\":" + rotation + ",\"p\":{\"a\":0,\"k\":[" +
                                       number(offset_x + scale * (tilt.origin.x - box.x)) + "," +
                                       number(offset_y + scale * (tilt.origin.y - box.y)) +
                                       ",0]},\"a\":{\"a\":0,\"k\":[0,0,0]}," + scale_text + "}";

    struct Placed {
        LottieLayerContent content;
        const std::string* transform;
    };
    std::vector<Placed> contents;  // bottom first
    for (const auto& [encoder, transform] :
         {std::pair{&background, &body_transform}, std::pair{&hair, &head_transform},
          std::pair{&clothes, &body_transform}, std::pair{&face_layer, &head_transform}}) {
        for (LottieLayerContent& content : encoder->finish()) contents.push_back({std::move(content), transform});
    }
    report_progress(progress, 0.95, "encoding", frame_count);
    std::string json = "{\"v\":\"" + std::string(kLottieVersion) + "\",\"fr\":" + format_shortest(animation.fps) +
                       ",\"ip\":0,\"op\":" + out_point + ",\"w\":" + std::to_string(canvas.width_px) +
                       ",\"h\":" + std::to_string(canvas.height_px) +
                       ",\"nm\":\"talkface\",\"ddd\":0,\"assets\":[],\"layers\":[";
    for (std::size_t k = 0; k < contents.size(); ++k) {
        const LottieLayerContent& content = contents[contents.size() - 1 - k].content;
        if (k > 0) json += ",\n";
        json += "{\"ddd\":0,\"ind\":" + std::to_string(k + 1) + ",\"ty\":4,\"nm\":" + json_quoted(content.name) +
                ",\"sr\":1,\"ks\":" + *contents[contents.size() - 1 - k].transform + ",\"ao\":0,";
        if (!content.masks.empty()) json += "\"hasMask\":true,\"masksProperties\":" + content.masks + ",";
        json += "\"shapes\":" + content.shapes + ",\"ip\":0,\"op\":" + out_point + ",\"st\":0,\"bm\":0}";
    }
    json += "],\"markers\":[]}\n";
    report_progress(progress, 1.0, "encoding", frame_count);
    return json;
}

}  // namespace talkface::detail

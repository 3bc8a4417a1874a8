// The temporal half of thesis 6.3.2: every frame of an Animation drawn as by the spatial half (the
// drawing model, layers.hpp), then written either as one group per frame (the thesis's <set>
// frames, frames_encoder.hpp) or as one face whose moving attributes are SMIL <animate> elements
// over key frames chosen per attribute (keyframes_encoder.hpp).
//
// The key frames come from the drawn frames themselves, not from the mouth key frames and events:
// whatever moves (lips, jaw, lids, eyeballs, the whole head) gets exactly the key frames it needs
// for linear interpolation to stay within the tolerance of every frame, and whatever holds still
// gets none. The head's tilt is taken out first: one rotate of the head's groups (head_tilt.hpp),
// the layers drawn in the groups' frame.
#include "render/svg_animation.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "common/internal_error.hpp"
#include "common/number_format.hpp"
#include "render/animation_frame.hpp"
#include "render/frames_encoder.hpp"
#include "render/head_tilt.hpp"
#include "render/keyframes_encoder.hpp"
#include "render/path_compaction.hpp"
#include "render/progress_report.hpp"
#include "render/svg_text.hpp"
#include "talkface/errors.hpp"

namespace talkface::detail {

namespace {

// Progress shares of the two stages: drawing the frames is most of the work.
constexpr double kFramesShare = 0.85;
constexpr std::size_t kProgressEveryFrames = 50;

void validate(const Animation& animation, const SvgAnimationOptions& options) {
    check_animation_input(animation, options.tolerance_px);
    const int encoding = static_cast<int>(options.encoding);
    if (encoding != static_cast<int>(AnimationEncoding::keyframes) &&
        encoding != static_cast<int>(AnimationEncoding::frames)) {
        throw InvalidArgument("encoding", "expected keyframes or frames, found " + std::to_string(encoding));
    }
}

}  // namespace

namespace {

// Where one animation's frames go: both frames encoders, or both keyframes encoders.
struct HeadEncoders {
    FramesEncoder* hair_frames = nullptr;
    FramesEncoder* face_frames = nullptr;
    KeyframesEncoder* hair_keyframes = nullptr;
    KeyframesEncoder* face_keyframes = nullptr;
};

// What drawing the frames leaves besides the encoders' content.
struct DrawnHead {
    HeadTilt tilt;
    std::string clothes_layer;
};

// Draws every frame of `animation` into `encoders`, reporting progress from `from` to `to`.
DrawnHead draw_frames(const FaceModel& face, const SvgOptions& svg_options, const SvgCanvas& canvas,
                      const Animation& animation, const SvgAnimationOptions& options,
                      const HeadEncoders& encoders, const ProgressCallback& progress, double from,
                      double to) {
    const std::size_t frame_count = animation.frames.size();
    const bool is_frames = encoders.hair_frames != nullptr;
    const int head_decimals = is_frames ? svg_options.decimals : std::max(0, svg_options.decimals - 1);
    DrawnHead drawn;
    Layer hair;
    Layer face_layer;
    std::vector<Point2> hair_points;
    // The paints of the face: its d, hence the stroke, is the same at every state.
    FacePaints paints;
    const FaceState* previous = nullptr;
    double previous_angle_deg = 0.0;
    for (std::size_t frame = 0; frame < frame_count; ++frame) {
        if (frame % kProgressEveryFrames == 0) {
            report_progress(
                progress, from + (to - from) * static_cast<double>(frame) / static_cast<double>(frame_count),
                "frames", frame);
        }
        const FaceState& state = animation.frames[frame];
        const double angle_deg = drawn.tilt.angle_deg.empty() ? 0.0 : drawn.tilt.angle_deg[frame];
        const bool is_repeat = is_held_frame(state, angle_deg, previous, previous_angle_deg);
        // The hair holds still whenever its points do (the mouth and the eyes move without it).
        bool is_hair_repeat = is_repeat;
        if (!is_repeat) {
            previous = &state;
            const ProjectedFace projected = project_animation_frame(face, animation, frame);
            if (frame == 0) {
                const LayerStyle style{svg_options.decimals, svg_options.stroke_width_in_d * projected.d, svg_options.look};
                if (is_frames) {
                    paints = make_face_paints(projected, style);
                } else {
                    paints = make_face_paints(projected, LayerStyle{head_decimals, style.stroke_px * kUnitsPerPx, style.look});
                    drawn.tilt = plan_head_tilt_on_canvas(animation, projected.origin, canvas.box,
                                                          options.tolerance_px);
                }
                drawn.clothes_layer = layer_group_svg(
                    "clothes",
                    svg_options.draw_clothes
                        ? draw_clothes_layer(projected, canvas.box, svg_options.clothes, style)
                        : Layer(),
                    svg_options.decimals);
            }
            if (!is_frames) {
                previous_angle_deg = drawn.tilt.angle_deg[frame];
                paints.view = ViewMap(drawn.tilt.origin, previous_angle_deg, kUnitsPerPx);
            }
            std::vector<Point2> new_hair_points = hair_layer_points(projected, paints);
            is_hair_repeat = frame > 0 && new_hair_points == hair_points;
            if (!is_hair_repeat) {
                hair_points = std::move(new_hair_points);
                hair = draw_hair_layer(projected, paints);
            }
            face_layer = draw_face_layer(projected, paints);
        }
        if (is_frames) {
            encoders.hair_frames->add(hair);
            encoders.face_frames->add(face_layer);
            continue;
        }
        if (is_hair_repeat) {
            encoders.hair_keyframes->add_repeat();
        } else {
            encoders.hair_keyframes->add(hair);
        }
        if (is_repeat) {
            encoders.face_keyframes->add_repeat();
        } else {
            encoders.face_keyframes->add(face_layer);
        }
    }
    return drawn;
}

// Where the hair's encoding ends and the face's begins in the progress of writing a document.
constexpr double kHairDone = kFramesShare + 0.3 * (1.0 - kFramesShare);

}  // namespace

std::string render_animation(const FaceModel& face, const SvgOptions& svg_options, const SvgCanvas& canvas,
                             const Animation& animation, const SvgAnimationOptions& options,
                             const ProgressCallback& progress) {
    validate(animation, options);
    const std::size_t frame_count = animation.frames.size();
    // The hair and face layers of every frame; the clothes hang from O and d, which no state moves
    // (the body does not turn with the head), so they are drawn once, between the two as in
    // render_svg() (thesis 6.3.1: background, hair, clothes, face).
    std::size_t group_counter = 0;
    const bool is_frames = options.encoding == AnimationEncoding::frames;
    // A decimal less in tenths of a pixel is the same precision.
    const int head_decimals = is_frames ? svg_options.decimals : std::max(0, svg_options.decimals - 1);
    FramesEncoder hair_frames("hair", animation.fps, head_decimals, group_counter);
    FramesEncoder face_frames("face", animation.fps, head_decimals, group_counter);
    const std::size_t expected_frames = is_frames ? 0 : frame_count;
    KeyframesEncoder hair_keyframes(animation.fps, options.tolerance_px * kUnitsPerPx, head_decimals,
                                    expected_frames);
    KeyframesEncoder face_keyframes(animation.fps, options.tolerance_px * kUnitsPerPx, head_decimals,
                                    expected_frames);
    const HeadEncoders encoders = is_frames
                                      ? HeadEncoders{&hair_frames, &face_frames, nullptr, nullptr}
                                      : HeadEncoders{nullptr, nullptr, &hair_keyframes, &face_keyframes};
    const DrawnHead drawn =
        draw_frames(face, svg_options, canvas, animation, options, encoders, progress, 0.0, kFramesShare);
    report_progress(progress, kFramesShare, "encoding", frame_count);

    std::string svg = kXmlDeclaration;
    svg += open_svg_root(canvas, svg_options.decimals, "tf-animation");
    svg += background_layer_svg(canvas, svg_options.background, svg_options.decimals);
    if (is_frames) {
        svg += hair_frames.finish() + drawn.clothes_layer + face_frames.finish();
    } else {
        svg += open_head_group(drawn.tilt, "hair") +
               hair_keyframes.finish(progress, kFramesShare, kHairDone) + "</g>\n" + drawn.clothes_layer +
               open_head_group(drawn.tilt, "face") + face_keyframes.finish(progress, kHairDone, 1.0) +
               "</g>\n";
    }
    svg += "</svg>\n";
    report_progress(progress, 1.0, "encoding", frame_count);
    return svg;
}

std::string render_animation_with_pose_apart(const FaceModel& face, const SvgOptions& svg_options,
                                             const SvgCanvas& canvas, const Animation& animation,
                                             const SvgAnimationOptions& options,
                                             const ProgressCallback& progress) {
    validate(animation, options);
    if (options.encoding != AnimationEncoding::keyframes)
        throw internal_error("the pose is carried apart in the keyframes encoding only");
    Animation at_rest = animation;
    for (FaceState& frame : at_rest.frames) frame.pose = Pose{};
    const std::size_t frame_count = animation.frames.size();
    const int head_decimals = std::max(0, svg_options.decimals - 1);
    const double tolerance = options.tolerance_px * kUnitsPerPx;
    KeyframesEncoder hair(animation.fps, tolerance, head_decimals, frame_count);
    KeyframesEncoder face_layer(animation.fps, tolerance, head_decimals, frame_count);
    KeyframesEncoder posed_hair(animation.fps, tolerance, head_decimals, frame_count);
    KeyframesEncoder posed_face(animation.fps, tolerance, head_decimals, frame_count);
    const double half = kFramesShare / 2.0;
    const DrawnHead rest =
        draw_frames(face, svg_options, canvas, at_rest, options,
                    HeadEncoders{nullptr, nullptr, &hair, &face_layer}, progress, 0.0, half);
    const DrawnHead posed =
        draw_frames(face, svg_options, canvas, animation, options,
                    HeadEncoders{nullptr, nullptr, &posed_hair, &posed_face}, progress, half, kFramesShare);
    if (posed.tilt.origin.x != rest.tilt.origin.x || posed.tilt.origin.y != rest.tilt.origin.y ||
        posed.clothes_layer != rest.clothes_layer) {
        throw internal_error(
            "the posed head turns about another point or wears other clothes than the head at rest");
    }
    report_progress(progress, kFramesShare, "encoding", frame_count);
    // The tilt turns the head's groups: an additive rotate as the pose's other animations are.
    std::string tilt;
    if (!posed.tilt.animation.empty()) {
        tilt = posed.tilt.animation;
        tilt.insert(std::string("<animateTransform").size(), " class=\"tf-pose\"");
    } else if (posed.tilt.held_angle_deg != 0.0) {
        tilt =
            "<animateTransform class=\"tf-pose\" attributeName=\"transform\" type=\"rotate\" "
            "additive=\"sum\"" +
            attribute("dur", clock_value(static_cast<double>(frame_count - 1) / animation.fps)) +
            attribute("values", format_shortest(posed.tilt.held_angle_deg)) + " fill=\"freeze\"/>\n";
    }
    std::string svg = kXmlDeclaration;
    svg += open_svg_root(canvas, svg_options.decimals, "tf-animation");
    svg += background_layer_svg(canvas, svg_options.background, svg_options.decimals);
    svg += open_head_group(rest.tilt, "hair") + tilt +
           hair.finish_with_pose(posed_hair, progress, kFramesShare, kHairDone) + "</g>\n" +
           rest.clothes_layer + open_head_group(rest.tilt, "face") + tilt +
           face_layer.finish_with_pose(posed_face, progress, kHairDone, 1.0) + "</g>\n";
    svg += "</svg>\n";
    report_progress(progress, 1.0, "encoding", frame_count);
    return svg;
}

}  // namespace talkface::detail

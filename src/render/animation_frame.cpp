#include "render/animation_frame.hpp"

#include <cmath>
#include <exception>
#include <string>

#include "common/number_format.hpp"
#include "talkface/errors.hpp"

namespace talkface::detail {

void check_animation_input(const Animation& animation, double tolerance_px) {
    if (animation.frames.empty()) throw InvalidArgument("animation", "has no frames");
    if (!std::isfinite(animation.fps) || animation.fps <= 0.0) {
        throw InvalidArgument("animation.fps", "expected a finite number > 0, found " + format_shortest(animation.fps));
    }
    if (!std::isfinite(tolerance_px) || tolerance_px <= 0.0) {
        throw InvalidArgument("tolerance_px", "expected a finite number > 0, found " + format_shortest(tolerance_px));
    }
}

ProjectedFace project_animation_frame(const FaceModel& face, const Animation& animation, std::size_t frame) {
    try {
        return project_face(face, animation.frames[frame]);
    } catch (const Error&) {
        std::throw_with_nested(InvalidArgument(
            "animation.frames[" + std::to_string(frame) + "]",
            "the face cannot be drawn at " + format_fixed(static_cast<double>(frame) / animation.fps, 3) + " s"));
    }
}

bool is_held_frame(const FaceState& state, double angle_deg, const FaceState* previous, double previous_angle_deg) {
    return previous != nullptr && state.pose == previous->pose && state.expression == previous->expression &&
           state.mouth == previous->mouth && angle_deg == previous_angle_deg;
}

}  // namespace talkface::detail

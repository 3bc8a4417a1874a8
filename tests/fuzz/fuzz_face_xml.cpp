// Any bytes as a face file: either talkface::Error, or a face that can be posed and drawn.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "talkface/errors.hpp"
#include "talkface/face_model.hpp"
#include "talkface/face_pose.hpp"
#include "talkface/svg_animator.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    talkface::FaceModel face;
    try {
        face = talkface::FaceModel::from_xml(std::string_view(reinterpret_cast<const char*>(data), size), "fuzz.xml");
    } catch (const talkface::Error&) {
        return 0;
    }
    // A face the loader accepts must be one every later stage accepts, at any pose.
    talkface::FaceState state;
    state.pose = {10.0, -15.0, 5.0};
    state.expression.blink_left = 1.0;
    (void)talkface::project_face(face, state);
    (void)talkface::SvgAnimator(face).render_svg(state);
    return 0;
}

#include "raster/frame_layout.hpp"

#include <algorithm>

#include "talkface/face_pose.hpp"

namespace talkface::detail {

FramePlacement place_face(const FaceModel& face, const CanvasBox& canvas, const FrameOptions& options) {
    const double width = options.width_px;
    const double height = options.height_px;
    FramePlacement placement;
    if (options.layout == FrameLayout::face) {
        placement.scale = std::min(width / canvas.width, height / canvas.height);
        placement.offset = {0.5 * (width - placement.scale * canvas.width) - placement.scale * canvas.x,
                            0.5 * (height - placement.scale * canvas.height) - placement.scale * canvas.y};
    } else {
        // Thesis 7.2.3: the face is moved by its rotation origin O and scaled by its eye distance d.
        const ProjectedFace neutral = project_face(face, FaceState{});
        const Point2 origin = neutral.origin;
        placement.scale = options.face_d_px > 0.0 ? options.face_d_px / neutral.d : height / canvas.height;
        const Point2 stage_origin = options.face_origin_px.value_or(
            Point2{0.5 * width, height - (canvas.y + canvas.height - origin.y) * placement.scale});
        placement.offset = {stage_origin.x - placement.scale * origin.x, stage_origin.y - placement.scale * origin.y};
    }
    const Point2 corner = placement.apply({canvas.x, canvas.y});
    placement.canvas_in_frame = {corner.x, corner.y, placement.scale * canvas.width, placement.scale * canvas.height};
    return placement;
}

}  // namespace talkface::detail

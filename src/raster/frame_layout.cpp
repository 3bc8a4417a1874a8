#include "raster/frame_layout.hpp"

#include <algorithm>

#include "render/announcer_layout.hpp"
#include "render/face_canvas.hpp"
#include "talkface/face_pose.hpp"
#include "talkface/web_page.hpp"

namespace talkface::detail {

namespace {

AnnouncerFacePlacement announcer_placement(const FaceModel& face, const CanvasBox& canvas,
                                           const std::vector<FaceState>& frames, const FrameOptions& options) {
    WebPageOptions stage;
    stage.stage_width_px = options.width_px;
    stage.stage_height_px = options.height_px;
    stage.face_d_px = options.face_d_px;
    stage.face_origin_px = options.face_origin_px;
    return announcer_face_placement(face, {canvas.x, canvas.y, canvas.width, canvas.height}, frames, stage);
}

}  // namespace

FramePlacement place_face(const FaceModel& face, const CanvasBox& canvas, const FrameOptions& options) {
    const double width = options.width_px;
    const double height = options.height_px;
    FramePlacement placement;
    if (options.layout == FrameLayout::face) {
        placement.scale = std::min(width / canvas.width, height / canvas.height);
        placement.offset = {0.5 * (width - placement.scale * canvas.width) - placement.scale * canvas.x,
                            0.5 * (height - placement.scale * canvas.height) - placement.scale * canvas.y};
    } else {
        const AnnouncerFacePlacement announcer = announcer_placement(face, canvas, {}, options);
        placement.scale = announcer.scale;
        placement.offset = announcer.to_stage({0.0, 0.0});
    }
    const Point2 corner = placement.apply({canvas.x, canvas.y});
    placement.canvas_in_frame = {corner.x, corner.y, placement.scale * canvas.width, placement.scale * canvas.height};
    return placement;
}

FrameOptions with_announcer_placement(const FaceModel& face, const std::vector<FaceState>& frames,
                                      FrameOptions options) {
    if (options.layout != FrameLayout::announcer || options.face_d_px > 0.0 || options.face_origin_px) return options;
    const AnnouncerFacePlacement announcer = announcer_placement(face, fit_face_canvas(face), frames, options);
    options.face_d_px = announcer.scale * project_face(face, FaceState{}).d;
    options.face_origin_px = announcer.stage_origin;
    return options;
}

}  // namespace talkface::detail

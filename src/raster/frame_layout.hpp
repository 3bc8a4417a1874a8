// Where the face's image pixels fall in a frame (FrameLayout): a scale and an offset.
#ifndef TALKFACE_RASTER_FRAME_LAYOUT_HPP
#define TALKFACE_RASTER_FRAME_LAYOUT_HPP

#include <vector>

#include "render/layers.hpp"
#include "talkface/face_model.hpp"
#include "talkface/frame_renderer.hpp"

namespace talkface::detail {

// frame = offset + scale * image, the same for x and y.
struct FramePlacement {
    double scale = 1.0;
    Point2 offset{0.0, 0.0};
    CanvasBox canvas_in_frame;  // the face's canvas, placed: the SVG document's viewport
    Point2 apply(Point2 image_xy) const { return {offset.x + scale * image_xy.x, offset.y + scale * image_xy.y}; }
};

// The placement of `face`, whose canvas is `canvas` (face_canvas.hpp), by `options`. announcer: as
// the announcer web page places it on a stage of the frame's size (render/announcer_layout.hpp),
// for the face at rest; face: the canvas fitted into the frame and centred, as an SVG viewer shows a
// document (preserveAspectRatio's default).
FramePlacement place_face(const FaceModel& face, const CanvasBox& canvas, const FrameOptions& options);

// `options` with the announcer's placement made explicit (face_d_px, face_origin_px) as the page
// places the face for an animation of `frames`: its mouth, as open as it gets in them, clear of the
// page's lower third. Unchanged for the face layout or a placement given already.
FrameOptions with_announcer_placement(const FaceModel& face, const std::vector<FaceState>& frames,
                                      FrameOptions options);

}  // namespace talkface::detail

#endif

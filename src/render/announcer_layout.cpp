// The announcer's stage layout: the face placed as thesis 7.2.3 places it, and a lower third that
// never hides the mouth, so that a deaf viewer can both read the caption and see the lips.
#include "render/announcer_layout.hpp"

#include <algorithm>
#include <limits>
#include <string>
#include <vector>

#include "common/number_format.hpp"
#include "talkface/errors.hpp"
#include "talkface/face_pose.hpp"

namespace talkface::detail {

namespace {

// The caption band: a title line over two lines of caption, as news frames have it.
constexpr double kCaptionHeightShare = 0.22;
// Kept free between the band and the stage's edge, and between the band and the mouth.
constexpr double kEdgeShare = 0.04;
constexpr double kMouthClearanceShare = 0.02;

// The mouth's extent in the face's image pixels over the frames that will be shown: the outer lip
// points of every frame, projected as the renderer projects them.
StageBox mouth_extent(const FaceModel& face, const std::vector<FaceState>& frames) {
    double left = std::numeric_limits<double>::max(), top = left;
    double right = std::numeric_limits<double>::lowest(), bottom = right;
    const std::vector<FaceState> rest_only{FaceState{}};
    for (const FaceState& state : frames.empty() ? rest_only : frames) {
        const ProjectedFace projected = project_face(face, state);
        for (const char* id : {"8.1", "8.2", "8.3", "8.4", "8.9", "8.10"}) {
            const Point2 p = projected.point(id);
            left = std::min(left, p.x);
            right = std::max(right, p.x);
            top = std::min(top, p.y);
            bottom = std::max(bottom, p.y);
        }
    }
    return {left, top, right - left, bottom - top};
}

// The placement, given the mouth's extent over every frame (in image pixels).
AnnouncerFacePlacement place_face(const FaceModel& face, const StageBox& canvas, const StageBox& mouth,
                                  const WebPageOptions& options) {
    const double stage_width = options.stage_width_px;
    const double stage_height = options.stage_height_px;
    const ProjectedFace neutral = project_face(face, FaceState{});
    const double clearance = kMouthClearanceShare * stage_height;
    const double low_top = stage_height - kEdgeShare * stage_height - kCaptionHeightShare * stage_height;

    // Unset: the face as tall as the stage, its canvas standing on the stage's bottom edge, and
    // larger, if need be, until its mouth clears the lower third (the canvas's margin above the
    // hair is cut first), so that the caption lies over the chest as in a news frame.
    const double canvas_bottom = canvas.y + canvas.height;
    AnnouncerFacePlacement placement;
    placement.image_origin = neutral.origin;
    placement.scale = options.face_d_px > 0.0 ? options.face_d_px / neutral.d : stage_height / canvas.height;
    if (options.face_d_px <= 0.0 && !options.face_origin_px && mouth.y + mouth.height < canvas_bottom) {
        placement.scale =
            std::max(placement.scale, (stage_height - low_top + clearance) / (canvas_bottom - mouth.y - mouth.height));
    }
    placement.stage_origin = options.face_origin_px.value_or(
        Point2{0.5 * stage_width, stage_height - (canvas_bottom - neutral.origin.y) * placement.scale});
    return placement;
}

}  // namespace

AnnouncerFacePlacement announcer_face_placement(const FaceModel& face, const StageBox& canvas,
                                                const std::vector<FaceState>& frames, const WebPageOptions& options) {
    return place_face(face, canvas, mouth_extent(face, frames), options);
}

AnnouncerLayout announcer_layout(const FaceModel& face, const StageBox& canvas, const std::vector<FaceState>& frames,
                                 const WebPageOptions& options) {
    const double stage_width = options.stage_width_px;
    const double stage_height = options.stage_height_px;
    const double band_height = kCaptionHeightShare * stage_height;
    const double edge = kEdgeShare * stage_height;
    const double clearance = kMouthClearanceShare * stage_height;
    const double low_top = stage_height - edge - band_height;
    const StageBox mouth = mouth_extent(face, frames);
    const AnnouncerFacePlacement placement = place_face(face, canvas, mouth, options);
    const double scale = placement.scale;

    AnnouncerLayout layout;
    const Point2 canvas_corner = placement.to_stage({canvas.x, canvas.y});
    layout.face = {canvas_corner.x, canvas_corner.y, canvas.width * scale, canvas.height * scale};
    const Point2 mouth_corner = placement.to_stage({mouth.x, mouth.y});
    layout.mouth = {mouth_corner.x, mouth_corner.y, mouth.width * scale, mouth.height * scale};

    const double band_x = kEdgeShare * stage_width;
    const double band_width = stage_width - 2.0 * band_x;
    // A mouth off the stage's sides or outside the band's height does not meet the band.
    const bool mouth_beside_band = layout.mouth.x >= band_x + band_width || layout.mouth.x + layout.mouth.width <= band_x;
    if (mouth_beside_band || layout.mouth.bottom() + clearance <= low_top || layout.mouth.y >= stage_height) {
        layout.caption = {band_x, low_top, band_width, band_height};
    } else if (layout.mouth.y - clearance >= edge + band_height || layout.mouth.bottom() <= 0.0) {
        layout.caption = {band_x, edge, band_width, band_height};
        layout.is_caption_on_top = true;
    } else {
        throw InvalidArgument("face_origin_px",
                              "the face's mouth (stage y " + format_fixed(layout.mouth.y, 1) + " to " +
                                  format_fixed(layout.mouth.bottom(), 1) + " px) leaves no band of " +
                                  format_fixed(band_height, 1) + " px above or below it for the caption on a stage " +
                                  std::to_string(options.stage_height_px) +
                                  " px high; place the face lower or higher, or make it smaller (face_d_px)");
    }
    return layout;
}

}  // namespace talkface::detail

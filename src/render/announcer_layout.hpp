// Where the virtual announcer's pieces stand on the stage (thesis 7.2): the face, placed by its
// rotation origin and eye distance, and the news frame's lower third (the title and the caption of
// the sentence being spoken), kept clear of the mouth in every frame. The page
// (apps/announcer_page.cpp) draws it; it lives here, below raster/ and video/, so that a video of
// the announcer can draw the same numbers.
#ifndef TALKFACE_RENDER_ANNOUNCER_LAYOUT_HPP
#define TALKFACE_RENDER_ANNOUNCER_LAYOUT_HPP

#include <vector>

#include "talkface/face_model.hpp"
#include "talkface/face_pose.hpp"
#include "talkface/web_page.hpp"

namespace talkface::detail {

// A rectangle in stage pixels.
struct StageBox {
    double x = 0.0;
    double y = 0.0;
    double width = 0.0;
    double height = 0.0;
    double bottom() const { return y + height; }
};

struct AnnouncerLayout {
    StageBox face;     // where the face's animation canvas is drawn
    StageBox mouth;    // the most the mouth covers, over every frame
    StageBox caption;  // the lower third: the title over the caption of the spoken sentence
    bool is_caption_on_top = false;  // true when the face stands so low that the caption goes above it
};

// Where the face stands: image pixels p go to stage_origin + scale * (p - image_origin), O being
// the face's rotation origin.
struct AnnouncerFacePlacement {
    double scale = 1.0;
    Point2 image_origin{0.0, 0.0};
    Point2 stage_origin{0.0, 0.0};
    Point2 to_stage(Point2 image_xy) const {
        return {stage_origin.x + (image_xy.x - image_origin.x) * scale, stage_origin.y + (image_xy.y - image_origin.y) * scale};
    }
};

// The face's placement alone, as announcer_layout() places it (a video of the announcer, which has
// no caption, stands the face where the page does).
AnnouncerFacePlacement announcer_face_placement(const FaceModel& face, const StageBox& canvas,
                                                const std::vector<FaceState>& frames, const WebPageOptions& options);

// `canvas` is the face's animation canvas (its viewBox, in the face's image pixels), `frames` the
// states the animation shows (empty: the neutral face); the caption keeps clear of the mouth in
// every one of them.
// \throws talkface::InvalidArgument naming face_origin_px when the face leaves no band of the
// stage, above or below the mouth, high enough for the caption.
AnnouncerLayout announcer_layout(const FaceModel& face, const StageBox& canvas, const std::vector<FaceState>& frames,
                                 const WebPageOptions& options);

}  // namespace talkface::detail

#endif

// The announcer in a frame stands where the announcer page stands it: one placement
// (render/announcer_layout.hpp), not a copy of its arithmetic.
#include <doctest/doctest.h>

#include <vector>

#include "pose/test_faces.hpp"
#include "raster/frame_layout.hpp"
#include "render/announcer_layout.hpp"
#include "render/face_canvas.hpp"
#include "render/face_grid.hpp"
#include "talkface/face_pose.hpp"

using namespace talkface;

namespace {

void check_same_box(const detail::CanvasBox& frame_box, const detail::StageBox& page_box) {
    CHECK(frame_box.x == doctest::Approx(page_box.x).epsilon(1e-9));
    CHECK(frame_box.y == doctest::Approx(page_box.y).epsilon(1e-9));
    CHECK(frame_box.width == doctest::Approx(page_box.width).epsilon(1e-9));
    CHECK(frame_box.height == doctest::Approx(page_box.height).epsilon(1e-9));
}

}  // namespace

TEST_CASE("the announcer's frame places the face's canvas where the page's stage does") {
    int enlarged = 0;
    for (const auto& [name, face] : test::test_faces()) {
        CAPTURE(name);
        const detail::CanvasBox canvas = detail::fit_face_canvas(face);
        const detail::StageBox stage_canvas{canvas.x, canvas.y, canvas.width, canvas.height};
        for (const auto& [width, height] : {std::pair{1280, 720}, std::pair{720, 1280}, std::pair{800, 450}}) {
            CAPTURE(width);
            WebPageOptions page;
            page.stage_width_px = width;
            page.stage_height_px = height;
            FrameOptions frame;
            frame.width_px = width;
            frame.height_px = height;
            // At rest, as FrameRenderer places the face on its own.
            check_same_box(detail::place_face(face, canvas, frame).canvas_in_frame,
                           detail::announcer_layout(face, stage_canvas, {}, page).face);
            // Talking, as render_video places it for an animation's frames: larger where the page
            // makes the face larger to keep the open mouth clear of the caption.
            const std::vector<FaceState> frames = test::talking_frames(face);
            const detail::AnnouncerLayout layout = detail::announcer_layout(face, stage_canvas, frames, page);
            const FrameOptions placed = detail::with_announcer_placement(face, frames, frame);
            check_same_box(detail::place_face(face, canvas, placed).canvas_in_frame, layout.face);
            if (layout.face.height > height * 1.0001) ++enlarged;
            // A placement given is kept.
            frame.face_d_px = 40.0;
            frame.face_origin_px = Point2{100.0, 200.0};
            page.face_d_px = 40.0;
            page.face_origin_px = Point2{100.0, 200.0};
            const FrameOptions given = detail::with_announcer_placement(face, frames, frame);
            CHECK(given.face_d_px == 40.0);
            check_same_box(detail::place_face(face, canvas, given).canvas_in_frame,
                           detail::announcer_layout(face, stage_canvas, {}, page).face);
        }
    }
    // The talking frames make some face larger than the stage, so the test tells a copy that
    // leaves that out from the shared placement.
    CHECK(enlarged > 0);
}

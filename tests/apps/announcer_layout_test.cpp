#include <doctest/doctest.h>

#include <cmath>
#include <cstdlib>
#include <string>
#include <vector>

#include "render/announcer_layout.hpp"
#include "pose/test_faces.hpp"
#include "render/face_grid.hpp"
#include "talkface/errors.hpp"
#include "talkface/face_pose.hpp"
#include "talkface/svg_animator.hpp"

using namespace talkface;
using detail::AnnouncerLayout;
using detail::StageBox;

namespace {

bool overlap(const StageBox& a, const StageBox& b) {
    return a.x < b.x + b.width && b.x < a.x + a.width && a.y < b.bottom() && b.y < a.bottom();
}

// The face's canvas as the animation draws it: the viewBox of its SVG.
StageBox canvas_of(const FaceModel& face) {
    const std::string svg = SvgAnimator(face).render_svg(FaceState{});
    const std::size_t start = svg.find("viewBox=\"") + 9;
    StageBox box;
    char* end = nullptr;
    box.x = std::strtod(svg.c_str() + start, &end);
    box.y = std::strtod(end, &end);
    box.width = std::strtod(end, &end);
    box.height = std::strtod(end, &end);
    return box;
}

}  // namespace

TEST_SUITE("announcer layout") {
    TEST_CASE("the mouth box holds the mouth of every frame, at every pose and shape") {
        for (const auto& [name, face] : test::test_faces()) {
            CAPTURE(name);
            WebPageOptions options;
            const StageBox canvas = canvas_of(face);
            const std::vector<FaceState> frames = test::talking_frames(face);
            const AnnouncerLayout layout = detail::announcer_layout(face, canvas, frames, options);
            const double scale = layout.face.width / canvas.width;
            for (const FaceState& state : frames) {
                const ProjectedFace projected = project_face(face, state);
                CAPTURE(state.pose.alpha_deg);
                CAPTURE(state.pose.beta_deg);
                CAPTURE(state.pose.gamma_deg);
                for (const std::string id : {"8.1", "8.2", "8.3", "8.4", "2.2", "2.3"}) {
                    CAPTURE(id);
                    const Point2 p = projected.point(id);
                    const double x = layout.face.x + (p.x - canvas.x) * scale;
                    const double y = layout.face.y + (p.y - canvas.y) * scale;
                    CHECK(x >= layout.mouth.x - 1e-6);
                    CHECK(x <= layout.mouth.x + layout.mouth.width + 1e-6);
                    CHECK(y >= layout.mouth.y - 1e-6);
                    CHECK(y <= layout.mouth.bottom() + 1e-6);
                }
            }
        }
    }

    TEST_CASE("the caption never covers the mouth, wherever the face stands, else the refusal names why") {
        const FaceModel face = FaceModel::default_face();
        const StageBox canvas = canvas_of(face);
        // The caption is checked against the layout's mouth box, which the case above shows holds the
        // mouth of every frame; the extreme poses give the box its size. (The whole pose grid here
        // made this case 2.7 minutes long under the sanitizers, for 228 placements.)
        std::vector<FaceState> frames;
        for (const FaceState& state : test::talking_frames(face)) {
            const Pose& pose = state.pose;
            if (std::abs(pose.alpha_deg) + std::abs(pose.beta_deg) + std::abs(pose.gamma_deg) == 0.0 ||
                (std::abs(pose.alpha_deg) == 15.0 && std::abs(pose.beta_deg) == 15.0 && std::abs(pose.gamma_deg) == 15.0))
                frames.push_back(state);
        }
        REQUIRE(frames.size() == 9 * all_mouth_shapes().size());
        int below = 0, above = 0, refused = 0;
        for (double d : {30.0, 60.0, 90.0, 200.0}) {
            for (double y = 0.0; y <= 450.0; y += 25.0) {
                for (double x : {100.0, 400.0, 700.0}) {
                    WebPageOptions options;
                    options.face_d_px = d;
                    options.face_origin_px = Point2{x, y};
                    CAPTURE(d);
                    CAPTURE(x);
                    CAPTURE(y);
                    try {
                        const AnnouncerLayout layout = detail::announcer_layout(face, canvas, frames, options);
                        CHECK_FALSE(overlap(layout.caption, layout.mouth));
                        CHECK(layout.caption.y >= 0.0);
                        CHECK(layout.caption.bottom() <= options.stage_height_px);
                        (layout.is_caption_on_top ? above : below) += 1;
                    } catch (const InvalidArgument& error) {
                        CHECK(std::string(error.what()).find("face_origin_px") != std::string::npos);
                        CHECK(std::string(error.what()).find("caption") != std::string::npos);
                        ++refused;
                    }
                }
            }
        }
        // Each way is taken somewhere on the grid.
        CHECK(below > 0);
        CHECK(above > 0);
        CHECK(refused > 0);
    }

    TEST_CASE("by default the face stands on the stage's bottom and the caption is below its talking mouth") {
        for (const auto& [name, face] : test::test_faces()) {
            CAPTURE(name);
            // The simulator's head moves: up to 5 degrees of nod and tilt, 8 of turn.
            std::vector<FaceState> frames;
            for (double alpha : {-5.0, 5.0}) {
                for (double beta : {-8.0, 8.0}) {
                    for (double gamma : {-5.0, 5.0}) {
                        for (MouthShape shape : all_mouth_shapes()) {
                            FaceState state;
                            state.pose = {alpha, beta, gamma};
                            state.mouth = mouth_controls(face, shape);
                            frames.push_back(state);
                        }
                    }
                }
            }
            const AnnouncerLayout layout = detail::announcer_layout(face, canvas_of(face), frames, WebPageOptions{});
            CHECK_FALSE(layout.is_caption_on_top);
            CHECK(layout.caption.y >= layout.mouth.bottom());
            // On the stage's bottom edge; larger than the stage's height only as far as the mouth
            // needs to clear the caption.
            CHECK(layout.face.bottom() == doctest::Approx(450.0));
            CHECK(layout.face.height >= 450.0);
            CHECK(layout.face.height < 1.1 * 450.0);
        }
    }
}

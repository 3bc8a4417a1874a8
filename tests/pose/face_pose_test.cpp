#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <map>
#include <string>
#include <vector>

#include "lift/lifted_point_index.hpp"
#include "lift/local_frame.hpp"
#include "pose/contour_sides.hpp"
#include "pose/test_faces.hpp"
#include "talkface/errors.hpp"
#include "talkface/face_lift.hpp"
#include "talkface/face_pose.hpp"
#include "talkface/mouth_shape.hpp"

using namespace talkface;
using talkface::detail::to_image;

namespace {

FaceState posed(double alpha_deg, double beta_deg, double gamma_deg) {
    FaceState state;
    state.pose = Pose{alpha_deg, beta_deg, gamma_deg};
    return state;
}

// The id of each point's mirror image on a face that is symmetric about a vertical axis.
std::map<std::string, std::string> mirror_partners() {
    const char* pairs[][2] = {{"3.2", "3.1"},     {"3.4", "3.3"},    {"3.8", "3.11"},
                              {"3.12", "3.7"},    {"4.2", "4.1"},    {"4.4", "4.3"},
                              {"4.4a", "4.3a"},   {"4.6", "4.5"},    {"10.2", "10.1"},
                              {"10.8", "10.7"},   {"10.10", "10.9"}, {"11.2", "11.3"},
                              {"11.2a", "11.3a"}, {"2.14", "2.13"},  {"8.9", "8.10"},
                              {"8.4", "8.3"},     {"9.6", "9.7"},    {"9.14", "9.13"},
                              {"9.2", "9.1"},     {"9.4", "9.5"},    {"EyeballLeft", "EyeballRight"},
                              {"A", "B"},         {"D", "E"},        {"F", "I"},
                              {"G", "H"},         {"J", "K"},        {"L", "M"},
                              {"N", "Q"},         {"R", "S"}};
    std::map<std::string, std::string> partner;
    for (const auto& pair : pairs) {
        partner[pair[0]] = pair[1];
        partner[pair[1]] = pair[0];
    }
    // src/face/default_face.cpp: hair.k mirrors hair.(24 - k), hair.12 is on the axis.
    for (int k = 1; k <= 23; ++k) partner["hair." + std::to_string(k)] = "hair." + std::to_string(24 - k);
    for (const char* on_axis : {"11.1", "2.1", "2.2", "2.3", "8.1", "8.2", "9.15", "C"})
        partner[on_axis] = on_axis;
    return partner;
}

double cross(Point2 o, Point2 a, Point2 b) {
    return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

bool on_segment(Point2 p, Point2 a, Point2 b) {
    return std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= p.y &&
           p.y <= std::max(a.y, b.y);
}

// Closed segments ab and cd share a point (touching counts).
bool segments_meet(Point2 a, Point2 b, Point2 c, Point2 d) {
    const double d1 = cross(c, d, a), d2 = cross(c, d, b), d3 = cross(a, b, c), d4 = cross(a, b, d);
    if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0))) return true;
    return (d1 == 0 && on_segment(a, c, d)) || (d2 == 0 && on_segment(b, c, d)) ||
           (d3 == 0 && on_segment(c, a, b)) || (d4 == 0 && on_segment(d, a, b));
}

// A polygon is simple when no two edges that are not neighbours meet.
bool is_simple(const std::vector<Point2>& polygon) {
    const std::size_t n = polygon.size();
    for (std::size_t i = 0; i < n; ++i) {
        for (std::size_t j = i + 2; j < n; ++j) {
            if (i == 0 && j == n - 1) continue;
            if (segments_meet(polygon[i], polygon[(i + 1) % n], polygon[j], polygon[(j + 1) % n]))
                return false;
        }
    }
    return true;
}

bool is_inside(Point2 p, const std::vector<Point2>& polygon) {
    bool inside = false;
    for (std::size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++) {
        const Point2 a = polygon[i], b = polygon[j];
        if ((a.y > p.y) != (b.y > p.y) && p.x < (b.x - a.x) * (p.y - a.y) / (b.y - a.y) + a.x)
            inside = !inside;
    }
    return inside;
}

// Where the eye's corners put its middle, and the pupil's offset from it, image x.
double pupil_offset_x(const ProjectedFace& face, const char* pupil, const char* corner_a,
                      const char* corner_b) {
    return face.point(pupil).x - (face.point(corner_a).x + face.point(corner_b).x) / 2.0;
}

}  // namespace

TEST_SUITE("face pose") {
    TEST_CASE("the zero pose is the frontal face, bit for bit") {
        for (const auto& [name, neutral] : test::test_faces()) {
            CAPTURE(name);
            FaceState state;
            SUBCASE("neutral") {}
            SUBCASE("with an expression and a mouth") {
                state.expression = Expression{0.3, 0.6, 0.5, 0.7};
                state.mouth = mouth_controls(neutral, MouthShape::o);
            }
            const ProjectedFace projected = project_face(neutral, state);
            const FaceModel face2d =
                apply_expression(apply_mouth(neutral, state.mouth.value_or(neutral_mouth_controls(neutral))),
                                 state.expression);
            CHECK(projected.face == face2d);
            REQUIRE(projected.points.size() == FaceModel::kPointCount + additional_point_ids().size());
            for (const std::string& id : FaceModel::point_ids()) {
                CAPTURE(id);
                CHECK(projected.point(id) == face2d.point(id));
            }
            const LiftedFace lifted = lift_face(face2d);
            for (const std::string& id : additional_point_ids()) {
                CAPTURE(id);
                CHECK(projected.point(id) == to_image(lifted.local(id), lifted.origin));
            }
            CHECK(projected.origin == rotation_origin(face2d));
            CHECK(projected.d == face2d.fapu("d"));
            CHECK(projected.left_contour == std::array<std::string, 3>{"11.2", "10.10", "2.14"});
            CHECK(projected.right_contour == std::array<std::string, 3>{"11.3", "10.9", "2.13"});
            CHECK(projected.nose_bridge == NoseBridgeSide::left);
        }
    }

    TEST_CASE("ids are the 72 model ids then A .. S, and an unknown id is refused") {
        const ProjectedFace projected = project_face(FaceModel::default_face(), posed(5, 10, -5));
        std::vector<std::string> want = FaceModel::point_ids();
        want.insert(want.end(), additional_point_ids().begin(), additional_point_ids().end());
        std::vector<std::string> ids;
        for (const ProjectedPoint& point : projected.points) ids.push_back(point.id);
        CHECK(ids == want);
        for (const ProjectedPoint& point : projected.points) CHECK(projected.point(point.id) == point.xy);
        CHECK_THROWS_WITH_AS(projected.point("8.5"), doctest::Contains("\"8.5\""), InvalidArgument);
        const std::vector<Point2> hair = projected.hair_polygon();
        REQUIRE(hair.size() == 23);
        CHECK(hair.front() == projected.point("hair.1"));
        CHECK(hair[11] == projected.point("hair.12"));
        CHECK(hair.back() == projected.point("hair.23"));
    }

    TEST_CASE("each angle moves the face on screen as documented") {
        const FaceModel neutral = FaceModel::default_face();
        const ProjectedFace frontal = project_face(neutral, {});
        for (double angle_deg : {5.0, 15.0}) {
            CAPTURE(angle_deg);
            // beta > 0: the nose tip goes to the image left (smaller image x).
            CHECK(project_face(neutral, posed(0, angle_deg, 0)).point("9.15").x < frontal.point("9.15").x);
            CHECK(project_face(neutral, posed(0, -angle_deg, 0)).point("9.15").x > frontal.point("9.15").x);
            // alpha > 0: a nod down, the nose tip drops (larger image y).
            CHECK(project_face(neutral, posed(angle_deg, 0, 0)).point("9.15").y > frontal.point("9.15").y);
            // gamma > 0: the top of the head goes to the image right.
            CHECK(project_face(neutral, posed(0, 0, angle_deg)).point("11.1").x > frontal.point("11.1").x);
            CHECK(project_face(neutral, posed(0, 0, -angle_deg)).point("11.1").x < frontal.point("11.1").x);
        }
    }

    TEST_CASE("a mirrored pose of the symmetric default face is the mirror image") {
        const FaceModel neutral = FaceModel::default_face();
        const auto partner = mirror_partners();
        const double axis_x = rotation_origin(neutral).x;
        test::for_each_grid_pose([&](double alpha_deg, double beta_deg, double gamma_deg) {
            const ProjectedFace face = project_face(neutral, posed(alpha_deg, beta_deg, gamma_deg));
            const ProjectedFace mirror =
                project_face(neutral, posed(alpha_deg, -beta_deg, -gamma_deg));
            for (const ProjectedPoint& point : face.points) {
                const std::string& id = point.id;
                CAPTURE(id);
                REQUIRE(partner.count(id) == 1);
                const Point2 p = face.point(id);
                const Point2 q = mirror.point(partner.at(id));
                CHECK(std::abs(p.x - (2.0 * axis_x - q.x)) <= 1e-9);
                CHECK(std::abs(p.y - q.y) <= 1e-9);
            }
            for (std::size_t k = 0; k < 3; ++k) {
                CHECK(face.left_contour[k] == partner.at(mirror.right_contour[k]));
            }
            if (beta_deg != 0.0) CHECK(face.nose_bridge != mirror.nose_bridge);
        });
    }

    TEST_CASE("the hair polygon stays simple at every pose of the grid") {
        for (const auto& [name, neutral] : test::test_faces()) {
            CAPTURE(name);
            REQUIRE(is_simple(project_face(neutral, {}).hair_polygon()));
            test::for_each_grid_pose([&](double alpha_deg, double beta_deg, double gamma_deg) {
                CHECK(is_simple(
                    project_face(neutral, posed(alpha_deg, beta_deg, gamma_deg)).hair_polygon()));
            });
        }
    }

    TEST_CASE("the forehead contour stays inside the hair at every pose of the grid") {
        // The hair depth shift's purpose (Algorithm 2.3 steps 1-2, thesis Figure 2.17): on the side the
        // face turns towards, the flat hair must not slide inside the face's outline.
        for (const auto& [name, neutral] : test::test_faces()) {
            CAPTURE(name);
            test::for_each_grid_pose([&](double alpha_deg, double beta_deg, double gamma_deg) {
                const ProjectedFace face =
                    project_face(neutral, posed(alpha_deg, beta_deg, gamma_deg));
                const std::vector<Point2> hair = face.hair_polygon();
                for (const std::string& id :
                     {face.left_contour[0], std::string("11.2a"), std::string("11.1"),
                      std::string("11.3a"), face.right_contour[0]}) {
                    CAPTURE(id);
                    CHECK(is_inside(face.point(id), hair));
                }
            });
        }
    }

    TEST_CASE("an angle outside +-15 degrees or not finite is refused and named") {
        const FaceModel neutral = FaceModel::default_face();
        const double nan = std::numeric_limits<double>::quiet_NaN();
        CHECK_THROWS_WITH_AS(project_face(neutral, posed(0, 15.0001, 0)), doctest::Contains("pose.beta_deg"),
                             InvalidArgument);
        CHECK_THROWS_WITH_AS(project_face(neutral, posed(0, 15.0001, 0)), doctest::Contains("15.0001"),
                             InvalidArgument);
        CHECK_THROWS_WITH_AS(project_face(neutral, posed(0, 15.0001, 0)), doctest::Contains("-15..15"),
                             InvalidArgument);
        CHECK_THROWS_WITH_AS(project_face(neutral, posed(-20, 0, 0)), doctest::Contains("pose.alpha_deg"),
                             InvalidArgument);
        CHECK_THROWS_WITH_AS(project_face(neutral, posed(-20, 0, 0)), doctest::Contains("-20"),
                             InvalidArgument);
        CHECK_THROWS_WITH_AS(project_face(neutral, posed(0, 0, nan)), doctest::Contains("pose.gamma_deg"),
                             InvalidArgument);
        CHECK_THROWS_WITH_AS(project_face(neutral, posed(0, -std::numeric_limits<double>::infinity(), 0)),
                             doctest::Contains("pose.beta_deg"), InvalidArgument);
        CHECK_NOTHROW(project_face(neutral, posed(-15, 15, -15)));
        FaceState bad_expression;
        bad_expression.expression.smile = 1.5;
        CHECK_THROWS_WITH_AS(project_face(neutral, bad_expression), doctest::Contains("expression.smile"),
                             InvalidArgument);
    }

    TEST_CASE("the contour is substituted exactly past +-10 degrees") {
        const FaceModel neutral = FaceModel::default_face();
        const std::array<std::string, 3> left{"11.2", "10.10", "2.14"};
        const std::array<std::string, 3> right{"11.3", "10.9", "2.13"};
        for (double beta_deg : {-10.0, -5.0, 0.0, 5.0, 10.0}) {
            CAPTURE(beta_deg);
            const ProjectedFace face = project_face(neutral, posed(0, beta_deg, 0));
            CHECK(face.left_contour == left);
            CHECK(face.right_contour == right);
        }
        for (double beta_deg : {10.000001, 12.0, 15.0}) {
            CAPTURE(beta_deg);
            const ProjectedFace face = project_face(neutral, posed(0, beta_deg, 0));
            CHECK(face.left_contour == std::array<std::string, 3>{"N", "L", "J"});
            CHECK(face.right_contour == right);
            const ProjectedFace other = project_face(neutral, posed(0, -beta_deg, 0));
            CHECK(other.left_contour == left);
            CHECK(other.right_contour == std::array<std::string, 3>{"Q", "M", "K"});
        }
    }

    TEST_CASE("the drawing reads each contour side at the indices of its points") {
        // project_face()'s sides, the four of Algorithm 2.3 steps 5-6, and any other ids by search.
        const FaceModel neutral = FaceModel::default_face();
        for (double beta_deg : {-15.0, 0.0, 15.0}) {
            CAPTURE(beta_deg);
            const ProjectedFace face = project_face(neutral, posed(0, beta_deg, 0));
            for (const auto* side : {&face.left_contour, &face.right_contour}) {
                const std::array<std::size_t, 3> indices = detail::contour_indices(*side);
                for (std::size_t k = 0; k < 3; ++k) CHECK(face.points[indices[k]].id == (*side)[k]);
            }
        }
        const std::array<std::string, 3> mixed{"N", "10.10", "K"};
        CHECK(detail::contour_indices(mixed) ==
              std::array<std::size_t, 3>{detail::lifted_at("N"), detail::lifted_at("10.10"), detail::lifted_at("K")});
        CHECK_THROWS_WITH_AS(detail::contour_indices({"11.2", "10.11", "2.14"}), doctest::Contains("\"10.11\""),
                             InvalidArgument);
    }

    TEST_CASE("the nose bridge is drawn from 9.6 unless the face turns to the image right") {
        const FaceModel neutral = FaceModel::default_face();
        CHECK(project_face(neutral, posed(0, 0, 0)).nose_bridge == NoseBridgeSide::left);
        CHECK(project_face(neutral, posed(0, 7, 0)).nose_bridge == NoseBridgeSide::left);
        CHECK(project_face(neutral, posed(0, -0.5, 0)).nose_bridge == NoseBridgeSide::right);
    }

    TEST_CASE("past the substitution, the substituted points are the receding side's silhouette") {
        // Algorithm 2.3 steps 5-6 replace the contour points that turn behind the cheek: at 15 degrees
        // the substitutes lie further out than the points they replace.
        const FaceModel neutral = FaceModel::default_face();
        const ProjectedFace left_turn = project_face(neutral, posed(0, 15, 0));
        CHECK(left_turn.point("N").x < left_turn.point("11.2").x);
        CHECK(left_turn.point("L").x < left_turn.point("10.10").x);
        CHECK(left_turn.point("J").x < left_turn.point("2.14").x);
        const ProjectedFace right_turn = project_face(neutral, posed(0, -15, 0));
        CHECK(right_turn.point("Q").x > right_turn.point("11.3").x);
        CHECK(right_turn.point("M").x > right_turn.point("10.9").x);
        CHECK(right_turn.point("K").x > right_turn.point("2.13").x);
    }

    TEST_CASE("the pupils keep looking at the viewer while the head turns") {
        // Thesis 2.4.3.2: the focus stays in front of the face, so as the head turns the pupils roll
        // back in their eyes: measured from the middle of each eye's corners, the pupil moves
        // against the turn, more the further the head turns, and the pupil moves less than the eye.
        for (const auto& [name, neutral] : test::test_faces()) {
            CAPTURE(name);
            const ProjectedFace frontal = project_face(neutral, {});
            const double left_eye_rest = pupil_offset_x(frontal, "EyeballLeft", "3.12", "3.8");
            const double right_eye_rest = pupil_offset_x(frontal, "EyeballRight", "3.11", "3.7");
            double previous_left_shift = 0.0, previous_right_shift = 0.0;
            for (double beta_deg : {5.0, 10.0, 15.0}) {
                CAPTURE(beta_deg);
                // beta > 0 turns the face to the image left (smaller x): the pupils lag to the right.
                const ProjectedFace turned = project_face(neutral, posed(0, beta_deg, 0));
                const double left_shift =
                    pupil_offset_x(turned, "EyeballLeft", "3.12", "3.8") - left_eye_rest;
                const double right_shift =
                    pupil_offset_x(turned, "EyeballRight", "3.11", "3.7") - right_eye_rest;
                CHECK(left_shift > previous_left_shift);
                CHECK(right_shift > previous_right_shift);
                previous_left_shift = left_shift;
                previous_right_shift = right_shift;
                const double pupil_move = turned.point("EyeballLeft").x - frontal.point("EyeballLeft").x;
                const double eye_move = (turned.point("3.12").x + turned.point("3.8").x -
                                         frontal.point("3.12").x - frontal.point("3.8").x) /
                                        2.0;
                CHECK(pupil_move < 0.0);
                CHECK(eye_move < pupil_move);
                // Mirror turn, mirror result.
                const ProjectedFace mirror = project_face(neutral, posed(0, -beta_deg, 0));
                CHECK(pupil_offset_x(mirror, "EyeballRight", "3.11", "3.7") - right_eye_rest < 0.0);
            }
        }
    }

    TEST_CASE("a pupil nods against a nod too") {
        const FaceModel neutral = FaceModel::default_face();
        const ProjectedFace frontal = project_face(neutral, {});
        const ProjectedFace nod = project_face(neutral, posed(15, 0, 0));
        const double pupil_drop = nod.point("EyeballLeft").y - frontal.point("EyeballLeft").y;
        const double lid_drop =
            (nod.point("3.2").y + nod.point("3.4").y - frontal.point("3.2").y - frontal.point("3.4").y) / 2.0;
        CHECK(pupil_drop > 0.0);
        CHECK(pupil_drop < lid_drop);
    }

    TEST_CASE("projecting does not depend on the order of calls") {
        const FaceModel neutral = FaceModel::default_face();
        FaceState state = posed(3, -7, 11);
        state.expression.blink_left = 0.4;
        state.mouth = mouth_controls(neutral, MouthShape::a);
        const ProjectedFace first = project_face(neutral, state);
        project_face(neutral, posed(-15, 15, 15));
        const ProjectedFace second = project_face(neutral, state);
        REQUIRE(first.points.size() == second.points.size());
        for (std::size_t i = 0; i < first.points.size(); ++i) {
            CHECK(first.points[i].id == second.points[i].id);
            CHECK(first.points[i].xy == second.points[i].xy);
        }
    }
}

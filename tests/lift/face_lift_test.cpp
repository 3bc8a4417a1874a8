#include <doctest/doctest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "common/test_paths.hpp"
#include "lift/lifted_point_index.hpp"
#include "lift/local_frame.hpp"
#include "talkface/errors.hpp"
#include "talkface/face_lift.hpp"
#include "talkface/face_model.hpp"

using namespace talkface;
using talkface::detail::to_image;
using talkface::detail::to_local;

namespace {

// Table 2.1, copied independently of src/lift/face_lift.cpp.
const std::vector<std::pair<std::string, double>> kTable21 = {{"EyeballLeft", 1.33}, {"EyeballRight", 1.33},
                                                              {"3.2", 1.33},         {"3.4", 1.33},
                                                              {"3.1", 1.33},         {"3.3", 1.33},
                                                              {"3.12", 1.19},        {"3.7", 1.19},
                                                              {"3.8", 1.25},         {"3.11", 1.25},
                                                              {"4.6", 1.17},         {"4.5", 1.17},
                                                              {"4.4a", 1.30},        {"4.3a", 1.30},
                                                              {"F", 1.30},           {"I", 1.30},
                                                              {"4.4", 1.44},         {"4.3", 1.44},
                                                              {"G", 1.44},           {"H", 1.44},
                                                              {"4.2", 1.49},         {"4.1", 1.49},
                                                              {"2.2", 1.55},         {"2.3", 1.55},
                                                              {"8.4", 1.40},         {"8.3", 1.40},
                                                              {"R", 1.40},           {"S", 1.40},
                                                              {"8.1", 1.60},         {"8.9", 1.60},
                                                              {"8.10", 1.60},        {"8.2", 1.56},
                                                              {"2.14", 0.36},        {"2.13", 0.36},
                                                              {"2.1", 1.33},         {"J", 1.18},
                                                              {"K", 1.18},           {"11.1", 1.37},
                                                              {"11.2a", 0.90},       {"11.3a", 0.90},
                                                              {"11.2", 0.42},        {"11.3", 0.42},
                                                              {"N", 0.85},           {"Q", 0.85},
                                                              {"10.2", -0.37},       {"10.1", -0.37},
                                                              {"10.8", 0.0},         {"10.7", 0.0},
                                                              {"A", 0.04},           {"B", 0.04},
                                                              {"9.6", 1.39},         {"9.7", 1.39},
                                                              {"9.2", 1.39},         {"9.1", 1.39},
                                                              {"9.14", 1.40},        {"9.13", 1.40},
                                                              {"9.4", 1.44},         {"9.5", 1.44},
                                                              {"9.15", 1.65},        {"C", 1.51},
                                                              {"D", 1.53},           {"E", 1.53},
                                                              {"10.9", 0.27},        {"10.10", 0.27},
                                                              {"L", 1.11},           {"M", 1.11}};

// The default face moved off its grid: every coordinate a random double.
FaceModel random_face(std::uint64_t seed) {
    std::mt19937_64 random(seed);
    std::uniform_real_distribution<double> shift_px(-4.0, 4.0);
    std::uniform_real_distribution<double> offset_px(-500.0, 500.0);
    const Point2 offset{offset_px(random), offset_px(random)};
    FaceModel face = FaceModel::default_face();
    for (const std::string& id : FaceModel::point_ids()) {
        const Point2 p = face.point(id);
        face.set_point(id, {p.x + offset.x + shift_px(random), p.y + offset.y + shift_px(random)});
    }
    const Point2 left = face.point("EyeballLeft");
    const Point2 right = face.point("EyeballRight");
    face.set_fapu("d", std::hypot(right.x - left.x, right.y - left.y));
    return face;
}

Point2 image_of(const LiftedFace& lifted, const std::string& id) {
    return to_image(lifted.local(id), lifted.origin);
}

}  // namespace

TEST_SUITE("FaceLift") {
    TEST_CASE("the rotation origin is 1.3 d below EyeMid") {
        CHECK(rotation_origin(FaceModel::default_face()) == Point2{200.0, 284.5});
        for (std::uint64_t seed = 1; seed <= 10; ++seed) {
            CAPTURE(seed);
            const FaceModel face = random_face(seed);
            const Point2 left = face.point("EyeballLeft");
            const Point2 right = face.point("EyeballRight");
            const Point2 origin = rotation_origin(face);
            CHECK(origin.x == doctest::Approx((left.x + right.x) / 2.0));
            CHECK(origin.y == doctest::Approx((left.y + right.y) / 2.0 + 1.3 * face.fapu("d")));
            CHECK(lift_face(face).origin == origin);
        }
    }

    TEST_CASE("global -> local -> global is exact on the default face") {
        const FaceModel face = FaceModel::default_face();
        const LiftedFace lifted = lift_face(face);
        REQUIRE(lifted.points.size() == 72 + 17);
        for (std::size_t i = 0; i < FaceModel::kPointCount; ++i) {
            CAPTURE(lifted.points[i].id);
            CHECK(lifted.points[i].id == FaceModel::point_ids()[i]);
            CHECK(to_image(lifted.points[i].local, lifted.origin) == face.points()[i]);
        }
    }

    TEST_CASE("global -> local -> global is within 1e-9 px on random faces") {
        for (std::uint64_t seed = 1; seed <= 50; ++seed) {
            CAPTURE(seed);
            const FaceModel face = random_face(seed);
            const LiftedFace lifted = lift_face(face);
            for (std::size_t i = 0; i < FaceModel::kPointCount; ++i) {
                CAPTURE(lifted.points[i].id);
                const Point2 back = to_image(lifted.points[i].local, lifted.origin);
                CHECK(std::abs(back.x - face.points()[i].x) <= 1e-9);
                CHECK(std::abs(back.y - face.points()[i].y) <= 1e-9);
            }
        }
    }

    TEST_CASE("the local frame is not mirrored: a left point stays left") {
        const FaceModel face = FaceModel::default_face();
        const LiftedFace lifted = lift_face(face);
        const Point3 left_eye = lifted.local("3.12");
        // x' = x_o - x: the image-left points have positive local x, and y' points up.
        CHECK(left_eye.x == lifted.origin.x - face.point("3.12").x);
        CHECK(left_eye.x > 0.0);
        CHECK(lifted.local("3.7").x < 0.0);
        CHECK(lifted.local("11.1").y > lifted.local("2.1").y);
        CHECK(image_of(lifted, "3.12").x < lifted.origin.x);
        CHECK(image_of(lifted, "3.12") == face.point("3.12"));
        // The thesis's x = x_p + x_o would put the image-left eye on the right.
        CHECK(left_eye.x + lifted.origin.x > lifted.origin.x);
        CHECK(to_local({10.0, 20.0}, 3.0, {100.0, 50.0}) == Point3{90.0, 30.0, 3.0});
        CHECK(to_image({90.0, 30.0, 3.0}, {100.0, 50.0}) == Point2{10.0, 20.0});
    }

    TEST_CASE("depths follow Table 2.1 for every point") {
        for (const auto& [id, depth] : kTable21) {
            CAPTURE(id);
            CHECK(depth_in_d(id) == depth);
        }
        for (int k = 1; k <= 23; ++k) {
            CAPTURE(k);
            CHECK(depth_in_d("hair." + std::to_string(k)) == -0.58);
        }
        for (const std::string& id : FaceModel::point_ids()) {
            CAPTURE(id);
            CHECK_NOTHROW(depth_in_d(id));
        }
        for (const std::string& id : additional_point_ids()) {
            CAPTURE(id);
            CHECK_NOTHROW(depth_in_d(id));
        }
        CHECK_THROWS_WITH_AS(depth_in_d("8.5"), doctest::Contains("point \"8.5\""), InvalidArgument);
        CHECK_THROWS_AS(depth_in_d("hair.24"), InvalidArgument);
        CHECK_THROWS_AS(depth_in_d("O"), InvalidArgument);

        const LiftedFace lifted = lift_face(FaceModel::default_face());
        CHECK(lifted.d == 65.0);
        for (const LiftedPoint& point : lifted.points) {
            CAPTURE(point.id);
            CHECK(point.local.z == depth_in_d(point.id) * 65.0);
        }
    }

    TEST_CASE("the 17 additional points follow Algorithm 2.1 step 4") {
        CHECK(additional_point_ids() == std::vector<std::string>{"A", "B", "C", "D", "E", "F", "G", "H", "I",
                                                                 "J", "K", "L", "M", "N", "Q", "R", "S"});
        for (const FaceModel& face : {FaceModel::default_face(), random_face(7),
                                      FaceModel::load(test::source_path("samples/faces/female.xml"))}) {
            CAPTURE(face.name());
            const LiftedFace lifted = lift_face(face);
            for (std::size_t i = 0; i < 17; ++i) CHECK(lifted.points[72 + i].id == additional_point_ids()[i]);
            auto p = [&](const char* id) { return face.point(id); };
            auto at = [&](const char* id) { return image_of(lifted, id); };
            auto check_near = [](Point2 actual, Point2 expected) {
                CHECK(actual.x == doctest::Approx(expected.x));
                CHECK(actual.y == doctest::Approx(expected.y));
            };
            const Point2 mid{(p("EyeballLeft").x + p("EyeballRight").x) / 2.0,
                             (p("EyeballLeft").y + p("EyeballRight").y) / 2.0};
            const double brow_h = face.fapu("EyebrowH");
            const double brow_h2 = face.fapu("EyebrowH2");
            // W_ear: horizontal distance from EyeMid to the ear's contact point with the head, per side.
            check_near(at("A"), {p("10.8").x, (4.0 * p("10.2").y + p("10.8").y) / 5.0});
            check_near(at("B"), {p("10.7").x, (4.0 * p("10.1").y + p("10.7").y) / 5.0});
            check_near(at("C"), {(p("9.13").x + p("9.14").x) / 2.0, (p("9.14").y + mid.y) / 2.0});
            check_near(at("D"), {(5.0 * p("9.4").x + p("9.5").x) / 6.0,
                                 p("9.4").y - (p("9.4").y - p("9.14").y) / 3.0});
            check_near(at("E"), {(5.0 * p("9.5").x + p("9.4").x) / 6.0,
                                 p("9.5").y - (p("9.5").y - p("9.13").y) / 3.0});
            check_near(at("F"), {p("4.4a").x, p("4.4a").y + brow_h2 / 1.3});
            check_near(at("G"), {p("4.4").x, p("4.4").y + brow_h / 1.3});
            check_near(at("H"), {p("4.3").x, p("4.3").y + brow_h / 1.3});
            check_near(at("I"), {p("4.3a").x, p("4.3a").y + brow_h2 / 1.3});
            check_near(at("J"), {(5.0 * p("2.14").x + p("2.1").x) / 6.0, p("2.14").y});
            check_near(at("K"), {(5.0 * p("2.13").x + p("2.1").x) / 6.0, p("2.13").y});
            check_near(at("L"), {(p("3.12").x + p("10.10").x) / 2.0, p("10.10").y});
            check_near(at("M"), {(p("3.7").x + p("10.9").x) / 2.0, p("10.9").y});
            CHECK(at("N") == p("11.2"));
            CHECK(at("Q") == p("11.3"));
            CHECK(at("R") == p("8.4"));
            // SPEC: S is 8.3 (the thesis's 8.5 does not exist).
            CHECK(at("S") == p("8.3"));
            CHECK(lifted.local("S").x == lifted.local("8.3").x);
            CHECK(lifted.local("S").y == lifted.local("8.3").y);
        }
    }

    TEST_CASE("the default face's additional points are exact and symmetric") {
        const LiftedFace lifted = lift_face(FaceModel::default_face());
        for (const auto& [left, right] : std::vector<std::pair<const char*, const char*>>{{"A", "B"},
                                                                                          {"D", "E"},
                                                                                          {"F", "I"},
                                                                                          {"G", "H"},
                                                                                          {"J", "K"},
                                                                                          {"L", "M"},
                                                                                          {"N", "Q"},
                                                                                          {"R", "S"}}) {
            CAPTURE(left);
            CHECK(lifted.local(left).x == -lifted.local(right).x);
            CHECK(lifted.local(left).y == lifted.local(right).y);
            CHECK(lifted.local(left).z == lifted.local(right).z);
        }
        CHECK(lifted.local("C").x == 0.0);
    }

    TEST_CASE("an unknown id in a lifted face is an InvalidArgument") {
        const LiftedFace lifted = lift_face(FaceModel::default_face());
        CHECK_THROWS_WITH_AS(lifted.local("P"), doctest::Contains("point \"P\""), InvalidArgument);
    }

    TEST_CASE("place_face scales every point and FAPU by d'/d and moves O") {
        const FaceModel face = FaceModel::load(test::source_path("samples/faces/male.xml"));
        const Point2 old_origin = rotation_origin(face);
        for (const double new_d_px : {32.5, 65.0, 130.0, 97.3}) {
            CAPTURE(new_d_px);
            const Point2 new_origin{640.0, 360.5};
            const FaceModel placed = place_face(face, new_origin, new_d_px);
            const double scale = new_d_px / face.fapu("d");
            CHECK(placed.fapu("d") == new_d_px);
            for (const std::string& name : FaceModel::fapu_names()) {
                CAPTURE(name);
                CHECK(placed.fapu(name) == doctest::Approx(face.fapu(name) * scale));
            }
            for (const std::string& id : FaceModel::point_ids()) {
                CAPTURE(id);
                CHECK(placed.point(id).x - new_origin.x ==
                      doctest::Approx((face.point(id).x - old_origin.x) * scale));
                CHECK(placed.point(id).y - new_origin.y ==
                      doctest::Approx((face.point(id).y - old_origin.y) * scale));
            }
            const Point2 moved = rotation_origin(placed);
            CHECK(moved.x == doctest::Approx(new_origin.x));
            CHECK(moved.y == doctest::Approx(new_origin.y));
            CHECK(placed.colors() == face.colors());
            CHECK(placed.name() == face.name());
        }
        CHECK(place_face(FaceModel::default_face(), {200.0, 284.5}, 65.0) == FaceModel::default_face());
    }

    TEST_CASE("place_face rejects a size that is not finite and positive") {
        const FaceModel face;
        for (const double bad : {0.0, -65.0, std::numeric_limits<double>::infinity(), std::nan("")}) {
            CAPTURE(bad);
            CHECK_THROWS_WITH_AS(place_face(face, {0.0, 0.0}, bad), doctest::Contains("d_px"),
                                 InvalidArgument);
        }
        CHECK_THROWS_WITH_AS(place_face(face, {std::nan(""), 0.0}, 65.0), doctest::Contains("origin"),
                             InvalidArgument);
    }

    TEST_CASE("the lifted order's indices are where lift_face puts each point") {
        static_assert(detail::lifted_at("A") == FaceModel::kPointCount);
        static_assert(detail::lifted_at("S") == detail::kLiftedPointCount - 1);
        const LiftedFace lifted = lift_face(FaceModel::default_face());
        REQUIRE(lifted.points.size() == detail::kLiftedPointCount);
        for (std::size_t i = 0; i < lifted.points.size(); ++i) {
            const std::string& id = lifted.points[i].id;
            CAPTURE(id);
            CHECK(detail::lifted_at(id) == i);
            CHECK(detail::lifted_point_index(id) == i);
        }
        CHECK(detail::lifted_at({"2.1", "N"}) == std::array<std::size_t, 2>{detail::point_at("2.1"), FaceModel::kPointCount + 13});
        for (const char* unknown : {"O", "P", "T", "", "AB", "hair.24"}) {
            CAPTURE(unknown);
            CHECK_FALSE(detail::lifted_point_index(unknown).has_value());
        }
    }
}

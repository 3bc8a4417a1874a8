#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "common/test_paths.hpp"
#include "face/fapu_measure.hpp"
#include "face/point_ids.hpp"
#include "talkface/errors.hpp"
#include "talkface/face_model.hpp"

using namespace talkface;

namespace {

// The default face mirrors about this vertical line (src/face/default_face.cpp).
constexpr double kAxisX = 200.0;

// Table 2.1's left/right pairs, image-left id first.
const std::vector<std::pair<std::string, std::string>> kMirroredPairs = {
    {"3.2", "3.1"},     {"3.4", "3.3"},    {"3.8", "3.11"},
    {"3.12", "3.7"},    {"4.2", "4.1"},    {"4.4", "4.3"},
    {"4.4a", "4.3a"},   {"4.6", "4.5"},    {"10.2", "10.1"},
    {"10.8", "10.7"},   {"10.10", "10.9"}, {"11.2", "11.3"},
    {"11.2a", "11.3a"}, {"2.14", "2.13"},  {"8.9", "8.10"},
    {"8.4", "8.3"},     {"9.6", "9.7"},    {"9.14", "9.13"},
    {"9.2", "9.1"},     {"9.4", "9.5"},    {"EyeballLeft", "EyeballRight"}};
const std::vector<std::string> kOnAxis = {"11.1", "2.1", "2.2", "2.3", "8.1", "8.2", "9.15", "hair.12"};

std::vector<FaceModel> all_faces() {
    return {FaceModel::default_face(), FaceModel::load(test::source_path("samples/faces/male.xml")),
            FaceModel::load(test::source_path("samples/faces/female.xml"))};
}

// The face contour as a polygon, in drawing order (Algorithm 2.2 step 3).
std::vector<Point2> contour_polygon(const FaceModel& face) {
    std::vector<Point2> polygon;
    for (const char* id :
         {"11.2", "11.2a", "11.1", "11.3a", "11.3", "10.9", "2.13", "2.1", "2.14", "10.10"}) {
        polygon.push_back(face.point(id));
    }
    return polygon;
}

bool is_inside(const std::vector<Point2>& polygon, Point2 p) {
    bool inside = false;
    for (std::size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++) {
        const Point2 a = polygon[i];
        const Point2 b = polygon[j];
        if ((a.y > p.y) != (b.y > p.y) && p.x < (b.x - a.x) * (p.y - a.y) / (b.y - a.y) + a.x)
            inside = !inside;
    }
    return inside;
}

double distance_to_segment(Point2 p, Point2 a, Point2 b) {
    const double dx = b.x - a.x;
    const double dy = b.y - a.y;
    const double t = std::clamp(((p.x - a.x) * dx + (p.y - a.y) * dy) / (dx * dx + dy * dy), 0.0, 1.0);
    return std::hypot(p.x - (a.x + t * dx), p.y - (a.y + t * dy));
}

double distance_to_polygon(const std::vector<Point2>& polygon, Point2 p) {
    double best = INFINITY;
    for (std::size_t i = 0; i < polygon.size(); ++i) {
        best = std::min(best, distance_to_segment(p, polygon[i], polygon[(i + 1) % polygon.size()]));
    }
    return best;
}

}  // namespace

TEST_SUITE("FaceModel") {
    TEST_CASE("the default face is named default and is what the default constructor gives") {
        const FaceModel face = FaceModel::default_face();
        CHECK(face.name() == "default");
        CHECK(FaceModel() == face);
        CHECK(face.colors() == FaceColors{});
        CHECK(face.points().size() == 72);
        CHECK(FaceModel::point_ids().size() == 72);
    }

    TEST_CASE("the default face is left/right symmetric, exactly") {
        const FaceModel face = FaceModel::default_face();
        for (const auto& [left, right] : kMirroredPairs) {
            CAPTURE(left);
            CHECK(face.point(right).x == 2.0 * kAxisX - face.point(left).x);
            CHECK(face.point(right).y == face.point(left).y);
            CHECK(face.point(left).x < kAxisX);
        }
        for (const std::string& id : kOnAxis) {
            CAPTURE(id);
            CHECK(face.point(id).x == kAxisX);
        }
        for (int k = 1; k <= 11; ++k) {
            CAPTURE(k);
            const Point2 left = face.point("hair." + std::to_string(k));
            const Point2 right = face.point("hair." + std::to_string(24 - k));
            CHECK(right.x == 2.0 * kAxisX - left.x);
            CHECK(right.y == left.y);
        }
        CHECK(face.fapu("LeftEyeH") == face.fapu("RightEyeH"));
        CHECK(face.fapu("r1") == face.fapu("r2"));
    }

    TEST_CASE("the default face lies on a 0.25 px grid with d = 65 px") {
        const FaceModel face = FaceModel::default_face();
        for (std::size_t i = 0; i < FaceModel::kPointCount; ++i) {
            CAPTURE(FaceModel::point_ids()[i]);
            CHECK(std::fmod(face.points()[i].x * 4.0, 1.0) == 0.0);
            CHECK(std::fmod(face.points()[i].y * 4.0, 1.0) == 0.0);
            CHECK(face.points()[i].x >= 0.0);
            CHECK(face.points()[i].x <= 400.0);
            CHECK(face.points()[i].y >= 0.0);
            CHECK(face.points()[i].y <= 400.0);
        }
        CHECK(face.fapu("d") == 65.0);
    }

    TEST_CASE("the default face's FAPUs agree with what its points measure") {
        const FaceModel face = FaceModel::default_face();
        for (const std::string& name : FaceModel::fapu_names()) {
            CAPTURE(name);
            CHECK(face.fapu(name) == doctest::Approx(detail::measured_fapu(face, name)));
        }
    }

    TEST_CASE("every face follows the thesis's point conventions") {
        for (const FaceModel& face : all_faces()) {
            CAPTURE(face.name());
            auto p = [&](const char* id) { return face.point(id); };
            // image-left eye: 3.12 outer, 3.8 inner corner, 3.2 top, 3.4 bottom
            CHECK(p("3.12").x < p("3.2").x);
            CHECK(p("3.2").x < p("3.8").x);
            CHECK(p("3.8").x < p("3.11").x);
            CHECK(p("3.11").x < p("3.7").x);
            CHECK(p("3.2").y < p("3.4").y);
            CHECK(p("3.1").y < p("3.3").y);
            // brows above the eyes, 4.6 outer, 4.2 inner
            CHECK(p("4.6").x < p("4.4a").x);
            CHECK(p("4.4a").x < p("4.4").x);
            CHECK(p("4.4").x < p("4.2").x);
            CHECK(p("4.4").y < p("3.2").y);
            CHECK(p("4.1").x < p("4.3").x);
            CHECK(p("4.3").x < p("4.3a").x);
            CHECK(p("4.3a").x < p("4.5").x);
            // mouth: 8.4 left corner, 8.3 right, closed when neutral
            CHECK(p("8.4").x < p("8.9").x);
            CHECK(p("8.9").x < p("8.1").x);
            CHECK(p("8.1").x < p("8.10").x);
            CHECK(p("8.10").x < p("8.3").x);
            CHECK(p("2.2").y == p("2.3").y);
            CHECK(p("8.1").y < p("2.2").y);
            CHECK(p("2.3").y < p("8.2").y);
            CHECK(p("8.2").y < p("2.1").y);
            // nose between eyes and mouth; ears on their sides
            CHECK(p("9.15").y < p("8.1").y);
            CHECK(p("EyeballLeft").y < p("9.6").y);
            CHECK(p("10.2").y < p("10.8").y);
            CHECK(p("10.2").x < p("10.10").x);
            CHECK(p("10.1").x > p("10.9").x);
            CHECK(p("11.1").y < p("4.4").y);
            CHECK(p("2.14").x < p("2.1").x);
            CHECK(p("2.1").x < p("2.13").x);
            // the rotation origin sits inside a 400 x 400 canvas
            const double d = face.fapu("d");
            const double origin_y = p("EyeballLeft").y + 1.3 * d;
            CHECK(origin_y > 0.0);
            CHECK(origin_y < 400.0);
        }
    }

    TEST_CASE("the hair stays outside the face contour by at least 0.2 d") {
        for (const FaceModel& face : all_faces()) {
            CAPTURE(face.name());
            const std::vector<Point2> contour = contour_polygon(face);
            for (int k = 1; k <= 23; ++k) {
                const std::string id = "hair." + std::to_string(k);
                CAPTURE(id);
                CHECK_FALSE(is_inside(contour, face.point(id)));
                CHECK(distance_to_polygon(contour, face.point(id)) >= 0.2 * face.fapu("d"));
            }
        }
    }

    TEST_CASE("the male and female sample faces differ in shape and colour") {
        const FaceModel male = FaceModel::load(test::source_path("samples/faces/male.xml"));
        const FaceModel female = FaceModel::load(test::source_path("samples/faces/female.xml"));
        CHECK(male.name() == "male");
        CHECK(female.name() == "female");
        CHECK(male.colors() != female.colors());
        // long hair reaches below the chin, short hair does not
        CHECK(female.point("hair.1").y > female.point("2.1").y);
        CHECK(male.point("hair.1").y < male.point("2.1").y);
        // a wider jaw, thicker brows and thinner lips on the male face
        CHECK(male.point("2.13").x - male.point("2.14").x > female.point("2.13").x - female.point("2.14").x);
        CHECK(male.fapu("EyebrowH") > female.fapu("EyebrowH"));
        CHECK(male.fapu("LowerLipH") < female.fapu("LowerLipH"));
    }

    TEST_CASE("accessors reject unknown ids and bad values") {
        FaceModel face;
        CHECK_THROWS_WITH_AS(face.point("8.5"), doctest::Contains("point \"8.5\""), InvalidArgument);
        CHECK_THROWS_AS(face.set_point("2.2", {NAN, 1.0}), InvalidArgument);
        CHECK_THROWS_WITH_AS(face.set_point("2.2", {1.0, -1.5e6}), doctest::Contains("-1500000"), InvalidArgument);
        face.set_point("2.2", {FaceModel::kMaxCoordinatePx, -FaceModel::kMaxCoordinatePx});
        face.set_point("2.2", FaceModel::default_face().point("2.2"));
        CHECK_THROWS_WITH_AS(face.fapu("MW1"), doctest::Contains("FAPU \"MW1\""), InvalidArgument);
        CHECK_THROWS_AS(face.set_fapu("MW0", 0.0), InvalidArgument);
        CHECK_THROWS_AS(face.set_fapu("MW0", INFINITY), InvalidArgument);
        CHECK_THROWS_WITH_AS(face.set_fapu("MW0", 2e7), doctest::Contains("at most 1e7"), InvalidArgument);
        CHECK(face == FaceModel::default_face());
        CHECK(FaceModel::is_point_id("hair.23"));
        CHECK_FALSE(FaceModel::is_point_id("hair.24"));
    }

    TEST_CASE("a point id resolves to its index in point_ids(), at compile time and by search") {
        // point_at() in a constant expression: the build itself checks these.
        static_assert(detail::point_at("hair.1") == 0);
        static_assert(detail::point_at("11.1") == detail::kHairPointCount);
        static_assert(detail::point_at("EyeballRight") == FaceModel::kPointCount - 1);
        const std::vector<std::string>& ids = FaceModel::point_ids();
        REQUIRE(ids.size() == FaceModel::kPointCount);
        for (std::size_t i = 0; i < ids.size(); ++i) {
            CAPTURE(ids[i]);
            CHECK(detail::point_at(ids[i]) == i);
            CHECK(detail::point_index(ids[i]) == i);
        }
        for (const char* unknown : {"", "8.5", "hair.0", "hair.24", "EyeballLef", "EyeballLeftX", "8.4 "}) {
            CAPTURE(unknown);
            CHECK_FALSE(detail::point_index(unknown).has_value());
            CHECK_THROWS(detail::point_at(unknown));
        }
    }

    TEST_CASE("the pipeline's move by index checks a point as set_point does, naming it") {
        FaceModel face;
        constexpr std::size_t k2_2 = detail::point_at("2.2");
        detail::FacePointEditor::set_point(face, k2_2, {12.5, -3.0});
        CHECK(face.point("2.2") == Point2{12.5, -3.0});
        CHECK_THROWS_WITH_AS(detail::FacePointEditor::set_point(face, k2_2, {NAN, 1.0}),
                             doctest::Contains("point \"2.2\""), InvalidArgument);
        CHECK_THROWS_WITH_AS(detail::FacePointEditor::set_point(face, k2_2, {1.0, -1.5e6}),
                             doctest::Contains("-1500000"), InvalidArgument);
        CHECK(face.point("2.2") == Point2{12.5, -3.0});
    }
}

// What lies over what in the drawing model, at every pose of a grid over +-15 degrees on every
// axis, on every bundled face: checked on the layers' shapes as numbers (paint order, clips, and
// where the outlines lie), not on pictures.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <set>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "common/test_paths.hpp"
#include "render/face_grid.hpp"
#include "render/drawing.hpp"
#include "render/layers.hpp"
#include "talkface/face_model.hpp"
#include "talkface/face_pose.hpp"
#include "talkface/mouth_shape.hpp"

using namespace talkface;
using namespace talkface::detail;

namespace {

Point2 bezier(const std::vector<Point2>& p, double t) {
    // De Casteljau over the control polygon (2 to 4 points).
    std::vector<Point2> q = p;
    for (std::size_t n = q.size(); n > 1; --n) {
        for (std::size_t i = 0; i + 1 < n; ++i) q[i] = {q[i].x + t * (q[i + 1].x - q[i].x), q[i].y + t * (q[i + 1].y - q[i].y)};
    }
    return q[0];
}

// Each subpath of `path` as a polygon, its curves cut into 16 lines each.
std::vector<std::vector<Point2>> flatten(const Path& path) {
    std::vector<std::vector<Point2>> polygons;
    std::size_t k = 0;
    for (const PathVerb verb : path.verbs) {
        const int count = points_of(verb);
        if (verb == PathVerb::move) {
            polygons.push_back({path.points[k]});
        } else if (verb == PathVerb::line) {
            polygons.back().push_back(path.points[k]);
        } else if (verb == PathVerb::cubic || verb == PathVerb::quadratic) {
            std::vector<Point2> control{polygons.back().back()};
            for (int i = 0; i < count; ++i) control.push_back(path.points[k + i]);
            for (int step = 1; step <= 16; ++step) polygons.back().push_back(bezier(control, step / 16.0));
        }
        k += count;
    }
    return polygons;
}

bool is_inside(const std::vector<Point2>& polygon, Point2 p) {
    bool inside = false;
    for (std::size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++) {
        const Point2 a = polygon[i], b = polygon[j];
        if ((a.y > p.y) != (b.y > p.y) && p.x < (b.x - a.x) * (p.y - a.y) / (b.y - a.y) + a.x) inside = !inside;
    }
    return inside;
}

// The distance from p to the polygon's edges.
double distance_to(const std::vector<Point2>& polygon, Point2 p) {
    double best = 1e300;
    for (std::size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++) {
        const Point2 a = polygon[j], b = polygon[i];
        const double dx = b.x - a.x, dy = b.y - a.y;
        const double length2 = dx * dx + dy * dy;
        const double t = length2 > 0.0 ? std::clamp(((p.x - a.x) * dx + (p.y - a.y) * dy) / length2, 0.0, 1.0) : 0.0;
        best = std::min(best, std::hypot(p.x - (a.x + t * dx), p.y - (a.y + t * dy)));
    }
    return best;
}

// Inside, or within `slack` of the edge.
bool is_covered(const std::vector<Point2>& polygon, Point2 p, double slack) {
    return is_inside(polygon, p) || distance_to(polygon, p) <= slack;
}

std::size_t index_of(const Layer& layer, std::string_view name) {
    for (std::size_t i = 0; i < layer.elements.size(); ++i) {
        if (layer.elements[i].name == name) return i;
    }
    FAIL("no element named " << name);
    return 0;
}

const Shape& shape_named(const Layer& layer, std::string_view name) { return layer.elements[index_of(layer, name)]; }

// The face's outline: the contour's upper part and the jaw, as one polygon.
std::vector<Point2> face_outline(const Layer& face) {
    std::vector<Point2> outline = flatten(shape_named(face, "face-contour").path).front();
    const std::vector<Point2> jaw = flatten(shape_named(face, "jaw").path).front();
    outline.pop_back();  // the line into the jaw's middle
    outline.insert(outline.end(), jaw.begin(), jaw.end());
    return outline;
}

// Every point of every subpath of a path shape.
std::vector<Point2> points_drawn(const Shape& shape) {
    std::vector<Point2> points;
    for (const auto& polygon : flatten(shape.path)) points.insert(points.end(), polygon.begin(), polygon.end());
    return points;
}

struct Drawn {
    Layer hair, face;
    double d = 0.0;
};

Drawn draw(const FaceModel& face, const FaceState& state, FaceLook look = FaceLook::outlined) {
    const ProjectedFace projected = project_face(face, state);
    const FacePaints paints = make_face_paints(projected, LayerStyle{2, 0.025 * projected.d, look});
    return {draw_hair_layer(projected, paints), draw_face_layer(projected, paints), projected.d};
}

// The share of an ear's rim that lies under the face or the hair.
double hidden_share(const Drawn& drawn, const char* ear) {
    const std::vector<Point2> outline = face_outline(drawn.face);
    const std::vector<Point2> hair = flatten(shape_named(drawn.hair, "hair").path).front();
    const std::vector<Point2> rim = flatten(shape_named(drawn.hair, ear).path).front();
    double hidden = 0.0;
    for (const Point2& p : rim) hidden += is_inside(outline, p) || is_inside(hair, p);
    return hidden / static_cast<double>(rim.size());
}

std::vector<FaceState> states_at(const FaceModel& face, const Pose& pose) {
    std::vector<FaceState> states(2);
    states[1].mouth = mouth_controls(face, MouthShape::a);
    states[1].expression.smile = 1.0;
    for (FaceState& state : states) state.pose = pose;
    return states;
}

}  // namespace

TEST_SUITE("layer order") {
    TEST_CASE("the ears lie under the hair and the face, their seams hidden, at every pose") {
        for (const auto& [name, face] : test::bundled_faces()) {
            CAPTURE(name);
            for (const Pose& pose : test::pose_grid()) {
                CAPTURE(pose.alpha_deg);
                CAPTURE(pose.beta_deg);
                CAPTURE(pose.gamma_deg);
                FaceState state;
                state.pose = pose;
                const Drawn drawn = draw(face, state);
                // The hair layer draws the ears first: the hair is painted over them, and the
                // face layer, painted after the hair layer, over both.
                const std::size_t hair = index_of(drawn.hair, "hair");
                CHECK(index_of(drawn.hair, "ear-left") < hair);
                CHECK(index_of(drawn.hair, "ear-right") < hair);
                const std::vector<Point2> outline = face_outline(drawn.face);
                for (const char* ear : {"ear-left", "ear-right"}) {
                    CAPTURE(ear);
                    // The straight edge that closes the ear runs inside the face, which covers it
                    // (within the outline's half width).
                    const std::vector<Point2> rim = flatten(shape_named(drawn.hair, ear).path).front();
                    CHECK(is_covered(outline, rim.front(), 0.0125 * drawn.d));
                    CHECK(is_covered(outline, rim.back(), 0.0125 * drawn.d));
                }
                // The ear on the side the face turns towards (the image left for beta > 0) goes
                // behind the head: no less of it lies under the face or the hair than at the same
                // nod and tilt without the turn, and at 15 degrees most of it.
                if (pose.beta_deg != 0.0) {
                    const char* far_ear = pose.beta_deg > 0.0 ? "ear-left" : "ear-right";
                    CAPTURE(far_ear);
                    FaceState frontal = state;
                    frontal.pose.beta_deg = 0.0;
                    const double far = hidden_share(drawn, far_ear);
                    // Within two of the rim's 17 sampled points.
                    CHECK(far >= hidden_share(draw(face, frontal), far_ear) - 2.0 / 17.0);
                    if (std::abs(pose.beta_deg) == 15.0) CHECK(far > 0.5);
                }
            }
        }
    }

    TEST_CASE("the nose, the brows, the eyes and the mouth lie on the face and are painted over it") {
        for (const auto& [name, face] : test::bundled_faces()) {
            CAPTURE(name);
            for (const Pose& pose : test::pose_grid()) {
                for (const FaceState& state : states_at(face, pose)) {
                  for (const FaceLook look : {FaceLook::outlined, FaceLook::flat}) {
                    CAPTURE(pose.alpha_deg);
                    CAPTURE(pose.beta_deg);
                    CAPTURE(pose.gamma_deg);
                    CAPTURE(face_look_name(look));
                    const Drawn drawn = draw(face, state, look);
                    const Layer& layer = drawn.face;
                    const std::vector<Point2> outline = face_outline(layer);
                    const std::size_t jaw = index_of(layer, "jaw");
                    CHECK(index_of(layer, "face-contour") < jaw);
                    for (const char* part : {"nose", "eyebrow-left", "eyebrow-right", "lips"}) {
                        CAPTURE(part);
                        CHECK(index_of(layer, part) > jaw);
                        for (const Point2& p : points_drawn(shape_named(layer, part))) CHECK(is_inside(outline, p));
                    }
                    for (const char* part : {"eye-left-white", "eyeball-left", "eye-right-white", "eyeball-right",
                                             "mouth-opening", "mouth-opening-outline"}) {
                        CHECK(index_of(layer, part) > jaw);
                    }
                    // The eyeballs are clipped by their eye's outline and painted over its white,
                    // under its outline's stroke; the eye outline lies on the face.
                    for (const char* side : {"left", "right"}) {
                        CAPTURE(side);
                        const std::string white = std::string("eye-") + side + "-white";
                        const std::string ball = std::string("eyeball-") + side;
                        const std::string stroke = std::string("eye-") + side + "-outline";
                        const Shape& eyeball = shape_named(layer, ball);
                        const Shape& eye_white = shape_named(layer, white);
                        CHECK(eyeball.kind == ShapeKind::group);
                        CHECK(eyeball.is_clipped);
                        CHECK(eye_white.kind == ShapeKind::reference);
                        CHECK(eyeball.definition == eye_white.definition);
                        CHECK(shape_named(layer, stroke).definition == eye_white.definition);
                        CHECK(index_of(layer, white) < index_of(layer, ball));
                        CHECK(index_of(layer, ball) < index_of(layer, stroke));
                        for (const auto& polygon : flatten(layer.definitions[eye_white.definition].outline)) {
                            for (const Point2& p : polygon) CHECK(is_inside(outline, p));
                        }
                    }
                    // The inside of the mouth (teeth, tongue) is the opening's own outline filled,
                    // painted over the lips and under the opening's stroke; the opening lies within
                    // the lips.
                    const Shape& inside = shape_named(layer, "mouth-opening");
                    CHECK(inside.kind == ShapeKind::reference);
                    CHECK(inside.paint.fill.kind == PaintKind::gradient);
                    CHECK(shape_named(layer, "mouth-opening-outline").definition == inside.definition);
                    CHECK(index_of(layer, "lips") < index_of(layer, "mouth-opening"));
                    CHECK(index_of(layer, "mouth-opening") < index_of(layer, "mouth-opening-outline"));
                    const std::vector<Point2> lips = flatten(shape_named(layer, "lips").path).front();
                    for (const auto& polygon : flatten(layer.definitions[inside.definition].outline)) {
                        for (const Point2& p : polygon) CHECK(is_covered(lips, p, 0.0125 * drawn.d));
                    }
                  }
                }
            }
        }
    }
}

// The hair and face layers: thesis Algorithm 2.2 steps 2-14, with Algorithm 2.3's substitutions
// (contour points past 10 degrees, the nose bridge side) already chosen by project_face().
#include <array>
#include <cmath>
#include <iterator>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "common/internal_error.hpp"
#include "lift/lifted_point_index.hpp"
#include "pose/contour_sides.hpp"
#include "render/curves.hpp"
#include "render/layers.hpp"
#include "render/svg_text.hpp"

namespace talkface::detail {

namespace {

// How far an eye's upper lid is moved up, in lid widths (draw_eyes): its band's lower edge stays
// 0.1 of its width inside the eye.
constexpr double kLidRise = 0.6;

// The pupil's diameter is 1/3 of the iris's (MPEG-4 neutral face).
constexpr double kPupilToIrisRadius = 1.0 / 3.0;
constexpr Rgb kPupilColour{0x11, 0x11, 0x11};
constexpr Rgb kHighlightColour{0xff, 0xff, 0xff};
constexpr Rgb kTeethColour{0xfa, 0xf7, 0xf0};

// Every frame draws the same points: the lists below name them by id and are resolved to their
// indices in the lifted order when this is compiled (lift/lifted_point_index.hpp).
using Indices3 = std::array<std::size_t, 3>;

// The points at `indices`, in the view.
template <std::size_t N>
std::vector<Point2> points_of(const ProjectedFace& face, const FacePaints& paints, const std::array<std::size_t, N>& indices) {
    std::vector<Point2> points;
    points.reserve(N);
    for (const std::size_t index : indices) points.push_back(paints.point(face, index));
    return points;
}

// The 23 hair points in polygon order, in the view: the first points of the lifted order.
std::vector<Point2> points_of_hair(const ProjectedFace& face, const FacePaints& paints) {
    std::vector<Point2> polygon;
    polygon.reserve(kHairPointCount);
    for (std::size_t i = 0; i < kHairPointCount; ++i) polygon.push_back(paints.point(face, i));
    return polygon;
}

// The drawing reads a projected face at the indices of the lifted order, as project_face() makes it.
void require_lifted_order(const ProjectedFace& face) {
    if (face.points.size() != kLiftedPointCount) {
        throw internal_error("a projected face of " + std::to_string(face.points.size()) + " points, not " +
                             std::to_string(kLiftedPointCount) + " in the lifted order");
    }
}

Shape path_shape(std::string_view name, Path path, const ShapePaint& paint) {
    Shape shape;
    shape.kind = ShapeKind::path;
    shape.name = name;
    shape.paint = paint;
    shape.path = std::move(path);
    return shape;
}

Point2 affine(Point2 origin, Point2 to_a, double s, Point2 to_b, double t) {
    return {origin.x + s * to_a.x + t * to_b.x, origin.y + s * to_a.y + t * to_b.y};
}

// The ear as one cubic Bezier segment in the frame of its upper contact point A: (s, t) is
// A + s (top - A) + t (lower contact - A), top = 10.2 / 10.1, lower contact = 10.8 / 10.7. It starts
// and ends inside the head, where the face contour, drawn over it, hides the straight edge that
// closes it; its control points round it over the top and down into the lobe. Affine combinations
// of three projected points: the ear turns, nods and tilts with the head. One segment, as the
// thesis's arc(10.8, 10.2, A): an animation moves four points per ear.
constexpr double kEarCurve[4][2] = {{-0.41, -0.3}, {2.09, -0.065}, {1.41, 1.77}, {-0.5, 1.03}};

// Each ear's upper contact point, top and lower contact point (image left, then right).
constexpr std::array<Indices3, 2> kEarPoints{lifted_at({"A", "10.2", "10.8"}), lifted_at({"B", "10.1", "10.7"})};

std::vector<Shape> draw_ears(const ProjectedFace& face, const FacePaints& paints) {
    // Thesis step 4's arc(10.8, 10.2, A) gives the ear's three points; drawn through them, it is a
    // spike. The ear is a rounded curve placed by them instead, under the hair (the hair layer
    // draws it first, so the hair hides it where it reaches) and under the face contour.
    constexpr std::string_view names[] = {"ear-left", "ear-right"};
    std::vector<Shape> shapes;
    for (std::size_t i = 0; i < std::size(kEarPoints); ++i) {
        const std::vector<Point2> points = points_of(face, paints, kEarPoints[i]);
        const Point2 contact = points[0];
        const Point2 to_top{points[1].x - contact.x, points[1].y - contact.y};
        const Point2 to_lobe{points[2].x - contact.x, points[2].y - contact.y};
        Point2 curve[4];
        for (int k = 0; k < 4; ++k) curve[k] = affine(contact, to_top, kEarCurve[k][0], to_lobe, kEarCurve[k][1]);
        Path path;
        path.move_to(curve[0]).curves({{curve[1], curve[2], curve[3]}}).close();
        shapes.push_back(path_shape(names[i], std::move(path), paints.ears));
    }
    return shapes;
}

void draw_face_contour(const ProjectedFace& face, const FacePaints& paints, Layer& layer) {
    // arc(11.2, 11.2a, 11.1, 11.3a, 11.3), arc(11.3, 10.9, 2.13), arc(2.13, 2.1, 2.14),
    // arc(2.14, 10.10, 11.2) as one closed curve: a face outline has no corners where they meet.
    // The sides are Algorithm 2.3's substitutions as project_face() chose them.
    const Indices3 left = contour_indices(face.left_contour);
    const Indices3 right = contour_indices(face.right_contour);
    constexpr std::array<std::size_t, 4> kMiddle = lifted_at({"11.2a", "11.1", "11.3a", "2.1"});
    const std::vector<Point2> points = points_of(face, paints, std::array<std::size_t, 10>{
        left[1], left[0], kMiddle[0], kMiddle[1], kMiddle[2], right[0], right[1], right[2], kMiddle[3], left[2]});
    const std::vector<CubicSegment> segments = closed_curve_segments(points);
    // Drawn as two open paths, so that the jaw, which the chin 2.1 moves with every mouth shape, is
    // animated apart from the rest, which only the pose moves. The upper part runs from cheek to
    // cheek (10.10 to 10.9: the segments that do not depend on 2.1) and its fill reaches down to
    // the middle of the jaw points, under the jaw's fill: no seam where the two fills meet. An
    // open path's fill closes it, its stroke does not: the jaw's stroke covers the line into the
    // jaw where it starts on the outline, and its fill the rest.
    const std::vector<CubicSegment> upper(segments.begin(), segments.begin() + 6);
    const std::vector<CubicSegment> jaw(segments.begin() + 6, segments.end());
    const Point2 jaw_middle{(points[7].x + points[9].x) / 2.0, (points[7].y + points[9].y) / 2.0};
    Path upper_path;
    upper_path.move_to(points.front()).curves(upper).line_to(jaw_middle);
    Path jaw_path;
    jaw_path.move_to(points[6]).curves(jaw);
    layer.elements.push_back(path_shape("face-contour", std::move(upper_path), paints.skin));
    layer.elements.push_back(path_shape("jaw", std::move(jaw_path), paints.skin));
}

Point2 lerp(Point2 a, Point2 b, double t) { return {a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)}; }

void draw_nose(const ProjectedFace& face, const FacePaints& paints, Layer& layer) {
    // Thesis step 6's arcs read as an open squiggle: a bridge line from the eyes, two wings apart
    // from it and a dash under the tip. The nose is drawn from the same points as the line the
    // bridge takes (Algorithm 2.3 step 8: the side that faces the viewer) from half-way down to C
    // into the wing, the wings and the tip as one line arc(9.14, 9.2, 9.15, 9.1, 9.13),
    // and two nostrils, all one path; a look without outlines shades the bridge's side instead.
    const bool is_right = face.nose_bridge == NoseBridgeSide::right;
    constexpr std::array<std::size_t, 7> kRightSide = lifted_at({"9.7", "C", "9.13", "9.1", "9.5", "9.15", "9.14"});
    constexpr std::array<std::size_t, 7> kLeftSide = lifted_at({"9.6", "C", "9.14", "9.2", "9.4", "9.15", "9.13"});
    const std::vector<Point2> p = points_of(face, paints, is_right ? kRightSide : kLeftSide);
    // p: the bridge's top, C, the bridge's lower end, wing, nostril's bottom, tip, the other wing's top.
    if (paints.nose_shade.fill.kind != PaintKind::none) {
        Path shade;
        shade.corner_cut_closed({lerp(p[0], p[1], 0.2), p[1], p[2], p[3], p[4], p[5],
                                 lerp(lerp(p[1], p[5], 0.6), p[6], 0.25)});
        layer.elements.push_back(path_shape("nose-shade", std::move(shade), paints.nose_shade));
    }
    constexpr std::array<std::size_t, 5> kBottom = lifted_at({"9.14", "9.2", "9.15", "9.1", "9.13"});
    const std::vector<Point2> bottom = points_of(face, paints, kBottom);
    const Point2 bridge_start = lerp(p[0], p[1], 0.5);
    Path path;
    if (paints.nose.stroke.kind != PaintKind::none) {
        path.move_to(bridge_start).arc({bridge_start, p[1], p[2]});
        path.move_to(bottom.front()).arc(bottom);
    }
    // The nostrils: small loops above the line, between the wing's bottom (9.4 / 9.5), D / E and
    // the tip.
    constexpr std::array<std::array<std::size_t, 4>, 2> kNostrils{lifted_at({"9.4", "D", "9.15", "9.2"}),
                                                                  lifted_at({"9.5", "E", "9.15", "9.1"})};
    for (const auto& ids : kNostrils) {
        const std::vector<Point2> q = points_of(face, paints, ids);
        path.corner_cut_closed({lerp(q[0], q[3], 0.2), lerp(q[1], q[3], 0.15), lerp(q[1], q[2], 0.55)});
    }
    layer.elements.push_back(path_shape("nose", std::move(path), paints.nose));
}

void draw_eyebrows(const ProjectedFace& face, const FacePaints& paints, Layer& layer) {
    // Corner-cut arc(4.6, 4.4a, 4.4, 4.2) and arc(4.2, G, F, 4.6): one closed outline per brow.
    constexpr std::array<std::array<std::size_t, 6>, 2> brows{lifted_at({"4.6", "4.4a", "4.4", "4.2", "G", "F"}),
                                                              lifted_at({"4.5", "4.3a", "4.3", "4.1", "H", "I"})};
    constexpr std::string_view names[] = {"eyebrow-left", "eyebrow-right"};
    for (std::size_t i = 0; i < brows.size(); ++i) {
        Path outline;
        outline.corner_cut_closed(points_of(face, paints, brows[i]));
        layer.elements.push_back(path_shape(names[i], std::move(outline), paints.brows));
    }
}

// The names of one eye's parts (static text: the drawing model keeps views of it).
struct EyeParts {
    std::array<std::size_t, 4> outline;  // corner, top, corner, bottom
    std::size_t eyeball;
    FapuIndex radius_fapu;
    std::string_view clip_id, outline_id, gradient_id;
    std::string_view white, eyeball_group, outline_stroke, lid;
};

// Image sides: left, then right.
const std::vector<EyeParts>& eye_parts() {
    static const std::vector<EyeParts> parts{
        {lifted_at({"3.12", "3.2", "3.8", "3.4"}), lifted_at("EyeballLeft"), kFapuR1, "tf-eye-left-clip", "tf-eye-left",
         "tf-iris-left-gradient", "eye-left-white", "eyeball-left", "eye-left-outline", "eye-left-lid"},
        {lifted_at({"3.7", "3.1", "3.11", "3.3"}), lifted_at("EyeballRight"), kFapuR2, "tf-eye-right-clip", "tf-eye-right",
         "tf-iris-right-gradient", "eye-right-white", "eyeball-right", "eye-right-outline", "eye-right-lid"}};
    return parts;
}

Path eye_outline(const ProjectedFace& face, const FacePaints& paints, const EyeParts& eye) {
    const std::vector<Point2> p = points_of(face, paints, eye.outline);
    Path path;
    path.move_to(p[0]).arc({p[0], p[1], p[2]}).arc({p[2], p[3], p[0]}).close();
    return path;
}

// Light from the upper left, darker rim: the eyes of thesis Figure 6.5.
RadialGradient iris_gradient(Rgb iris) {
    return {0.4, 0.4, 0.6,
            {{0.0, blend(iris, Rgb{0xff, 0xff, 0xff}, 0.45)}, {0.6, iris}, {1.0, blend(iris, Rgb{}, 0.5)}}};
}

// Each eye's clip path and iris gradient, in that order: the definitions of eye i are 2 i and 2 i + 1.
void draw_eye_definitions(const ProjectedFace& face, const FacePaints& paints, Layer& layer) {
    for (const EyeParts& eye : eye_parts()) {
        // The outline is defined once, in its clip path, and drawn again for the white and the
        // stroke: an animation then moves one path per eye instead of three.
        Definition clip;
        clip.kind = DefinitionKind::clip_path;
        clip.id = eye.clip_id;
        clip.outline_id = eye.outline_id;
        clip.outline = eye_outline(face, paints, eye);
        layer.definitions.push_back(std::move(clip));
        Definition gradient;
        gradient.kind = DefinitionKind::radial_gradient;
        gradient.id = eye.gradient_id;
        gradient.gradient = paints.iris_gradient;
        layer.definitions.push_back(std::move(gradient));
    }
}

Shape circle_shape(Point2 centre, double radius, const Paint& fill) {
    Shape shape;
    shape.kind = ShapeKind::circle;
    shape.centre = centre;
    shape.radius = radius;
    shape.paint.fill = fill;
    return shape;
}

Shape reference_shape(std::string_view name, std::size_t definition, const ShapePaint& paint) {
    Shape shape;
    shape.kind = ShapeKind::reference;
    shape.name = name;
    shape.definition = definition;
    shape.paint = paint;
    return shape;
}

// The head's axes in the drawing: across the face (image left to right, frontal) and down it, as
// the line between the outer eye corners (which no mouth shape, blink or smile moves) turns.
struct HeadAxes {
    Point2 across;
    Point2 down;
};

HeadAxes head_axes(const ProjectedFace& face, const FacePaints& paints) {
    constexpr std::size_t k3_12 = point_at("3.12"), k3_7 = point_at("3.7");
    // The model points come first in the lifted order: the same index in both.
    const Point2 left = paints.point(face, k3_12), right = paints.point(face, k3_7);
    const Point2 frontal_left = face.face.points()[k3_12], frontal_right = face.face.points()[k3_7];
    const double angle = std::atan2(right.y - left.y, right.x - left.x) -
                         std::atan2(frontal_right.y - frontal_left.y, frontal_right.x - frontal_left.x);
    return {{std::cos(angle), std::sin(angle)}, {-std::sin(angle), std::cos(angle)}};
}

void draw_eyes(const ProjectedFace& face, const FacePaints& paints, const HeadAxes& axes, Layer& layer) {
    for (std::size_t i = 0; i < eye_parts().size(); ++i) {
        const EyeParts& eye = eye_parts()[i];
        const std::size_t clip = 2 * i;
        const std::size_t gradient = 2 * i + 1;
        if (paints.eye_lid.fill.kind != PaintKind::none) {
            // The upper lid: the eye's outline moved up by 0.6 of the lid's width and stroked that
            // wide, under the white, shows as a band over the upper lid's edge, ending in a point
            // past each corner, that closes with the eye into a line (its lower edge stays inside
            // the eye, under the white). Moved by a fixed offset, it costs an animation no number.
            const double up = -kLidRise * paints.eye_lid.stroke_width;
            Shape lid = reference_shape(eye.lid, clip, paints.eye_lid);
            lid.offset = {up * axes.down.x, up * axes.down.y};
            layer.elements.push_back(std::move(lid));
        }
        layer.elements.push_back(reference_shape(eye.white, clip, paints.eye_white));
        // Clipped by the eye outline, so a closing lid hides iris and pupil (thesis 6.3.1).
        const Point2 pupil = paints.point(face, eye.eyeball);
        const double iris_radius_px = face.face.fapus()[eye.radius_fapu];
        const double iris_radius = paints.view.scale() * iris_radius_px;
        const double pupil_radius = kPupilToIrisRadius * iris_radius;
        // The light comes from the upper left of the image, whatever the view turns.
        const Point2 light = paints.view.apply_to_offset({-0.35 * iris_radius_px, -0.35 * iris_radius_px});
        const Point2 highlight{pupil.x + light.x, pupil.y + light.y};
        Shape eyeball;
        eyeball.kind = ShapeKind::group;
        eyeball.name = eye.eyeball_group;
        eyeball.definition = clip;
        eyeball.is_clipped = true;
        eyeball.children = {circle_shape(pupil, iris_radius, Paint::of_gradient(gradient)),
                            circle_shape(pupil, pupil_radius, Paint::of(kPupilColour)),
                            circle_shape(highlight, 0.5 * pupil_radius, Paint::of(kHighlightColour))};
        layer.elements.push_back(std::move(eyeball));
        layer.elements.push_back(reference_shape(eye.outline_stroke, clip, paints.eye_outline));
    }
}

// The inside of an open mouth, in mouth widths (MW0): the upper teeth hang this far under the
// upper lip's inner edge; the lower teeth stand this high over the lower lip's, the tongue behind
// them this high; the teeth stop this far short of the mouth's corners, which stay dark.
constexpr double kUpperTeethMw = 0.1;
constexpr double kLowerTeethMw = 0.06;
constexpr double kTongueMw = 0.14;
constexpr double kTeethCornerMw = 0.05;

Definition moved_clip(std::string_view id, std::size_t source, Point2 offset) {
    Definition clip;
    clip.kind = DefinitionKind::clip_path;
    clip.id = id;
    clip.is_moved = true;
    clip.source = source;
    clip.offset = offset;
    return clip;
}

Shape clipped_group(std::string_view name, std::size_t clip, std::vector<Shape> children) {
    Shape group;
    group.kind = ShapeKind::group;
    group.name = name;
    group.definition = clip;
    group.is_clipped = true;
    group.children = std::move(children);
    return group;
}

void draw_mouth(const ProjectedFace& face, const FacePaints& paints, const HeadAxes& axes, Layer& layer) {
    constexpr std::array<std::size_t, 6> kLips = lifted_at({"8.1", "8.9", "8.4", "8.2", "8.3", "8.10"});
    const std::vector<Point2> lips = points_of(face, paints, kLips);
    Path outer;
    outer.move_to(lips[0])
        .arc({lips[0], lips[1], lips[2]})
        .arc({lips[2], lips[3], lips[4]})
        .arc({lips[4], lips[5], lips[0]})
        .close();
    // arc(R, 2.2, S) + arc(S, 2.3, R): R and S sit on the corners 8.4 and 8.3 (SPEC: S = 8.3).
    constexpr std::array<std::size_t, 4> kInner = lifted_at({"R", "2.2", "S", "2.3"});
    const std::vector<Point2> inner_points = points_of(face, paints, kInner);
    Definition opening;
    opening.kind = DefinitionKind::clip_path;
    opening.id = "tf-mouth-clip";
    opening.outline_id = "tf-mouth";
    opening.outline.move_to(inner_points[0])
        .arc({inner_points[0], inner_points[1], inner_points[2]})
        .arc({inner_points[2], inner_points[3], inner_points[0]})
        .close();
    const std::size_t clip = layer.definitions.size();
    layer.definitions.push_back(std::move(opening));

    // Teeth and tongue are the opening's own outline again, moved: a shape at a fixed distance
    // under the upper lip's inner edge or over the lower lip's, clipped by the opening, keeps its
    // size as the mouth opens and follows the lip it hangs from (the lower lip moves with the jaw,
    // 8.2 and 2.1 with it). The animation moves no number for them (issue 17: shapes of their own
    // cost a minute of speech 25 KiB or more). Inside the opening, in paint order: the dark; the
    // upper teeth, everywhere but the corners; under them (where the opening moved down by the
    // teeth's height reaches), the lower teeth, the tongue above them and the dark above that.
    // Named references, not a structured binding: C++17 lets no lambda capture a binding (clang
    // refuses it, which broke tests/fuzz/README.md's clang build).
    const Point2& across = axes.across;
    const Point2& down = axes.down;
    const double mw = paints.view.scale() * face.face.fapus()[kFapuMW0];
    const auto offset = [&](double across_mw, double down_mw) {
        return Point2{mw * (across_mw * across.x + down_mw * down.x), mw * (across_mw * across.y + down_mw * down.y)};
    };
    const std::size_t short_of_left = layer.definitions.size();
    layer.definitions.push_back(moved_clip("tf-mouth-teeth-left-clip", clip, offset(kTeethCornerMw, 0.0)));
    const std::size_t short_of_right = layer.definitions.size();
    layer.definitions.push_back(moved_clip("tf-mouth-teeth-right-clip", clip, offset(-kTeethCornerMw, 0.0)));
    const std::size_t under_upper_teeth = layer.definitions.size();
    layer.definitions.push_back(moved_clip("tf-mouth-below-teeth-clip", clip, offset(0.0, kUpperTeethMw)));

    const auto inside = [&](std::string_view name, const ShapePaint& paint, Point2 moved_by) {
        Shape shape = reference_shape(name, clip, paint);
        shape.offset = moved_by;
        return shape;
    };
    ShapePaint dark = paints.mouth_opening;
    dark.stroke = Paint{};
    ShapePaint outline = paints.mouth_opening;
    outline.fill = Paint{};
    std::vector<Shape> below_teeth{inside("lower-teeth", paints.lower_teeth, {0.0, 0.0}),
                                   inside("tongue", paints.tongue, offset(0.0, -kLowerTeethMw)),
                                   inside("mouth-back", dark, offset(0.0, -kTongueMw))};
    std::vector<Shape> teeth{inside("upper-teeth", paints.teeth, {0.0, 0.0}),
                             clipped_group("mouth-below-upper-teeth", under_upper_teeth, std::move(below_teeth))};
    // The opening moved to either side, intersected: the opening short of its corners, and inside it
    // where the opening has no dent (its arcs bulge outwards at every mouth shape and smile;
    // tests/render/layer_order_test.cpp checks it).
    layer.elements.push_back(path_shape("lips", std::move(outer), paints.lips));
    layer.elements.push_back(reference_shape("mouth-opening", clip, dark));
    layer.elements.push_back(clipped_group(
        "mouth-inside", short_of_left, {clipped_group("mouth-inside-short-of-corners", short_of_right, std::move(teeth))}));
    layer.elements.push_back(reference_shape("mouth-opening-outline", clip, outline));
}

ShapePaint paint_of(const Paint& fill, const Paint& stroke, double stroke_width) {
    return {fill, stroke, stroke_width};
}

}  // namespace

ViewMap::ViewMap(Point2 origin, double angle_deg, double scale)
    : is_identity_(false), origin_(origin), scale_(scale) {
    const double angle_rad = angle_deg * (3.14159265358979323846 / 180.0);
    cos_ = std::cos(angle_rad);
    sin_ = std::sin(angle_rad);
}

Point2 ViewMap::apply_to_offset(Point2 offset_px) const {
    if (is_identity_) return offset_px;
    return {scale_ * (cos_ * offset_px.x + sin_ * offset_px.y),
            scale_ * (cos_ * offset_px.y - sin_ * offset_px.x)};
}

Point2 ViewMap::apply(Point2 image_xy) const {
    // The identity leaves the numbers as they are, bit for bit: a single frame is drawn this way.
    if (is_identity_) return image_xy;
    return apply_to_offset({image_xy.x - origin_.x, image_xy.y - origin_.y});
}

Point2 FacePaints::point(const ProjectedFace& face, std::size_t index) const { return view.apply(face.points[index].xy); }

std::vector<Point2> hair_layer_points(const ProjectedFace& face, const FacePaints& paints) {
    require_lifted_order(face);
    std::vector<Point2> points = points_of_hair(face, paints);
    for (const Indices3& ear : kEarPoints) {
        for (const std::size_t index : ear) points.push_back(paints.point(face, index));
    }
    return points;
}

Rgb flat_skin_shade(const FaceColors& colors) { return blend(colors.skin, colors.outline, 0.16); }

FacePaints make_face_paints(const ProjectedFace& face, const LayerStyle& style) {
    const FaceColors& colors = face.face.colors();
    const Paint none;
    FacePaints paints;
    paints.style = style;
    if (style.look == FaceLook::flat) {
        // No outlines: what an outline told apart, a shade of the skin tells apart here (the ears
        // and, in the clothes layer, the neck, which meet the face's own skin).
        const Rgb shade = flat_skin_shade(colors);
        paints.skin = paint_of(Paint::of(colors.skin), none, 0.0);
        paints.ears = paint_of(Paint::of(shade), none, 0.0);
        paints.hair = paint_of(Paint::of(colors.hair), none, 0.0);
        paints.nose = paint_of(Paint::of(blend(colors.skin, colors.outline, 0.55)), none, 0.0);
        paints.nose_shade = paint_of(Paint::of(blend(colors.skin, colors.outline, 0.1)), none, 0.0);
        paints.brows = paint_of(Paint::of(colors.brows), none, 0.0);
        paints.eye_white = paint_of(Paint::of(colors.eye_white), none, 0.0);
        paints.eye_outline = paint_of(none, none, 0.0);
        // An eye without an outline looks bare, and closed it vanishes: an upper lid shows both.
        const Paint lid = Paint::of(blend(colors.skin, colors.outline, 0.85));
        paints.eye_lid = paint_of(lid, lid, 1.8 * style.stroke_px);
        paints.lips = paint_of(Paint::of(colors.lips), none, 0.0);
        paints.mouth_opening = paint_of(Paint::of(colors.mouth_inside), none, 0.0);
        paints.iris_gradient = {0.5, 0.5, 0.5, {{0.0, colors.iris}, {0.75, colors.iris}, {1.0, blend(colors.iris, Rgb{}, 0.3)}}};
    } else {
        const Paint outline = Paint::of(colors.outline);
        const double stroke = style.stroke_px;
        paints.skin = paint_of(Paint::of(colors.skin), outline, stroke);
        paints.ears = paints.skin;
        paints.hair = paint_of(Paint::of(colors.hair), Paint::of(blend(colors.hair, Rgb{}, 0.4)), stroke);
        paints.nose = paint_of(none, outline, stroke);
        paints.brows = paint_of(Paint::of(colors.brows), Paint::of(colors.brows), 0.5 * stroke);
        paints.eye_white = paint_of(Paint::of(colors.eye_white), none, 0.0);
        paints.eye_outline = paint_of(none, outline, stroke);
        paints.lips = paint_of(Paint::of(colors.lips), outline, stroke);
        paints.mouth_opening = paint_of(Paint::of(colors.mouth_inside), outline, 0.6 * stroke);
        paints.iris_gradient = iris_gradient(colors.iris);
    }
    paints.teeth = paint_of(Paint::of(kTeethColour), none, 0.0);
    paints.lower_teeth = paint_of(Paint::of(blend(kTeethColour, colors.mouth_inside, 0.12)), none, 0.0);
    paints.tongue = paint_of(Paint::of(blend(colors.lips, Rgb{0xf2, 0x9a, 0xa6}, 0.55)), none, 0.0);
    return paints;
}

Layer draw_hair_layer(const ProjectedFace& face, const FacePaints& paints) {
    require_lifted_order(face);
    Path outline;
    outline.corner_cut_closed(points_of_hair(face, paints));
    Layer layer;
    layer.elements = draw_ears(face, paints);
    layer.elements.push_back(path_shape("hair", std::move(outline), paints.hair));
    return layer;
}

Layer draw_face_layer(const ProjectedFace& face, const FacePaints& paints) {
    require_lifted_order(face);
    Layer layer;
    draw_eye_definitions(face, paints, layer);
    draw_face_contour(face, paints, layer);
    draw_nose(face, paints, layer);
    draw_eyebrows(face, paints, layer);
    // The lids and the teeth are moved along the head's axes.
    const HeadAxes axes = head_axes(face, paints);
    draw_eyes(face, paints, axes, layer);
    draw_mouth(face, paints, axes, layer);
    return layer;
}

}  // namespace talkface::detail

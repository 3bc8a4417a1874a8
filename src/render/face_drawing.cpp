// The hair and face layers: thesis Algorithm 2.2 steps 2-14, with Algorithm 2.3's substitutions
// (contour points past 10 degrees, the nose bridge side) already chosen by project_face().
#include <cmath>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "render/curves.hpp"
#include "render/layers.hpp"
#include "render/svg_text.hpp"

namespace talkface::detail {

namespace {

// The pupil's diameter is 1/3 of the iris's (MPEG-4 neutral face).
constexpr double kPupilToIrisRadius = 1.0 / 3.0;
constexpr Rgb kPupilColour{0x11, 0x11, 0x11};
constexpr Rgb kHighlightColour{0xff, 0xff, 0xff};

std::vector<Point2> points_of(const ProjectedFace& face, const FaceLook& look,
                              const std::vector<std::string>& ids) {
    std::vector<Point2> points;
    points.reserve(ids.size());
    for (const std::string& id : ids) points.push_back(look.point(face, id));
    return points;
}

Shape path_shape(std::string_view name, Path path, const ShapePaint& paint) {
    Shape shape;
    shape.kind = ShapeKind::path;
    shape.name = name;
    shape.paint = paint;
    shape.path = std::move(path);
    return shape;
}

void draw_ears(const ProjectedFace& face, const FaceLook& look, Layer& layer) {
    // arc(10.8, 10.2, A) as one cubic through the ear's top 10.2 (curves.hpp: rim_segment); the
    // straight edge that closes each ear runs under the face contour, drawn after it.
    const std::vector<std::vector<std::string>> ears{{"10.8", "10.2", "A"}, {"10.7", "10.1", "B"}};
    constexpr std::string_view names[] = {"ear-left", "ear-right"};
    for (std::size_t i = 0; i < ears.size(); ++i) {
        const std::vector<Point2> points = points_of(face, look, ears[i]);
        Path path;
        path.move_to(points[0]).curves({rim_segment(points[0], points[1], points[2])}).close();
        layer.elements.push_back(path_shape(names[i], std::move(path), look.skin));
    }
}

void draw_face_contour(const ProjectedFace& face, const FaceLook& look, Layer& layer) {
    // arc(11.2, 11.2a, 11.1, 11.3a, 11.3), arc(11.3, 10.9, 2.13), arc(2.13, 2.1, 2.14),
    // arc(2.14, 10.10, 11.2) as one closed curve: a face outline has no corners where they meet.
    const auto& left = face.left_contour;
    const auto& right = face.right_contour;
    const std::vector<Point2> points =
        points_of(face, look,
                  {left[1], left[0], "11.2a", "11.1", "11.3a", right[0], right[1], right[2], "2.1", left[2]});
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
    layer.elements.push_back(path_shape("face-contour", std::move(upper_path), look.skin));
    layer.elements.push_back(path_shape("jaw", std::move(jaw_path), look.skin));
}

void draw_nose(const ProjectedFace& face, const FaceLook& look, Layer& layer) {
    // Algorithm 2.3 step 8: the bridge line runs down the side of the nose that faces the viewer.
    const std::vector<std::string> bridge = face.nose_bridge == NoseBridgeSide::right
                                                ? std::vector<std::string>{"9.7", "C", "9.13"}
                                                : std::vector<std::string>{"9.6", "C", "9.14"};
    const std::vector<std::vector<std::string>> arcs{
        bridge, {"9.14", "9.2", "9.4"}, {"9.13", "9.1", "9.5"}, {"D", "9.15", "E"}};
    Path path;
    for (const auto& ids : arcs) {
        const std::vector<Point2> points = points_of(face, look, ids);
        path.move_to(points.front()).arc(points);
    }
    layer.elements.push_back(path_shape("nose", std::move(path), look.nose));
}

void draw_eyebrows(const ProjectedFace& face, const FaceLook& look, Layer& layer) {
    // Corner-cut arc(4.6, 4.4a, 4.4, 4.2) and arc(4.2, G, F, 4.6): one closed outline per brow.
    const std::vector<std::vector<std::string>> brows{{"4.6", "4.4a", "4.4", "4.2", "G", "F"},
                                                      {"4.5", "4.3a", "4.3", "4.1", "H", "I"}};
    constexpr std::string_view names[] = {"eyebrow-left", "eyebrow-right"};
    for (std::size_t i = 0; i < brows.size(); ++i) {
        Path outline;
        outline.corner_cut_closed(points_of(face, look, brows[i]));
        layer.elements.push_back(path_shape(names[i], std::move(outline), look.brows));
    }
}

// The names of one eye's parts (static text: the drawing model keeps views of it).
struct EyeParts {
    std::vector<std::string> outline;  // corner, top, corner, bottom
    const char* eyeball;
    const char* radius_fapu;
    std::string_view clip_id, outline_id, gradient_id;
    std::string_view white, eyeball_group, outline_stroke;
};

// Image sides: left, then right.
const std::vector<EyeParts>& eye_parts() {
    static const std::vector<EyeParts> parts{
        {{"3.12", "3.2", "3.8", "3.4"}, "EyeballLeft", "r1", "tf-eye-left-clip", "tf-eye-left",
         "tf-iris-left-gradient", "eye-left-white", "eyeball-left", "eye-left-outline"},
        {{"3.7", "3.1", "3.11", "3.3"}, "EyeballRight", "r2", "tf-eye-right-clip", "tf-eye-right",
         "tf-iris-right-gradient", "eye-right-white", "eyeball-right", "eye-right-outline"}};
    return parts;
}

Path eye_outline(const ProjectedFace& face, const FaceLook& look, const EyeParts& eye) {
    const std::vector<Point2> p = points_of(face, look, eye.outline);
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
void draw_eye_definitions(const ProjectedFace& face, const FaceLook& look, Layer& layer) {
    for (const EyeParts& eye : eye_parts()) {
        // The outline is defined once, in its clip path, and drawn again for the white and the
        // stroke: an animation then moves one path per eye instead of three.
        Definition clip;
        clip.kind = DefinitionKind::clip_path;
        clip.id = eye.clip_id;
        clip.outline_id = eye.outline_id;
        clip.outline = eye_outline(face, look, eye);
        layer.definitions.push_back(std::move(clip));
        Definition gradient;
        gradient.kind = DefinitionKind::radial_gradient;
        gradient.id = eye.gradient_id;
        gradient.gradient = look.iris_gradient;
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

void draw_eyes(const ProjectedFace& face, const FaceLook& look, Layer& layer) {
    for (std::size_t i = 0; i < eye_parts().size(); ++i) {
        const EyeParts& eye = eye_parts()[i];
        const std::size_t clip = 2 * i;
        const std::size_t gradient = 2 * i + 1;
        layer.elements.push_back(reference_shape(eye.white, clip, look.eye_white));
        // Clipped by the eye outline, so a closing lid hides iris and pupil (thesis 6.3.1).
        const Point2 pupil = look.point(face, eye.eyeball);
        const double iris_radius_px = face.face.fapu(eye.radius_fapu);
        const double iris_radius = look.view.scale() * iris_radius_px;
        const double pupil_radius = kPupilToIrisRadius * iris_radius;
        // The light comes from the upper left of the image, whatever the view turns.
        const Point2 light = look.view.apply_to_offset({-0.35 * iris_radius_px, -0.35 * iris_radius_px});
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
        layer.elements.push_back(reference_shape(eye.outline_stroke, clip, look.eye_outline));
    }
}

void draw_mouth(const ProjectedFace& face, const FaceLook& look, Layer& layer) {
    const std::vector<Point2> lips = points_of(face, look, {"8.1", "8.9", "8.4", "8.2", "8.3", "8.10"});
    Path outer;
    outer.move_to(lips[0])
        .arc({lips[0], lips[1], lips[2]})
        .arc({lips[2], lips[3], lips[4]})
        .arc({lips[4], lips[5], lips[0]})
        .close();
    // arc(R, 2.2, S) + arc(S, 2.3, R): R and S sit on the corners 8.4 and 8.3 (SPEC: S = 8.3).
    const std::vector<Point2> inner_points = points_of(face, look, {"R", "2.2", "S", "2.3"});
    Path inner;
    inner.move_to(inner_points[0])
        .arc({inner_points[0], inner_points[1], inner_points[2]})
        .arc({inner_points[2], inner_points[3], inner_points[0]})
        .close();
    layer.elements.push_back(path_shape("lips", std::move(outer), look.lips));
    layer.elements.push_back(path_shape("mouth-opening", std::move(inner), look.mouth_opening));
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

Point2 FaceLook::point(const ProjectedFace& face, std::string_view id) const {
    const auto found = point_index.find(std::string(id));
    return view.apply(found == point_index.end() ? face.point(id) : face.image_xy[found->second]);
}

std::vector<Point2> hair_polygon_in_view(const ProjectedFace& face, const FaceLook& look) {
    std::vector<Point2> polygon = face.hair_polygon();
    for (Point2& point : polygon) point = look.view.apply(point);
    return polygon;
}

FaceLook make_face_look(const ProjectedFace& face, const LayerStyle& style) {
    const FaceColors& colors = face.face.colors();
    const Paint outline = Paint::of(colors.outline);
    const Paint none;
    const double stroke = style.stroke_px;
    FaceLook look;
    look.style = style;
    look.skin = paint_of(Paint::of(colors.skin), outline, stroke);
    look.hair = paint_of(Paint::of(colors.hair), Paint::of(blend(colors.hair, Rgb{}, 0.4)), stroke);
    look.nose = paint_of(none, outline, stroke);
    look.brows = paint_of(Paint::of(colors.brows), Paint::of(colors.brows), 0.5 * stroke);
    look.eye_white = paint_of(Paint::of(colors.eye_white), none, 0.0);
    look.eye_outline = paint_of(none, outline, stroke);
    look.lips = paint_of(Paint::of(colors.lips), outline, stroke);
    look.mouth_opening = paint_of(Paint::of(colors.mouth_inside), outline, 0.6 * stroke);
    look.iris_gradient = iris_gradient(colors.iris);
    for (std::size_t i = 0; i < face.ids.size(); ++i) look.point_index.emplace(face.ids[i], i);
    return look;
}

Layer draw_hair_layer(const ProjectedFace& face, const FaceLook& look) {
    Path outline;
    outline.corner_cut_closed(hair_polygon_in_view(face, look));
    Layer layer;
    layer.elements.push_back(path_shape("hair", std::move(outline), look.hair));
    return layer;
}

Layer draw_face_layer(const ProjectedFace& face, const FaceLook& look) {
    Layer layer;
    draw_eye_definitions(face, look, layer);
    draw_ears(face, look, layer);
    draw_face_contour(face, look, layer);
    draw_nose(face, look, layer);
    draw_eyebrows(face, look, layer);
    draw_eyes(face, look, layer);
    draw_mouth(face, look, layer);
    return layer;
}

}  // namespace talkface::detail

// The hair and face layers: thesis Algorithm 2.2 steps 2-14, with Algorithm 2.3's substitutions
// (contour points past 10 degrees, the nose bridge side) already chosen by project_face().
#include <cmath>
#include <string>
#include <vector>

#include "common/number_format.hpp"
#include "render/curves.hpp"
#include "render/layers.hpp"
#include "render/svg_text.hpp"

namespace talkface::detail {

namespace {

// The pupil's diameter is 1/3 of the iris's (MPEG-4 neutral face).
constexpr double kPupilToIrisRadius = 1.0 / 3.0;

std::vector<Point2> points_of(const ProjectedFace& face, const FaceLook& look,
                              const std::vector<std::string>& ids) {
    std::vector<Point2> points;
    points.reserve(ids.size());
    for (const std::string& id : ids) points.push_back(look.point(face, id));
    return points;
}

std::string path_element(const std::string& data, const std::string& paint_attributes,
                         const std::string& class_name) {
    return "<path" + attribute("class", class_name) + attribute("d", data) + paint_attributes + "/>\n";
}

std::string draw_ears(const ProjectedFace& face, const FaceLook& look) {
    std::string svg;
    // arc(10.8, 10.2, A) as one cubic through the ear's top 10.2 (curves.hpp: rim_segment); the
    // straight edge that closes each ear runs under the face contour, drawn after it.
    const std::vector<std::vector<std::string>> ears{{"10.8", "10.2", "A"}, {"10.7", "10.1", "B"}};
    const char* const names[] = {"ear-left", "ear-right"};
    for (std::size_t i = 0; i < ears.size(); ++i) {
        const std::vector<Point2> points = points_of(face, look, ears[i]);
        PathData path(look.style.decimals);
        path.move_to(points[0]).curves({rim_segment(points[0], points[1], points[2])}).close();
        svg += path_element(path.str(), look.skin, names[i]);
    }
    return svg;
}

std::string draw_face_contour(const ProjectedFace& face, const FaceLook& look) {
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
    PathData upper_path(look.style.decimals);
    upper_path.move_to(points.front()).curves(upper).line_to(jaw_middle);
    PathData jaw_path(look.style.decimals);
    jaw_path.move_to(points[6]).curves(jaw);
    return path_element(upper_path.str(), look.skin, "face-contour") +
           path_element(jaw_path.str(), look.skin, "jaw");
}

std::string draw_nose(const ProjectedFace& face, const FaceLook& look) {
    // Algorithm 2.3 step 8: the bridge line runs down the side of the nose that faces the viewer.
    const std::vector<std::string> bridge = face.nose_bridge == NoseBridgeSide::right
                                                ? std::vector<std::string>{"9.7", "C", "9.13"}
                                                : std::vector<std::string>{"9.6", "C", "9.14"};
    const std::vector<std::vector<std::string>> arcs{
        bridge, {"9.14", "9.2", "9.4"}, {"9.13", "9.1", "9.5"}, {"D", "9.15", "E"}};
    PathData path(look.style.decimals);
    for (const auto& ids : arcs) {
        const std::vector<Point2> points = points_of(face, look, ids);
        path.move_to(points.front()).arc(points);
    }
    return path_element(path.str(), look.nose, "nose");
}

std::string draw_eyebrows(const ProjectedFace& face, const FaceLook& look) {
    // Corner-cut arc(4.6, 4.4a, 4.4, 4.2) and arc(4.2, G, F, 4.6): one closed outline per brow.
    const std::vector<std::vector<std::string>> brows{{"4.6", "4.4a", "4.4", "4.2", "G", "F"},
                                                      {"4.5", "4.3a", "4.3", "4.1", "H", "I"}};
    const char* const names[] = {"eyebrow-left", "eyebrow-right"};
    std::string svg;
    for (std::size_t i = 0; i < brows.size(); ++i) {
        PathData outline(look.style.decimals);
        outline.corner_cut_closed(points_of(face, look, brows[i]));
        svg += "<path" + attribute("class", names[i]) + attribute("d", outline.str()) + look.brows + "/>\n";
    }
    return svg;
}

struct EyeParts {
    const char* side;                  // "left" or "right", image sides
    std::vector<std::string> outline;  // corner, top, corner, bottom
    const char* eyeball;
    const char* radius_fapu;
};

const std::vector<EyeParts>& eye_parts() {
    static const std::vector<EyeParts> parts{
        {"left", {"3.12", "3.2", "3.8", "3.4"}, "EyeballLeft", "r1"},
        {"right", {"3.7", "3.1", "3.11", "3.3"}, "EyeballRight", "r2"}};
    return parts;
}

std::string eye_outline_data(const ProjectedFace& face, const FaceLook& look, const EyeParts& eye) {
    const std::vector<Point2> p = points_of(face, look, eye.outline);
    PathData path(look.style.decimals);
    path.move_to(p[0]).arc({p[0], p[1], p[2]}).arc({p[2], p[3], p[0]}).close();
    return path.str();
}

std::string eye_clip_id(const EyeParts& eye) { return std::string("tf-eye-") + eye.side + "-clip"; }
std::string eye_outline_id(const EyeParts& eye) { return std::string("tf-eye-") + eye.side; }
std::string iris_gradient_id(const EyeParts& eye) {
    return std::string("tf-iris-") + eye.side + "-gradient";
}

// Light from the upper left, darker rim: the eyes of thesis Figure 6.5.
std::string iris_gradient(const EyeParts& eye, Rgb iris) {
    return "<radialGradient" + attribute("id", iris_gradient_id(eye)) +
           " cx=\"0.4\" cy=\"0.4\" r=\"0.6\">\n" + "<stop offset=\"0\"" +
           attribute("stop-color", to_hex(blend(iris, Rgb{0xff, 0xff, 0xff}, 0.45))) + "/>\n" +
           "<stop offset=\"0.6\"" + attribute("stop-color", to_hex(iris)) + "/>\n" + "<stop offset=\"1\"" +
           attribute("stop-color", to_hex(blend(iris, Rgb{}, 0.5))) + "/>\n</radialGradient>\n";
}

std::string draw_eye_defs(const ProjectedFace& face, const FaceLook& look) {
    std::string svg;
    for (std::size_t i = 0; i < eye_parts().size(); ++i) {
        const EyeParts& eye = eye_parts()[i];
        // The outline is written once, here, and <use>d for the white and the stroke: an animation
        // then moves one path per eye instead of three.
        svg += "<clipPath" + attribute("id", eye_clip_id(eye)) + ">\n<path" +
               attribute("id", eye_outline_id(eye)) + attribute("d", eye_outline_data(face, look, eye)) +
               "/>\n</clipPath>\n";
        svg += look.iris_gradients[i];
    }
    return svg;
}

std::string circle(Point2 centre, double radius, const std::string& fill, int decimals) {
    return "<circle" + attribute("cx", format_fixed(centre.x, decimals)) +
           attribute("cy", format_fixed(centre.y, decimals)) +
           attribute("r", format_fixed(radius, decimals)) + attribute("fill", fill) + "/>\n";
}

std::string draw_eyes(const ProjectedFace& face, const FaceLook& look) {
    std::string svg;
    for (const EyeParts& eye : eye_parts()) {
        const std::string outline = attribute("xlink:href", "#" + eye_outline_id(eye));
        svg += "<use" + attribute("class", std::string("eye-") + eye.side + "-white") + outline +
               look.eye_white + "/>\n";
        // Clipped by the eye outline, so a closing lid hides iris and pupil (thesis 6.3.1).
        const Point2 pupil = look.point(face, eye.eyeball);
        const double iris_radius_px = face.face.fapu(eye.radius_fapu);
        const double iris_radius = look.view.scale() * iris_radius_px;
        const double pupil_radius = kPupilToIrisRadius * iris_radius;
        // The light comes from the upper left of the image, whatever the view turns.
        const Point2 light = look.view.apply_to_offset({-0.35 * iris_radius_px, -0.35 * iris_radius_px});
        const Point2 highlight{pupil.x + light.x, pupil.y + light.y};
        const int decimals = look.style.decimals;
        svg += "<g" + attribute("class", std::string("eyeball-") + eye.side) +
               attribute("clip-path", "url(#" + eye_clip_id(eye) + ")") + ">\n" +
               circle(pupil, iris_radius, "url(#" + iris_gradient_id(eye) + ")", decimals) +
               circle(pupil, pupil_radius, "#111111", decimals) +
               circle(highlight, 0.5 * pupil_radius, "#ffffff", decimals) + "</g>\n";
        svg += "<use" + attribute("class", std::string("eye-") + eye.side + "-outline") + outline +
               look.eye_outline + "/>\n";
    }
    return svg;
}

std::string draw_mouth(const ProjectedFace& face, const FaceLook& look) {
    const std::vector<Point2> lips = points_of(face, look, {"8.1", "8.9", "8.4", "8.2", "8.3", "8.10"});
    PathData outer(look.style.decimals);
    outer.move_to(lips[0])
        .arc({lips[0], lips[1], lips[2]})
        .arc({lips[2], lips[3], lips[4]})
        .arc({lips[4], lips[5], lips[0]})
        .close();
    // arc(R, 2.2, S) + arc(S, 2.3, R): R and S sit on the corners 8.4 and 8.3 (SPEC: S = 8.3).
    const std::vector<Point2> inner_points = points_of(face, look, {"R", "2.2", "S", "2.3"});
    PathData inner(look.style.decimals);
    inner.move_to(inner_points[0])
        .arc({inner_points[0], inner_points[1], inner_points[2]})
        .arc({inner_points[2], inner_points[3], inner_points[0]})
        .close();
    return path_element(outer.str(), look.lips, "lips") +
           path_element(inner.str(), look.mouth_opening, "mouth-opening");
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
    const std::string outline = to_hex(colors.outline);
    FaceLook look;
    look.style = style;
    look.skin = paint(to_hex(colors.skin), outline, style.stroke_px, style.decimals);
    look.hair =
        paint(to_hex(colors.hair), to_hex(blend(colors.hair, Rgb{}, 0.4)), style.stroke_px, style.decimals);
    look.nose = paint("none", outline, style.stroke_px, style.decimals);
    const std::string brow_colour = to_hex(colors.brows);
    look.brows = paint(brow_colour, brow_colour, 0.5 * style.stroke_px, style.decimals);
    look.eye_white = paint(to_hex(colors.eye_white), "none", 0.0, style.decimals);
    look.eye_outline = paint("none", outline, style.stroke_px, style.decimals);
    look.lips = paint(to_hex(colors.lips), outline, style.stroke_px, style.decimals);
    look.mouth_opening = paint(to_hex(colors.mouth_inside), outline, 0.6 * style.stroke_px, style.decimals);
    for (std::size_t i = 0; i < eye_parts().size(); ++i)
        look.iris_gradients[i] = iris_gradient(eye_parts()[i], colors.iris);
    for (std::size_t i = 0; i < face.ids.size(); ++i) look.point_index.emplace(face.ids[i], i);
    return look;
}

std::string draw_hair_layer(const ProjectedFace& face, const FaceLook& look) {
    PathData outline(look.style.decimals);
    outline.corner_cut_closed(hair_polygon_in_view(face, look));
    return "<path" + attribute("class", "hair") + attribute("d", outline.str()) + look.hair + "/>\n";
}

std::string draw_face_layer(const ProjectedFace& face, const FaceLook& look) {
    return "<defs>\n" + draw_eye_defs(face, look) + "</defs>\n" + draw_ears(face, look) +
           draw_face_contour(face, look) + draw_nose(face, look) + draw_eyebrows(face, look) +
           draw_eyes(face, look) + draw_mouth(face, look);
}

}  // namespace talkface::detail

// Live2D Cubism motion (.motion3.json, Live2D's CubismSpecs FileFormats/motion3.json.md): one
// curve per standard parameter, linear segments, times in seconds.
//   ParamMouthOpenY, ParamMouthForm  from the mouth key frames: a point on each, the table below
//   ParamEyeLOpen, ParamEyeROpen     1 - blink, per frame (Cubism's L is the character's left: the
//                                    image-right eye, talkface's blink_right)
//   ParamBrowLY, ParamBrowRY         the eyebrow raise, 0..1, per frame
//   ParamAngleX, ParamAngleY, ParamAngleZ  head turn, nod and tilt in degrees, per frame:
//                                    AngleX = -beta (> 0 towards the image right), AngleY = -alpha
//                                    (> 0 looking up: talkface's nod down is alpha > 0), AngleZ = gamma
// Per-frame curves keep only the points that a straight line through their neighbours would miss,
// so a still face costs two points. Lossy: the mouth is two numbers, not a shape.
#include <cmath>
#include <string>
#include <vector>

#include "common/number_format.hpp"
#include "talkface/errors.hpp"
#include "timing/export_writers.hpp"

namespace talkface::detail {

namespace {

struct Point {
    double time_s;
    double value;
};

struct Curve {
    const char* id;
    std::vector<Point> points;
};

// How far each shape opens the mouth (0..1) and how it shapes the corners (-1 pursed .. 1
// spread), from its formulas (thesis 5.2.2, SPEC "Mouth shapes"): opening = the upper and lower
// lips' moves in MNS0 over a's 1.1; form = the corners' horizontal move over the most (0.2 MW0).
struct MouthParameters {
    double open;
    double form;
};

MouthParameters mouth_parameters(MouthShape shape) {
    switch (shape) {
        case MouthShape::m: return {0.0, 0.0};
        case MouthShape::f: return {0.0, 0.0};
        case MouthShape::h_prime: return {0.5, 0.0};
        case MouthShape::h: return {0.68, -0.42};
        case MouthShape::r: return {0.45, -0.75};
        case MouthShape::z: return {0.27, 0.0};
        case MouthShape::a: return {1.0, -0.62};
        case MouthShape::i: return {0.15, 0.42};
        case MouthShape::u: return {0.55, -1.0};
        case MouthShape::e: return {0.45, 0.42};
        case MouthShape::o: return {0.82, -1.0};
        case MouthShape::n: return {0.64, 0.0};
    }
    return {0.0, 0.0};
}

// Drops each point that lies within 1e-4 of the line through the points kept before and after it.
std::vector<Point> simplified(const std::vector<Point>& points) {
    if (points.size() < 3) return points;
    std::vector<Point> kept{points.front()};
    for (std::size_t k = 1; k + 1 < points.size(); ++k) {
        const Point& before = kept.back();
        const Point& after = points[k + 1];
        const double u = (points[k].time_s - before.time_s) / (after.time_s - before.time_s);
        const double on_line = before.value + u * (after.value - before.value);
        if (std::abs(points[k].value - on_line) > 1e-4) kept.push_back(points[k]);
    }
    kept.push_back(points.back());
    return kept;
}

// A curve from 0 to end_s: a point per key, then the last value held to the end.
std::vector<Point> spanning(std::vector<Point> points, double end_s) {
    if (points.empty() || points.front().time_s > 0.0) {
        points.insert(points.begin(), {0.0, points.empty() ? 0.0 : points.front().value});
    }
    while (points.size() > 1 && points.back().time_s > end_s) points.pop_back();
    if (points.back().time_s < end_s) points.push_back({end_s, points.back().value});
    return points;
}

std::string number(double value) { return format_fixed(value, 4); }

}  // namespace

std::string live2d_motion(const ExportInput& input) {
    const double end_s = input.timeline.duration_s;
    if (input.frames.empty()) {
        throw InvalidArgument("frames", "a Live2D motion needs the face of every frame (Animation::frames), found none");
    }
    std::vector<Point> open;
    std::vector<Point> form;
    for (const MouthKeyFrame& key_frame : input.mouth_key_frames) {
        if (key_frame.time_s > end_s) break;
        const MouthParameters parameters = mouth_parameters(key_frame.shape);
        open.push_back({key_frame.time_s, parameters.open});
        form.push_back({key_frame.time_s, parameters.form});
    }
    std::vector<Curve> curves{{"ParamMouthOpenY", spanning(open, end_s)}, {"ParamMouthForm", spanning(form, end_s)}};
    const auto per_frame = [&](const char* id, double (*value)(const FaceState&)) {
        std::vector<Point> points;
        for (std::size_t i = 0; i < input.frames.size(); ++i) {
            points.push_back({static_cast<double>(i) / input.fps, value(input.frames[i])});
        }
        curves.push_back({id, simplified(spanning(points, end_s))});
    };
    per_frame("ParamEyeLOpen", [](const FaceState& s) { return 1.0 - s.expression.blink_right; });
    per_frame("ParamEyeROpen", [](const FaceState& s) { return 1.0 - s.expression.blink_left; });
    per_frame("ParamBrowLY", [](const FaceState& s) { return s.expression.brows; });
    per_frame("ParamBrowRY", [](const FaceState& s) { return s.expression.brows; });
    per_frame("ParamAngleX", [](const FaceState& s) { return -s.pose.beta_deg; });
    per_frame("ParamAngleY", [](const FaceState& s) { return -s.pose.alpha_deg; });
    per_frame("ParamAngleZ", [](const FaceState& s) { return s.pose.gamma_deg; });

    std::size_t segment_count = 0;
    std::size_t point_count = 0;
    std::string curves_json;
    for (std::size_t c = 0; c < curves.size(); ++c) {
        const std::vector<Point>& points = curves[c].points;
        // The first point, then a linear segment (identifier 0) to each next point.
        std::string segments = number(points[0].time_s) + ", " + number(points[0].value);
        for (std::size_t k = 1; k < points.size(); ++k) {
            segments += ", 0, " + number(points[k].time_s) + ", " + number(points[k].value);
        }
        segment_count += points.size() - 1;
        point_count += points.size();
        curves_json += std::string(c == 0 ? "" : ",\n") + "    {\n      \"Target\": \"Parameter\",\n      \"Id\": \"" +
                       curves[c].id + "\",\n      \"Segments\": [" + segments + "]\n    }";
    }
    return "{\n  \"Version\": 3,\n  \"Meta\": {\n    \"Duration\": " + number(end_s) + ",\n    \"Fps\": " +
           number(input.fps) + ",\n    \"Loop\": false,\n    \"AreBeziersRestricted\": true,\n    \"CurveCount\": " +
           std::to_string(curves.size()) + ",\n    \"TotalSegmentCount\": " + std::to_string(segment_count) +
           ",\n    \"TotalPointCount\": " + std::to_string(point_count) +
           ",\n    \"UserDataCount\": 0,\n    \"TotalUserDataSize\": 0\n  },\n  \"Curves\": [\n" + curves_json +
           "\n  ]\n}\n";
}

}  // namespace talkface::detail

// The 3D lift (SPEC pipeline step 2): thesis Algorithm 2.1 and Table 2.1, with SPEC's corrections.
#include "talkface/face_lift.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "common/number_format.hpp"
#include "face/point_ids.hpp"
#include "lift/lifted_point_index.hpp"
#include "lift/local_frame.hpp"
#include "talkface/errors.hpp"

namespace talkface {
inline namespace v0 {

namespace {

// Table 2.1, in units of d, grouped as the thesis prints it; hair points are apart (all -0.58 d).
// clang-format off
const std::pair<const char*, double> kDepthTable[] = {
    // eyes
    {"3.2", 1.33}, {"3.4", 1.33}, {"3.1", 1.33}, {"3.3", 1.33}, {"EyeballLeft", 1.33}, {"EyeballRight", 1.33},
    {"3.12", 1.19}, {"3.7", 1.19}, {"3.8", 1.25}, {"3.11", 1.25},
    // eyebrows
    {"4.6", 1.17}, {"4.5", 1.17}, {"4.4a", 1.30}, {"4.3a", 1.30}, {"F", 1.30}, {"I", 1.30},
    {"4.4", 1.44}, {"4.3", 1.44}, {"G", 1.44}, {"H", 1.44}, {"4.2", 1.49}, {"4.1", 1.49},
    // mouth
    {"2.2", 1.55}, {"2.3", 1.55}, {"8.4", 1.40}, {"8.3", 1.40}, {"R", 1.40}, {"S", 1.40},
    {"8.1", 1.60}, {"8.9", 1.60}, {"8.10", 1.60}, {"8.2", 1.56},
    // jaw
    {"2.14", 0.36}, {"2.13", 0.36}, {"2.1", 1.33}, {"J", 1.18}, {"K", 1.18},
    // forehead
    {"11.1", 1.37}, {"11.2a", 0.90}, {"11.3a", 0.90}, {"11.2", 0.42}, {"11.3", 0.42},
    {"N", 0.85}, {"Q", 0.85},
    // ears
    {"10.2", -0.37}, {"10.1", -0.37}, {"10.8", 0.0}, {"10.7", 0.0}, {"A", 0.04}, {"B", 0.04},
    // nose
    {"9.6", 1.39}, {"9.7", 1.39}, {"9.2", 1.39}, {"9.1", 1.39}, {"9.14", 1.40}, {"9.13", 1.40},
    {"9.4", 1.44}, {"9.5", 1.44}, {"9.15", 1.65}, {"C", 1.51}, {"D", 1.53}, {"E", 1.53},
    // cheeks
    {"10.9", 0.27}, {"10.10", 0.27}, {"L", 1.11}, {"M", 1.11}};
// clang-format on

constexpr double kHairDepthInD = -0.58;
// Algorithm 2.1 step 3: the neck centre lies 1.3 d below EyeMid.
constexpr double kOriginBelowEyeMidInD = 1.3;

bool is_hair_id(std::string_view id) {
    return id.substr(0, 5) == "hair." && FaceModel::is_point_id(id);
}

double checked_d(const FaceModel& face) {
    const double d = face.fapus()[detail::kFapuD];
    if (!(std::isfinite(d) && d > 0.0)) {
        throw InvalidArgument(
            "FAPU \"d\"", "must be finite and positive to lift a face, got " + detail::format_shortest(d));
    }
    return d;
}

Point2 eye_mid(const FaceModel& face) {
    constexpr std::size_t kLeft = detail::point_at("EyeballLeft"), kRight = detail::point_at("EyeballRight");
    const Point2 left = face.points()[kLeft];
    const Point2 right = face.points()[kRight];
    return {(left.x + right.x) / 2.0, (left.y + right.y) / 2.0};
}

// Algorithm 2.1 step 4, in image pixels, in additional_point_ids() order.
std::vector<Point2> additional_points_image(const FaceModel& face, Point2 eye_mid_xy) {
    // Every frame lifts its face: its points are read at indices found when this is compiled.
    using detail::point_at;
    constexpr std::size_t k10_8 = point_at("10.8"), k10_7 = point_at("10.7"), k10_2 = point_at("10.2"),
                          k10_1 = point_at("10.1"), k9_13 = point_at("9.13"), k9_14 = point_at("9.14"),
                          k9_4 = point_at("9.4"), k9_5 = point_at("9.5"), k4_4a = point_at("4.4a"),
                          k4_4 = point_at("4.4"), k4_3 = point_at("4.3"), k4_3a = point_at("4.3a"),
                          k2_14 = point_at("2.14"), k2_1 = point_at("2.1"), k2_13 = point_at("2.13"),
                          k3_12 = point_at("3.12"), k10_10 = point_at("10.10"), k3_7 = point_at("3.7"),
                          k10_9 = point_at("10.9"), k11_2 = point_at("11.2"), k11_3 = point_at("11.3"),
                          k8_4 = point_at("8.4"), k8_3 = point_at("8.3");
    const auto& p = face.points();
    const double eyebrow_h = face.fapus()[detail::kFapuEyebrowH];
    const double eyebrow_h2 = face.fapus()[detail::kFapuEyebrowH2];
    // W_ear is "the distance between EyeMid and an ear". Table 2.1 puts A in front of the lobe's
    // contact point 10.8 (0.04 d against 0) and far in front of the ear's top 10.2 (-0.37 d), so A is
    // where the top of the ear meets the head: W_ear is measured horizontally to the contact points
    // 10.8 / 10.7, per side, and arc(10.8, 10.2, A) then outlines the ear's rim. Measured to 10.2
    // instead, A would sit right under the ear's top and the ear would be drawn as a sliver.
    const double ear_left_w_px = eye_mid_xy.x - p[k10_8].x;
    const double ear_right_w_px = p[k10_7].x - eye_mid_xy.x;
    return {
        {eye_mid_xy.x - ear_left_w_px, (4.0 * p[k10_2].y + p[k10_8].y) / 5.0},              // A
        {eye_mid_xy.x + ear_right_w_px, (4.0 * p[k10_1].y + p[k10_7].y) / 5.0},             // B
        {(p[k9_13].x + p[k9_14].x) / 2.0, (p[k9_14].y + eye_mid_xy.y) / 2.0},               // C
        {(5.0 * p[k9_4].x + p[k9_5].x) / 6.0, p[k9_4].y - (p[k9_4].y - p[k9_14].y) / 3.0},  // D
        {(5.0 * p[k9_5].x + p[k9_4].x) / 6.0, p[k9_5].y - (p[k9_5].y - p[k9_13].y) / 3.0},  // E
        {p[k4_4a].x, p[k4_4a].y + eyebrow_h2 / 1.3},                                        // F
        {p[k4_4].x, p[k4_4].y + eyebrow_h / 1.3},                                           // G
        {p[k4_3].x, p[k4_3].y + eyebrow_h / 1.3},                                           // H
        {p[k4_3a].x, p[k4_3a].y + eyebrow_h2 / 1.3},                                        // I
        {(5.0 * p[k2_14].x + p[k2_1].x) / 6.0, p[k2_14].y},                                 // J
        {(5.0 * p[k2_13].x + p[k2_1].x) / 6.0, p[k2_13].y},                                 // K
        {(p[k3_12].x + p[k10_10].x) / 2.0, p[k10_10].y},                                    // L
        {(p[k3_7].x + p[k10_9].x) / 2.0, p[k10_9].y},                                       // M
        p[k11_2],                                                                           // N
        p[k11_3],                                                                           // Q
        p[k8_4],                                                                            // R
        // SPEC: S is 8.3; the thesis prints 8.5, which is not a point of the model.
        p[k8_3],  // S
    };
}

}  // namespace

Point3 LiftedFace::local(std::string_view id) const {
    const auto found =
        std::find_if(points.begin(), points.end(), [&](const LiftedPoint& point) { return point.id == id; });
    if (found == points.end()) {
        throw InvalidArgument("point \"" + std::string(id) + "\"",
                              "not a point of the lifted face (the 72 model points and A .. S)");
    }
    return found->local;
}

const std::vector<std::string>& additional_point_ids() {
    static const std::vector<std::string> ids(detail::kAdditionalPointIds.begin(),
                                              detail::kAdditionalPointIds.end());
    return ids;
}

double depth_in_d(std::string_view id) {
    if (is_hair_id(id)) return kHairDepthInD;
    for (const auto& [table_id, depth] : kDepthTable) {
        if (id == table_id) return depth;
    }
    throw InvalidArgument("point \"" + std::string(id) + "\"",
                          "no depth in Table 2.1: not one of the 72 model points or A .. S");
}

Point2 rotation_origin(const FaceModel& face) {
    const double d = checked_d(face);
    const Point2 mid = eye_mid(face);
    return {mid.x, mid.y + d * kOriginBelowEyeMidInD};
}

LiftedFace lift_face(const FaceModel& face) {
    // Table 2.1 in lifted order (the 72 model ids, then A .. S), looked up once rather than by id for
    // every point of every frame.
    static const std::vector<double> depths = [] {
        std::vector<double> table;
        for (const std::string& id : FaceModel::point_ids()) table.push_back(depth_in_d(id));
        for (const std::string& id : additional_point_ids()) table.push_back(depth_in_d(id));
        return table;
    }();
    LiftedFace lifted;
    lifted.d = checked_d(face);
    lifted.origin = rotation_origin(face);
    const auto& model_ids = FaceModel::point_ids();
    const auto& extra_ids = additional_point_ids();
    lifted.points.reserve(model_ids.size() + extra_ids.size());
    for (std::size_t i = 0; i < model_ids.size(); ++i) {
        lifted.points.push_back(
            {model_ids[i], detail::to_local(face.points()[i], depths[i] * lifted.d, lifted.origin)});
    }
    const std::vector<Point2> extra_xy = additional_points_image(face, eye_mid(face));
    for (std::size_t i = 0; i < extra_ids.size(); ++i) {
        lifted.points.push_back(
            {extra_ids[i],
             detail::to_local(extra_xy[i], depths[model_ids.size() + i] * lifted.d, lifted.origin)});
    }
    return lifted;
}

FaceModel place_face(const FaceModel& face, Point2 origin, double d_px) {
    if (!(std::isfinite(d_px) && d_px > 0.0)) {
        throw InvalidArgument("d_px", "must be finite and positive, got " + detail::format_shortest(d_px));
    }
    if (!(std::isfinite(origin.x) && std::isfinite(origin.y))) {
        throw InvalidArgument("origin", "coordinates must be finite");
    }
    const Point2 old_origin = rotation_origin(face);
    const double scale = d_px / face.fapu("d");
    FaceModel placed = face;
    const auto& ids = FaceModel::point_ids();
    for (std::size_t i = 0; i < ids.size(); ++i) {
        const Point2 p = face.points()[i];
        placed.set_point(ids[i],
                         {origin.x + (p.x - old_origin.x) * scale, origin.y + (p.y - old_origin.y) * scale});
    }
    for (const std::string& name : FaceModel::fapu_names()) {
        placed.set_fapu(name, name == "d" ? d_px : face.fapu(name) * scale);
    }
    return placed;
}

}  // namespace v0
}  // namespace talkface

namespace talkface::detail {

std::optional<std::size_t> lifted_point_index(std::string_view id) {
    const auto found = std::find(kLiftedPointIds.begin(), kLiftedPointIds.end(), id);
    if (found == kLiftedPointIds.end()) return std::nullopt;
    return static_cast<std::size_t>(found - kLiftedPointIds.begin());
}

}  // namespace talkface::detail

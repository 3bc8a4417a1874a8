// A face at a pose (thesis Algorithm 2.3 with SPEC's corrections): expression and mouth, 3D lift, hair
// depth shift, rotation, gaze hold, orthographic projection, contour substitution.
#include "talkface/face_pose.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "common/number_format.hpp"
#include "common/string_ends.hpp"
#include "face/point_ids.hpp"
#include "lift/local_frame.hpp"
#include "pose/contour_sides.hpp"
#include "talkface/errors.hpp"
#include "talkface/face_lift.hpp"
#include "talkface/rotation3d.hpp"

namespace talkface {
inline namespace v0 {

namespace {

// Algorithm 2.3 steps 5-6: past this turn the receding side's contour points are hidden.
constexpr double kContourSwapDeg = 10.0;
// Thesis 2.4.3.2: the eyeball radius and the focus distance, in units of d.
constexpr double kEyeballRadiusD = 0.3;
constexpr double kFocusDepthD = 15.0;
// Algorithm 2.3 steps 1-2 shift the hair's depth "by a constant multiple of d according to x and
// beta" without giving it (SPEC: choose a smooth rule). At a full turn the outermost hair point on the
// side the face turns towards comes forward by this many d; see hair_depth_shift(). Tuned on the
// default and sample faces at beta = 15: the hair beside the temple narrows from 29.5 to 21 px on the
// default face, as the side of a turning head should, where no shift would leave 4.5 px and let the
// sample male face's forehead poke through its hair.
constexpr double kHairShiftD = 1.0;

struct Vec3 {
    double x, y, z;
};

Vec3 operator+(Vec3 a, Vec3 b) {
    return {a.x + b.x, a.y + b.y, a.z + b.z};
}
Vec3 operator-(Vec3 a, Vec3 b) {
    return {a.x - b.x, a.y - b.y, a.z - b.z};
}
Vec3 operator*(double s, Vec3 a) {
    return {s * a.x, s * a.y, s * a.z};
}
Vec3 unit(Vec3 a) {
    return (1.0 / std::sqrt(a.x * a.x + a.y * a.y + a.z * a.z)) * a;
}
Vec3 to_vec(Point3 p) {
    return {p.x, p.y, p.z};
}
Point3 to_point(Vec3 v) {
    return {v.x, v.y, v.z};
}

void require_pose_angle(double angle_deg, const char* field) {
    if (!std::isfinite(angle_deg) || std::abs(angle_deg) > kMaxPoseAngleDeg) {
        const std::string limit = detail::format_shortest(kMaxPoseAngleDeg);
        throw InvalidArgument(field, "got " + detail::format_shortest(angle_deg) +
                                         " degrees; a head pose angle must be within -" + limit + ".." +
                                         limit + " degrees (thesis 1.3.2)");
    }
}

bool is_hair_id(const std::string& id) {
    return detail::starts_with(id, "hair.");
}

double smoothstep(double t) {
    const double clamped = std::clamp(t, 0.0, 1.0);
    return clamped * clamped * (3.0 - 2.0 * clamped);
}

// The hair lies flat at -0.58 d (Table 2.1), behind the face contour. Turning the head moves that
// flat sheet sideways less than the rounded face in front of it on the side the face turns towards
// (local +x for beta > 0), so the hair outline would slip inside the face contour there (thesis
// Figure 2.17). Bringing those hair points forward makes the turn push them outward with the face.
// The shift grows smoothly from 0 at the face's centre line to kHairShiftD * d at the hair's widest
// point, and linearly with |beta|; it is continuous in beta (0 at beta = 0 on both sides) and mirror
// symmetric: shift(x, beta) = shift(-x, -beta). The thesis also selects points by their height
// against EyeMid (which side is unclear in its mixed frames); this rule depends on x alone, and the
// smoothstep leaves the crown, near the centre line, almost in place without a jump at any height.
double hair_depth_shift(double local_x, double hair_half_width, double beta_deg, double d) {
    const double towards_turn_x = beta_deg > 0.0 ? local_x : -local_x;
    if (towards_turn_x <= 0.0 || hair_half_width <= 0.0) return 0.0;
    return kHairShiftD * d * (std::abs(beta_deg) / kMaxPoseAngleDeg) *
           smoothstep(towards_turn_x / hair_half_width);
}

// Thesis 2.4.3.2: the eyeball centre sits one radius behind the pupil, on the line to the focus;
// it turns with the head, and the pupil is put back on the line from the turned centre to the focus,
// which does not turn.
Vec3 gazing_pupil(Vec3 pupil, Vec3 focus, const Rotation3D& rotation, double radius) {
    const Vec3 centre = pupil - radius * unit(focus - pupil);
    const Vec3 turned_centre = to_vec(rotation.rotate(to_point(centre)));
    return turned_centre + radius * unit(focus - turned_centre);
}

}  // namespace

Point2 ProjectedFace::point(std::string_view id) const {
    const auto found = std::find_if(points.begin(), points.end(),
                                    [&](const ProjectedPoint& point) { return point.id == id; });
    if (found == points.end()) {
        throw InvalidArgument("point \"" + std::string(id) + "\"",
                              "no such point in a projected face; expected one of the 72 model ids "
                              "(FaceModel::point_ids()) or A .. S");
    }
    return found->xy;
}

std::vector<Point2> ProjectedFace::hair_polygon() const {
    std::vector<Point2> polygon;
    for (const ProjectedPoint& point : points) {
        if (is_hair_id(point.id)) polygon.push_back(point.xy);
    }
    return polygon;
}

ProjectedFace project_face(const FaceModel& neutral, const FaceState& state) {
    const Pose& pose = state.pose;
    require_pose_angle(pose.alpha_deg, "pose.alpha_deg");
    require_pose_angle(pose.beta_deg, "pose.beta_deg");
    require_pose_angle(pose.gamma_deg, "pose.gamma_deg");
    const Rotation3D rotation(pose.alpha_deg, pose.beta_deg, pose.gamma_deg);

    FaceModel face2d = apply_expression(
        apply_mouth(neutral, state.mouth.value_or(neutral_mouth_controls(neutral))), state.expression);
    LiftedFace lifted = lift_face(face2d);
    const double d = lifted.d;

    // Points are told apart by index, not id, as this runs once a frame: FaceModel order puts the hair
    // first (face/point_ids.hpp), and lift_face() keeps that order.
    double hair_half_width = 0.0;
    for (std::size_t i = 0; i < detail::kHairPointCount; ++i) {
        hair_half_width = std::max(hair_half_width, std::abs(lifted.points[i].local.x));
    }
    constexpr std::size_t eyeball_left_index = detail::point_at("EyeballLeft");
    constexpr std::size_t eyeball_right_index = detail::point_at("EyeballRight");

    const Point2 eyeball_left = face2d.points()[eyeball_left_index];
    const Point2 eyeball_right = face2d.points()[eyeball_right_index];
    const Point2 eye_mid{(eyeball_left.x + eyeball_right.x) / 2.0, (eyeball_left.y + eyeball_right.y) / 2.0};
    const Vec3 focus = to_vec(detail::to_local(eye_mid, kFocusDepthD * d, lifted.origin));
    const Rotation3D identity;

    ProjectedFace projected;
    projected.points.reserve(lifted.points.size());
    for (std::size_t i = 0; i < lifted.points.size(); ++i) {
        const Vec3 local = to_vec(lifted.points[i].local);
        // Each point moves by (where the pose puts it) - (where the frontal face has it), added to its
        // frontal image position. At zero angles the rotation is the identity bit for bit and both gaze
        // computations are the same arithmetic, so the move is exactly 0 and the frontal face comes
        // out exactly as Algorithm 2.2 draws it, whatever rounding the local frame's round trip or
        // the gaze's unit vectors carry.
        Vec3 move_local{0.0, 0.0, 0.0};
        if (i == eyeball_left_index || i == eyeball_right_index) {
            const double radius = kEyeballRadiusD * d;
            move_local =
                gazing_pupil(local, focus, rotation, radius) - gazing_pupil(local, focus, identity, radius);
        } else {
            Vec3 shifted = local;
            if (i < detail::kHairPointCount) shifted.z += hair_depth_shift(local.x, hair_half_width, pose.beta_deg, d);
            move_local = to_vec(rotation.rotate(to_point(shifted))) - local;
        }
        // lift_face() lists the 72 model points first, in FaceModel order.
        const Point2 frontal = i < FaceModel::kPointCount
                                   ? face2d.points()[i]
                                   : detail::to_image(lifted.points[i].local, lifted.origin);
        // to_image: x = x_o - x', y = y_o - y', so a local move shows up negated in the image.
        projected.points.push_back(
            {std::move(lifted.points[i].id), Point2{frontal.x - move_local.x, frontal.y - move_local.y}});
    }

    // Algorithm 2.3 steps 5-6, in SPEC's un-mirrored frame. The thesis's local-to-global formula
    // (x = x_p + x_o) mirrors the face, so its steps swap sides here: beta > 0 turns our face towards
    // the image left, that side's contour points (11.2, 10.10, 2.14, depth 0.27-0.42 d) slip behind
    // the cheek, and N, L, J (0.85-1.18 d) become the silhouette; beta < 0 mirrors it.
    if (pose.beta_deg > kContourSwapDeg) projected.left_contour = detail::kLeftContourTurned.id_strings();
    if (pose.beta_deg < -kContourSwapDeg) projected.right_contour = detail::kRightContourTurned.id_strings();
    // Algorithm 2.3 step 8, in the same un-mirrored frame: the thesis draws the bridge from 9.7 when
    // beta > 0 in its mirrored frame, which is our beta < 0; otherwise the frontal bridge from 9.6.
    projected.nose_bridge = pose.beta_deg < 0.0 ? NoseBridgeSide::right : NoseBridgeSide::left;
    projected.origin = lifted.origin;
    projected.d = d;
    projected.face = std::move(face2d);
    return projected;
}

}  // namespace v0

namespace detail {

std::array<std::size_t, 3> contour_indices(const std::array<std::string, 3>& side) {
    for (const ContourSide* known : {&kLeftContour, &kLeftContourTurned, &kRightContour, &kRightContourTurned}) {
        if (std::equal(side.begin(), side.end(), known->ids.begin())) return known->indices;
    }
    std::array<std::size_t, 3> indices{};
    for (std::size_t k = 0; k < side.size(); ++k) {
        const std::optional<std::size_t> index = lifted_point_index(side[k]);
        if (!index) {
            throw InvalidArgument("contour point \"" + side[k] + "\"",
                                  "not a point of a projected face; expected one of the 72 model ids "
                                  "(FaceModel::point_ids()) or A .. S");
        }
        indices[k] = *index;
    }
    return indices;
}

}  // namespace detail
}  // namespace talkface

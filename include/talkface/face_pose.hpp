// talkface: a face at a pose, with an expression and a mouth, projected to the image
// (thesis Algorithms 2.2 and 2.3, with SPEC's corrections).
#ifndef TALKFACE_FACE_POSE_HPP
#define TALKFACE_FACE_POSE_HPP

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "talkface/export.h"
#include "talkface/expression.hpp"
#include "talkface/face_model.hpp"
#include "talkface/mouth_controls.hpp"
#include "talkface/types.hpp"

namespace talkface {
inline namespace v0 {

/// The largest head rotation about any axis, degrees (thesis 1.3.2).
inline constexpr double kMaxPoseAngleDeg = 15.0;

/// A head pose in degrees; see Rotation3D for the axes and signs.
struct Pose {
    double alpha_deg = 0.0;  ///< about X: nod (> 0 down)
    double beta_deg = 0.0;   ///< about Y: turn (> 0 towards the image left)
    double gamma_deg = 0.0;  ///< about Z: tilt
    friend bool operator==(const Pose& a, const Pose& b) {
        return a.alpha_deg == b.alpha_deg && a.beta_deg == b.beta_deg && a.gamma_deg == b.gamma_deg;
    }
    friend bool operator!=(const Pose& a, const Pose& b) { return !(a == b); }
};

/// Everything that changes from frame to frame: pose, expression and mouth.
struct FaceState {
    Pose pose;
    Expression expression;
    std::optional<MouthControls> mouth;  ///< nullopt: the neutral mouth
};

/// Which side of the nose the bridge line is drawn from (Algorithm 2.3 step 8).
enum class NoseBridgeSide : int { left = 0, right = 1 };

/// One point of a projected face.
struct ProjectedPoint {
    std::string id;  ///< a model id (FaceModel::point_ids()) or "A" .. "S"
    Point2 xy;       ///< image pixels; the eyeball ids hold the pupils after gaze
};

/// A face drawn at a state: every point in image pixels, ready for a renderer.
struct TALKFACE_API ProjectedFace {
    std::vector<ProjectedPoint> points;  ///< the 72 model points, then "A" .. "S" (as LiftedFace)
    /// The face contour's side points (forehead, cheek, jaw) on each side, after the contour
    /// substitution of Algorithm 2.3 (past 10 degrees the receding side uses N L J or Q M K).
    std::array<std::string, 3> left_contour{"11.2", "10.10", "2.14"};
    std::array<std::string, 3> right_contour{"11.3", "10.9", "2.13"};
    NoseBridgeSide nose_bridge = NoseBridgeSide::left;
    Point2 origin;        ///< rotation origin O, image pixels
    double d = 0.0;       ///< eyeball distance, pixels
    FaceModel face;       ///< the 2D face with expression and mouth applied (before the pose)

    /// A point's image position. \throws talkface::InvalidArgument for an unknown id.
    Point2 point(std::string_view id) const;
    /// The 23 hair points in polygon order.
    std::vector<Point2> hair_polygon() const;
};

/// Projects a face (Algorithm 2.3): expression and mouth applied to the neutral face, lifted, hair
/// depth shifted, rotated (Y, X, Z), gaze held on the focus (EyeMid.x, EyeMid.y, 15 d) with an
/// eyeball radius of 0.3 d, projected orthographically, contour substituted past +-10 degrees.
/// A pure function. \throws talkface::InvalidArgument naming the angle if one is outside
/// +-kMaxPoseAngleDeg or not finite, or an expression amount outside 0..1.
TALKFACE_API ProjectedFace project_face(const FaceModel& neutral, const FaceState& state);

}  // namespace v0
}  // namespace talkface

#endif

// talkface: the 3D lift of a 2D face (thesis Algorithm 2.1 and Table 2.1, with SPEC's corrections).
#ifndef TALKFACE_FACE_LIFT_HPP
#define TALKFACE_FACE_LIFT_HPP

#include <string>
#include <string_view>
#include <vector>

#include "talkface/export.h"
#include "talkface/face_model.hpp"
#include "talkface/types.hpp"

namespace talkface {
inline namespace v0 {

/// One point of a lifted face.
struct LiftedPoint {
    std::string id;  ///< a model id (FaceModel::point_ids()) or "A" .. "S"
    Point3 local;    ///< in the face's local frame (see Point3), pixels
};

/// A face in its local 3D frame: the rotation origin O, the 72 model points and the 17 additional
/// points A..S (A B C D E F G H I J K L M N Q R S), each with a depth from Table 2.1 in units of d.
struct TALKFACE_API LiftedFace {
    Point2 origin;                    ///< O in image pixels: (EyeMid.x, EyeMid.y + 1.3 d)
    double d = 0.0;                   ///< eyeball distance, pixels
    std::vector<LiftedPoint> points;  ///< the 72 model points (FaceModel order), then "A" .. "S"

    /// A point's local position. \throws talkface::InvalidArgument for an unknown id.
    Point3 local(std::string_view id) const;
};

/// Lifts a face into 3D (Algorithm 2.1 steps 3-5 and Table 2.1). S is placed at 8.3 (the thesis's
/// "8.5" does not exist). \throws talkface::InvalidArgument if d is not positive.
TALKFACE_API LiftedFace lift_face(const FaceModel& face);

/// The 17 additional point ids, "A" .. "S" without O and P.
TALKFACE_API const std::vector<std::string>& additional_point_ids();

/// Table 2.1: a point's depth in units of d. \throws talkface::InvalidArgument for an unknown id.
TALKFACE_API double depth_in_d(std::string_view id);

/// The rotation origin O of Algorithm 2.1 step 3, in image pixels.
TALKFACE_API Point2 rotation_origin(const FaceModel& face);

/// The same face moved so its rotation origin is at `origin` and scaled so its d is `d_px`; every
/// point and FAPU scales by d_px / d (thesis, end of 2.3.2).
/// \throws talkface::InvalidArgument if d_px is not finite and positive.
TALKFACE_API FaceModel place_face(const FaceModel& face, Point2 origin, double d_px);

}  // namespace v0
}  // namespace talkface

#endif

// talkface: Rotation3D, the head rotation of thesis 2.4.3.1 as a proper rotation matrix.
#ifndef TALKFACE_ROTATION3D_HPP
#define TALKFACE_ROTATION3D_HPP

#include <array>

#include "talkface/export.h"
#include "talkface/types.hpp"

namespace talkface {
inline namespace v0 {

/// A rotation about the local X (alpha, nod), Y (beta, turn) and Z (gamma, tilt) axes, applied in
/// the order Y, then X, then Z: R = Rz(gamma) Rx(alpha) Ry(beta).
///
/// Signs, in the local frame of Point3 (x towards the image left, y up, z towards the viewer):
/// beta > 0 turns the face towards the image left, alpha > 0 nods it down, gamma > 0 tilts the top of
/// the head towards the image right (clockwise on screen). SPEC: Rx uses z2 = y1 sin(alpha) + z1
/// cos(alpha); the thesis's minus sign would not be a rotation.
///
/// Any finite angle is a valid rotation; poses of a face are limited to +-15 degrees where a pose
/// is applied (project_face()). A value type; thread-safe for const use.
class TALKFACE_API Rotation3D {
public:
    /// The identity.
    Rotation3D();
    /// \throws talkface::InvalidArgument naming the angle if one is not finite.
    Rotation3D(double alpha_deg, double beta_deg, double gamma_deg);

    double alpha_deg() const { return alpha_deg_; }  ///< about X (nod)
    double beta_deg() const { return beta_deg_; }    ///< about Y (turn)
    double gamma_deg() const { return gamma_deg_; }  ///< about Z (tilt)

    /// The 3x3 matrix, row-major. Orthonormal with determinant 1.
    const std::array<double, 9>& matrix() const { return matrix_; }
    /// R p.
    Point3 rotate(Point3 local_xyz) const;
    /// R^T p, the inverse rotation.
    Point3 unrotate(Point3 local_xyz) const;

    friend bool operator==(const Rotation3D& a, const Rotation3D& b) { return a.matrix_ == b.matrix_; }
    friend bool operator!=(const Rotation3D& a, const Rotation3D& b) { return !(a == b); }

private:
    double alpha_deg_ = 0.0;
    double beta_deg_ = 0.0;
    double gamma_deg_ = 0.0;
    std::array<double, 9> matrix_{1, 0, 0, 0, 1, 0, 0, 0, 1};
};

}  // namespace v0
}  // namespace talkface

#endif

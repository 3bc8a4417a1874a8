// Rotation3D: thesis 2.4.3.1 as one proper rotation matrix, R = Rz(gamma) Rx(alpha) Ry(beta).
#include "talkface/rotation3d.hpp"

#include <cmath>
#include <string>

#include <Eigen/Core>

#include "common/number_format.hpp"
#include "talkface/errors.hpp"

namespace talkface {
inline namespace v0 {

namespace {

constexpr double kPi = 3.14159265358979323846;

double finite_angle_rad(double angle_deg, const char* parameter) {
    if (!std::isfinite(angle_deg)) {
        throw InvalidArgument(parameter, "a rotation angle must be finite, got " +
                                             detail::format_shortest(angle_deg) + " degrees");
    }
    return angle_deg * (kPi / 180.0);
}

// The three factors are written out from the thesis's per-axis formulas so that each sign can be
// checked against 2.4.3.1. At zero angles every sine is 0 and every cosine 1 exactly, so the product
// is the identity bit for bit (project_face() relies on that for the exact frontal face).
Eigen::Matrix3d rotation_matrix(double alpha_rad, double beta_rad, double gamma_rad) {
    const double ca = std::cos(alpha_rad), sa = std::sin(alpha_rad);
    const double cb = std::cos(beta_rad), sb = std::sin(beta_rad);
    const double cg = std::cos(gamma_rad), sg = std::sin(gamma_rad);
    // One matrix row per line, as the formulas read.
    // clang-format off
    Eigen::Matrix3d about_y;
    // x1 = x cos b + z sin b; z1 = -x sin b + z cos b
    about_y << cb,  0.0, sb,
               0.0, 1.0, 0.0,
               -sb, 0.0, cb;
    Eigen::Matrix3d about_x;
    // y2 = y1 cos a - z1 sin a; SPEC: z2 = y1 sin a + z1 cos a (the thesis's minus sign makes the
    // map non-orthogonal)
    about_x << 1.0, 0.0, 0.0,
               0.0, ca,  -sa,
               0.0, sa,  ca;
    Eigen::Matrix3d about_z;
    // x3 = x2 cos g - y2 sin g; y3 = x2 sin g + y2 cos g
    about_z << cg,  -sg, 0.0,
               sg,  cg,  0.0,
               0.0, 0.0, 1.0;
    // clang-format on
    return about_z * about_x * about_y;
}

Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>> as_matrix(const std::array<double, 9>& m) {
    return Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(m.data());
}

Point3 to_point(const Eigen::Vector3d& v) {
    return Point3{v.x(), v.y(), v.z()};
}

Eigen::Vector3d to_vector(Point3 p) {
    return Eigen::Vector3d(p.x, p.y, p.z);
}

}  // namespace

Rotation3D::Rotation3D() = default;

Rotation3D::Rotation3D(double alpha_deg, double beta_deg, double gamma_deg)
    : alpha_deg_(alpha_deg), beta_deg_(beta_deg), gamma_deg_(gamma_deg) {
    const Eigen::Matrix3d r =
        rotation_matrix(finite_angle_rad(alpha_deg, "alpha_deg"), finite_angle_rad(beta_deg, "beta_deg"),
                        finite_angle_rad(gamma_deg, "gamma_deg"));
    for (int row = 0; row < 3; ++row) {
        for (int column = 0; column < 3; ++column) {
            matrix_[static_cast<std::size_t>(3 * row + column)] = r(row, column);
        }
    }
}

Point3 Rotation3D::rotate(Point3 local_xyz) const {
    return to_point(as_matrix(matrix_) * to_vector(local_xyz));
}

Point3 Rotation3D::unrotate(Point3 local_xyz) const {
    return to_point(as_matrix(matrix_).transpose() * to_vector(local_xyz));
}

}  // namespace v0
}  // namespace talkface

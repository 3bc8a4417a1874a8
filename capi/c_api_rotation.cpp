// tf_rotation3d_*: the C face of talkface::Rotation3D, as plain functions of the three angles
// (a rotation is three numbers; a handle would only add a destroy call).
#include "c_api_guard.hpp"
#include "talkface/rotation3d.hpp"

using talkface::Point3;
using talkface::Rotation3D;
using talkface::capi::guard;
using talkface::capi::require_non_null;

extern "C" {

tf_status tf_rotation3d_matrix(double alpha_deg, double beta_deg, double gamma_deg, double out_matrix[9]) {
    return guard([&] {
        require_non_null(out_matrix, "out_matrix");
        const Rotation3D rotation(alpha_deg, beta_deg, gamma_deg);
        for (int i = 0; i < 9; ++i) out_matrix[i] = rotation.matrix()[static_cast<size_t>(i)];
    });
}

tf_status tf_rotation3d_rotate(double alpha_deg, double beta_deg, double gamma_deg, const double in_xyz[3],
                               double out_xyz[3]) {
    return guard([&] {
        require_non_null(in_xyz, "in_xyz");
        require_non_null(out_xyz, "out_xyz");
        const Point3 rotated =
            Rotation3D(alpha_deg, beta_deg, gamma_deg).rotate(Point3{in_xyz[0], in_xyz[1], in_xyz[2]});
        out_xyz[0] = rotated.x;
        out_xyz[1] = rotated.y;
        out_xyz[2] = rotated.z;
    });
}

tf_status tf_rotation3d_unrotate(double alpha_deg, double beta_deg, double gamma_deg, const double in_xyz[3],
                                 double out_xyz[3]) {
    return guard([&] {
        require_non_null(in_xyz, "in_xyz");
        require_non_null(out_xyz, "out_xyz");
        const Point3 rotated =
            Rotation3D(alpha_deg, beta_deg, gamma_deg).unrotate(Point3{in_xyz[0], in_xyz[1], in_xyz[2]});
        out_xyz[0] = rotated.x;
        out_xyz[1] = rotated.y;
        out_xyz[2] = rotated.z;
    });
}

}  // extern "C"

// Rotation3D in Python: the matrix as a (3, 3) array; rotate() takes one point or an (N, 3) array.
#include "bind.hpp"

namespace talkface::python {

namespace {

using DoubleArray = py::array_t<double, py::array::c_style | py::array::forcecast>;

// Applies `apply` (rotate or unrotate) to a (3,) point or to each row of an (N, 3) array.
template <typename Apply>
py::array_t<double> apply_to_points(const DoubleArray& local_xyz, Apply apply) {
    const bool is_point = local_xyz.ndim() == 1 && local_xyz.shape(0) == 3;
    const bool is_rows = local_xyz.ndim() == 2 && local_xyz.shape(1) == 3;
    if (!is_point && !is_rows) {
        throw InvalidArgument("local_xyz", "expected shape (3,) or (N, 3), got " + shape_text(local_xyz));
    }
    const py::ssize_t rows = is_point ? 1 : local_xyz.shape(0);
    py::array_t<double> result(
        std::vector<py::ssize_t>(local_xyz.shape(), local_xyz.shape() + local_xyz.ndim()));
    const double* in = local_xyz.data();
    double* out = result.mutable_data();
    for (py::ssize_t row = 0; row < rows; ++row) {
        const Point3 moved = apply(Point3{in[3 * row], in[3 * row + 1], in[3 * row + 2]});
        out[3 * row] = moved.x;
        out[3 * row + 1] = moved.y;
        out[3 * row + 2] = moved.z;
    }
    return result;
}

}  // namespace

void bind_rotation3d(py::module_& m) {
    py::class_<Rotation3D>(m, "Rotation3D", R"doc(
A head rotation about the local X (alpha, nod), Y (beta, turn) and Z (gamma, tilt) axes, applied in
the order Y, then X, then Z: R = Rz(gamma) Rx(alpha) Ry(beta); a proper rotation matrix.

Local frame: x towards the image left, y up, z towards the viewer. beta > 0 turns the face towards the
image left, alpha > 0 nods it down, gamma > 0 tilts the top of the head towards the image right.

Example:
    >>> r = talkface.Rotation3D(0.0, 10.0, 0.0)
    >>> r.matrix() @ r.matrix().T
)doc")
        .def(py::init<double, double, double>(), py::arg("alpha_deg") = 0.0, py::arg("beta_deg") = 0.0,
             py::arg("gamma_deg") = 0.0, R"doc(
A rotation by the three angles, degrees (any finite angle; poses are limited to +-15 where applied).

Args:
    alpha_deg (float): about X (nod), degrees.
    beta_deg (float): about Y (turn), degrees.
    gamma_deg (float): about Z (tilt), degrees.

Raises:
    talkface.InvalidArgument: an angle is not finite (the message names it).

Example:
    >>> r = talkface.Rotation3D(alpha_deg=5.0, beta_deg=-10.0)
    >>> r.beta_deg
)doc")
        .def_property_readonly("alpha_deg", &Rotation3D::alpha_deg, "about X (nod), degrees")
        .def_property_readonly("beta_deg", &Rotation3D::beta_deg, "about Y (turn), degrees")
        .def_property_readonly("gamma_deg", &Rotation3D::gamma_deg, "about Z (tilt), degrees")
        .def(
            "matrix",
            [](const Rotation3D& rotation) {
                auto array = new_matrix(3, 3);
                std::copy(rotation.matrix().begin(), rotation.matrix().end(), array.mutable_data());
                return array;
            },
            R"doc(
The 3x3 matrix as a new (3, 3) float64 array. Orthonormal with determinant 1.

Example:
    >>> m = talkface.Rotation3D(3.0, 4.0, 5.0).matrix()
    >>> numpy.linalg.det(m)
)doc")
        .def(
            "rotate",
            [](const Rotation3D& rotation, const DoubleArray& local_xyz) {
                return apply_to_points(local_xyz, [&](Point3 p) { return rotation.rotate(p); });
            },
            py::arg("local_xyz"), R"doc(
R p for one point or for each row.

Args:
    local_xyz (array-like): shape (3,) or (N, 3), local pixels; converted to float64.

Returns:
    numpy.ndarray: a new array of the same shape.

Raises:
    talkface.InvalidArgument: another shape.

Example:
    >>> talkface.Rotation3D(0, 90, 0).rotate([0.0, 0.0, 1.0])
    >>> talkface.Rotation3D(0, 10, 0).rotate(numpy.zeros((5, 3)))
)doc")
        .def(
            "unrotate",
            [](const Rotation3D& rotation, const DoubleArray& local_xyz) {
                return apply_to_points(local_xyz, [&](Point3 p) { return rotation.unrotate(p); });
            },
            py::arg("local_xyz"), R"doc(
R^T p, the inverse rotation, for one point or for each row (shapes as rotate()).

Raises:
    talkface.InvalidArgument: a shape other than (3,) or (N, 3).

Example:
    >>> r = talkface.Rotation3D(5, 10, 15)
    >>> r.unrotate(r.rotate([1.0, 2.0, 3.0]))
)doc")
        .def(
            "__eq__", [](const Rotation3D& a, const Rotation3D& b) { return a == b; }, py::is_operator())
        .def("__repr__", [](const Rotation3D& rotation) {
            return py::str("talkface.Rotation3D(alpha_deg={!r}, beta_deg={!r}, gamma_deg={!r})")
                .format(rotation.alpha_deg(), rotation.beta_deg(), rotation.gamma_deg());
        });
}

}  // namespace talkface::python

// The 3D lift in Python: LiftedFace and place_face.
#include "bind.hpp"

namespace talkface::python {

void bind_face_lift(py::module_& m) {
    py::class_<LiftedFace>(m, "LiftedFace", R"doc(
A face in its local 3D frame (thesis Algorithm 2.1, Table 2.1): pixels, x towards the image left, y up,
z towards the viewer, origin at the rotation origin O (the neck). Made by lift_face().

Example:
    >>> lifted = talkface.lift_face(face)
    >>> lifted.local("A")
)doc")
        .def_readonly("origin", &LiftedFace::origin, "O, (x, y) in image pixels")
        .def_readonly("d", &LiftedFace::d, "eyeball distance, pixels")
        .def_property_readonly(
            "ids", [](const LiftedFace& lifted) { return ids_of(lifted.points); },
            "the 72 model ids, then \"A\" .. \"S\" (a new list)")
        .def_property_readonly(
            "local_xyz",
            [](const LiftedFace& lifted) {
                auto array = new_matrix(static_cast<py::ssize_t>(lifted.points.size()), 3);
                auto view = array.mutable_unchecked<2>();
                for (py::ssize_t row = 0; row < view.shape(0); ++row) {
                    const Point3& point = lifted.points[static_cast<std::size_t>(row)].local;
                    view(row, 0) = point.x;
                    view(row, 1) = point.y;
                    view(row, 2) = point.z;
                }
                return array;
            },
            "a new (N, 3) float64 array of local (x, y, z) pixels, in ids order")
        .def("local", &LiftedFace::local, py::arg("id"), R"doc(
A point's local position.

Args:
    id (str): a model point id or "A" .. "S".

Returns:
    tuple[float, float, float]: (x, y, z), pixels in the local frame.

Raises:
    talkface.InvalidArgument: an unknown id.

Example:
    >>> x, y, z = talkface.lift_face(face).local("9.15")
    >>> z / face.fapu("d")
)doc")
        .def("__repr__", [](const LiftedFace& lifted) {
            return py::str("<talkface.LiftedFace {} points, d={!r} px>")
                .format(lifted.points.size(), lifted.d);
        });

    m.def("lift_face", &lift_face, py::arg("face"), R"doc(
Lifts a face into 3D (Algorithm 2.1 steps 3-5, Table 2.1); S is placed at 8.3.

Args:
    face (FaceModel): a neutral face.

Raises:
    talkface.InvalidArgument: the face's d is not positive.

Example:
    >>> lifted = talkface.lift_face(talkface.FaceModel.default())
    >>> len(lifted.ids)
)doc");
    m.def("additional_point_ids", &additional_point_ids, R"doc(
The 17 additional point ids "A" .. "S" (without O and P), as a list.

Example:
    >>> talkface.additional_point_ids()[:3]
    ['A', 'B', 'C']
)doc");
    m.def("depth_in_d", &depth_in_d, py::arg("id"), R"doc(
Table 2.1: a point's depth, in units of d (eyeball distance).

Args:
    id (str): a model point id or "A" .. "S".

Raises:
    talkface.InvalidArgument: an unknown id.

Example:
    >>> talkface.depth_in_d("9.15")
    >>> talkface.depth_in_d("A") * face.fapu("d")
)doc");
    m.def("rotation_origin", &rotation_origin, py::arg("face"), R"doc(
The rotation origin O of Algorithm 2.1 step 3: (x, y) in image pixels.

Example:
    >>> x, y = talkface.rotation_origin(face)
    >>> y > face.point("9.15")[1]
)doc");
    m.def("place_face", &place_face, py::arg("face"), py::arg("origin"), py::arg("d_px"), R"doc(
The same face moved so its rotation origin is at origin and scaled so its d is d_px; every point and
FAPU scales by d_px / d (thesis, end of 2.3.2).

Args:
    face (FaceModel): the face.
    origin (tuple[float, float]): the new rotation origin, image pixels.
    d_px (float): the new eyeball distance, pixels.

Raises:
    talkface.InvalidArgument: d_px is not finite and positive.

Example:
    >>> small = talkface.place_face(face, (320.0, 400.0), 40.0)
    >>> small.fapu("d")
)doc");
}

}  // namespace talkface::python

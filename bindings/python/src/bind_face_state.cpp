// What changes from frame to frame, in Python: Pose, Expression, MouthShape, MouthControls, FaceState,
// and project_face() with its ProjectedFace.
#include "bind.hpp"

namespace talkface::python {

namespace {

void bind_expression(py::module_& m) {
    py::class_<Expression>(m, "Expression", R"doc(
Basic expression amounts in 0..1, combinable (thesis 2.4.2); all 0 is the neutral face.

Example:
    >>> e = talkface.Expression(blink_left=1.0, smile=0.5)
    >>> talkface.apply_expression(face, e)
)doc")
        .def(py::init([](double blink_left, double blink_right, double smile, double brows) {
                 return Expression{blink_left, blink_right, smile, brows};
             }),
             py::arg("blink_left") = 0.0, py::arg("blink_right") = 0.0, py::arg("smile") = 0.0,
             py::arg("brows") = 0.0, R"doc(
Args:
    blink_left (float): image-left eye (3.2, 3.4), 0..1, 1 = closed.
    blink_right (float): image-right eye (3.1, 3.3), 0..1, 1 = closed.
    smile (float): 0..1, mouth corners up by UpperLipH, lower lids up (squint).
    brows (float): 0..1, eyebrows up by EyebrowH.

Example:
    >>> talkface.Expression(brows=1.0)
    >>> talkface.Expression(blink_left=0.5, blink_right=0.5)
)doc")
        .def_readwrite("blink_left", &Expression::blink_left, "image-left eye, 0..1 (1 = closed)")
        .def_readwrite("blink_right", &Expression::blink_right, "image-right eye, 0..1 (1 = closed)")
        .def_readwrite("smile", &Expression::smile, "0..1")
        .def_readwrite("brows", &Expression::brows, "eyebrow raise, 0..1")
        .def(
            "__eq__", [](const Expression& a, const Expression& b) { return a == b; }, py::is_operator())
        .def("__repr__", [](const Expression& e) {
            return py::str("talkface.Expression(blink_left={!r}, blink_right={!r}, smile={!r}, brows={!r})")
                .format(e.blink_left, e.blink_right, e.smile, e.brows);
        });

    m.def("apply_expression", &apply_expression, py::arg("face"), py::arg("expression"), R"doc(
The face with the expression applied (a new face).

Args:
    face (FaceModel): a neutral face.
    expression (Expression): amounts in 0..1.

Raises:
    talkface.InvalidArgument: an amount outside 0..1 or not finite (the message names it).

Example:
    >>> closed = talkface.apply_expression(face, talkface.Expression(blink_left=1.0))
    >>> closed.point("3.2")
)doc");
}

void bind_mouth(py::module_& m) {
    py::enum_<MouthShape>(m, "MouthShape", R"doc(
The 12 basic mouth shapes of thesis 5.2.2: initials m, f, h_prime (h'), h, r, z; finals a, i, u, e, o, n.
The values equal the C ABI's tf_mouth_shape.

Example:
    >>> talkface.MouthShape.a
    >>> talkface.mouth_shape_name(talkface.MouthShape.h_prime)
)doc")
        .value("m", MouthShape::m)
        .value("f", MouthShape::f)
        .value("h_prime", MouthShape::h_prime)
        .value("h", MouthShape::h)
        .value("r", MouthShape::r)
        .value("z", MouthShape::z)
        .value("a", MouthShape::a)
        .value("i", MouthShape::i)
        .value("u", MouthShape::u)
        .value("e", MouthShape::e)
        .value("o", MouthShape::o)
        .value("n", MouthShape::n);

    m.def(
        "all_mouth_shapes",
        [] {
            const auto& shapes = all_mouth_shapes();
            return std::vector<MouthShape>(shapes.begin(), shapes.end());
        },
        R"doc(
All 12 shapes, in enum order, as a list.

Example:
    >>> [talkface.mouth_shape_name(s) for s in talkface.all_mouth_shapes()]
    ['m', 'f', "h'", 'h', 'r', 'z', 'a', 'i', 'u', 'e', 'o', 'n']
)doc");
    m.def("mouth_shape_name", &mouth_shape_name, py::arg("shape"), R"doc(
The thesis's name of a shape: "m", "f", "h'", "h", "r", "z", "a", "i", "u", "e", "o", "n".

Example:
    >>> talkface.mouth_shape_name(talkface.MouthShape.h_prime)
    "h'"
)doc");
    m.def("mouth_shape_from_name", &mouth_shape_from_name, py::arg("name"), R"doc(
Parses a name as mouth_shape_name() writes it ("h_prime" is accepted for "h'").

Raises:
    talkface.InvalidArgument: an unknown name (the message lists the valid ones).

Example:
    >>> talkface.mouth_shape_from_name("a")
    >>> talkface.mouth_shape_from_name("h_prime") == talkface.MouthShape.h_prime
)doc");

    py::class_<MouthControls>(m, "MouthControls", R"doc(
The four mouth control points, each an (x, y) tuple in image pixels: up = 8.9, down = 8.2,
left = 8.4, right = 8.3. Key frames interpolate these; apply_mouth() turns them into a whole mouth.

Example:
    >>> c = talkface.mouth_controls(face, talkface.MouthShape.a)
    >>> c.down[1] - c.up[1]
)doc")
        .def(py::init([](Point2 up, Point2 down, Point2 left, Point2 right) {
                 return MouthControls{up, down, left, right};
             }),
             py::arg("up") = Point2{}, py::arg("down") = Point2{}, py::arg("left") = Point2{},
             py::arg("right") = Point2{}, R"doc(
Args:
    up, down, left, right (tuple[float, float]): 8.9, 8.2, 8.4, 8.3, image pixels.

Example:
    >>> talkface.MouthControls(up=(100, 200), down=(100, 220), left=(80, 210), right=(120, 210))
    >>> talkface.neutral_mouth_controls(face)
)doc")
        .def_readwrite("up", &MouthControls::up, "8.9, (x, y) image pixels")
        .def_readwrite("down", &MouthControls::down, "8.2, (x, y) image pixels")
        .def_readwrite("left", &MouthControls::left, "8.4, (x, y) image pixels")
        .def_readwrite("right", &MouthControls::right, "8.3, (x, y) image pixels")
        .def(
            "__eq__", [](const MouthControls& a, const MouthControls& b) { return a == b; },
            py::is_operator())
        .def("__repr__", [](const MouthControls& c) {
            return py::str("talkface.MouthControls(up={!r}, down={!r}, left={!r}, right={!r})")
                .format(c.up, c.down, c.left, c.right);
        });

    m.def("neutral_mouth_controls", &neutral_mouth_controls, py::arg("neutral"), R"doc(
The control points of the neutral face (shape m is this).

Example:
    >>> talkface.neutral_mouth_controls(face).up == face.point("8.9")
    True
)doc");
    m.def("mouth_controls", &mouth_controls, py::arg("neutral"), py::arg("shape"), R"doc(
A shape's control points: thesis 5.2.2's formulas in FAPU multiples of the neutral face.

Args:
    neutral (FaceModel): the neutral face.
    shape (MouthShape): one of the 12 shapes.

Example:
    >>> c = talkface.mouth_controls(face, talkface.MouthShape.o)
    >>> talkface.apply_mouth(face, c)
)doc");
    m.def("apply_mouth", &apply_mouth, py::arg("neutral"), py::arg("controls"), R"doc(
The face with its mouth set to controls (a new face): 8.1 and 8.10 follow 8.9, the inner lips follow
the lips (never passing through each other), the jaw 2.1 = (8.2.x, 8.2.y + JawH).

Example:
    >>> open_face = talkface.apply_mouth(face, talkface.mouth_controls(face, talkface.MouthShape.a))
    >>> open_face.point("2.1")
)doc");
}

void bind_pose_and_state(py::module_& m) {
    m.attr("kMaxPoseAngleDeg") = kMaxPoseAngleDeg;

    py::class_<Pose>(m, "Pose", R"doc(
A head pose in degrees; see Rotation3D for the axes and signs. Each angle within +-kMaxPoseAngleDeg
(15) when projected.

Example:
    >>> talkface.Pose(beta_deg=10.0)
    >>> talkface.FaceState(pose=talkface.Pose(0.0, 10.0, -5.0))
)doc")
        .def(py::init([](double alpha_deg, double beta_deg, double gamma_deg) {
                 return Pose{alpha_deg, beta_deg, gamma_deg};
             }),
             py::arg("alpha_deg") = 0.0, py::arg("beta_deg") = 0.0, py::arg("gamma_deg") = 0.0, R"doc(
Args:
    alpha_deg (float): about X, nod (> 0 down), degrees.
    beta_deg (float): about Y, turn (> 0 towards the image left), degrees.
    gamma_deg (float): about Z, tilt, degrees.

Example:
    >>> pose = talkface.Pose(alpha_deg=5.0)
    >>> pose.alpha_deg
)doc")
        .def_readwrite("alpha_deg", &Pose::alpha_deg, "about X (nod, > 0 down), degrees")
        .def_readwrite("beta_deg", &Pose::beta_deg, "about Y (turn, > 0 towards the image left), degrees")
        .def_readwrite("gamma_deg", &Pose::gamma_deg, "about Z (tilt), degrees")
        .def(
            "__eq__", [](const Pose& a, const Pose& b) { return a == b; }, py::is_operator())
        .def("__repr__", [](const Pose& p) {
            return py::str("talkface.Pose(alpha_deg={!r}, beta_deg={!r}, gamma_deg={!r})")
                .format(p.alpha_deg, p.beta_deg, p.gamma_deg);
        });

    py::class_<FaceState>(m, "FaceState", R"doc(
Everything that changes from frame to frame: pose, expression and mouth (None = the neutral mouth).
state.pose and state.expression are the state's own (assigning their fields changes the state);
state.mouth is a copy: assign a whole MouthControls.

Example:
    >>> state = talkface.FaceState(pose=talkface.Pose(beta_deg=10.0))
    >>> state.mouth = talkface.mouth_controls(face, talkface.MouthShape.a)
)doc")
        .def(py::init([](const Pose& pose, const Expression& expression, std::optional<MouthControls> mouth) {
                 return FaceState{pose, expression, std::move(mouth)};
             }),
             py::arg("pose") = Pose{}, py::arg("expression") = Expression{}, py::arg("mouth") = py::none(),
             R"doc(
Args:
    pose (Pose): head pose, degrees.
    expression (Expression): blink, smile, brows amounts.
    mouth (MouthControls | None): mouth control points, image pixels; None for the neutral mouth.

Example:
    >>> talkface.FaceState()
    >>> talkface.FaceState(expression=talkface.Expression(smile=0.5))
)doc")
        .def_readwrite("pose", &FaceState::pose, "head pose (Pose)")
        .def_readwrite("expression", &FaceState::expression, "expression amounts (Expression)")
        .def_readwrite("mouth", &FaceState::mouth, "mouth control points, or None for the neutral mouth")
        .def("__repr__", [](const FaceState& s) {
            return py::str("talkface.FaceState(pose={!r}, expression={!r}, mouth={!r})")
                .format(s.pose, s.expression, s.mouth);
        });
}

void bind_projection(py::module_& m) {
    py::enum_<NoseBridgeSide>(m, "NoseBridgeSide", R"doc(
Which side of the nose the bridge line is drawn from (Algorithm 2.3 step 8).

Example:
    >>> talkface.project_face(face, talkface.FaceState()).nose_bridge
    >>> talkface.NoseBridgeSide.left
)doc")
        .value("left", NoseBridgeSide::left)
        .value("right", NoseBridgeSide::right);

    py::class_<ProjectedFace>(m, "ProjectedFace", R"doc(
A face drawn at a state: every point in image pixels, ready for a renderer. Made by project_face().

Example:
    >>> projected = talkface.project_face(face, talkface.FaceState(pose=talkface.Pose(beta_deg=12)))
    >>> projected.point("9.15"), projected.left_contour
)doc")
        .def_property_readonly(
            "ids", [](const ProjectedFace& projected) { return ids_of(projected.points); },
            "the 72 model ids, then \"A\" .. \"S\" (a new list)")
        .def_property_readonly(
            "image_xy",
            [](const ProjectedFace& projected) {
                std::vector<Point2> xy;
                for (const ProjectedPoint& point : projected.points) xy.push_back(point.xy);
                return points_to_array(xy);
            },
            "a new (N, 2) float64 array of (x, y) image pixels, in ids order; eyeball ids hold the pupils")
        .def_readonly("left_contour", &ProjectedFace::left_contour,
                      "forehead, cheek, jaw point ids of the image-left contour, after substitution")
        .def_readonly("right_contour", &ProjectedFace::right_contour,
                      "forehead, cheek, jaw point ids of the image-right contour, after substitution")
        .def_readonly("nose_bridge", &ProjectedFace::nose_bridge, "NoseBridgeSide")
        .def_readonly("origin", &ProjectedFace::origin, "rotation origin O, (x, y) image pixels")
        .def_readonly("d", &ProjectedFace::d, "eyeball distance, pixels")
        .def_property_readonly(
            "face", [](const ProjectedFace& projected) { return projected.face; },
            "the 2D face with expression and mouth applied, before the pose (a copy)")
        .def("point", &ProjectedFace::point, py::arg("id"), R"doc(
A point's image position, (x, y) pixels.

Raises:
    talkface.InvalidArgument: an unknown id.

Example:
    >>> projected.point("8.3")
    >>> projected.point("A")
)doc")
        .def(
            "hair_polygon",
            [](const ProjectedFace& projected) { return points_to_array(projected.hair_polygon()); },
            R"doc(
The 23 hair points in polygon order, as a new (23, 2) float64 array of image pixels.

Example:
    >>> hair = projected.hair_polygon()
    >>> hair.shape
    (23, 2)
)doc");

    m.def(
        "project_face",
        [](const FaceModel& neutral, const FaceState& state) {
            // Copies: another Python thread may change the caller's objects once the GIL is free.
            const FaceModel neutral_copy = neutral;
            const FaceState state_copy = state;
            py::gil_scoped_release release;
            return project_face(neutral_copy, state_copy);
        },
        py::arg("neutral"), py::arg("state"), R"doc(
Projects a face (Algorithm 2.3): expression and mouth applied to the neutral face, lifted, hair depth
shifted, rotated (Y, X, Z), gaze held on a fixed focus, projected orthographically, contour
substituted past +-10 degrees. Releases the GIL while it works.

Args:
    neutral (FaceModel): the neutral face.
    state (FaceState): pose (degrees), expression, mouth.

Raises:
    talkface.InvalidArgument: an angle outside +-15 degrees or not finite (named, e.g. "beta_deg"), or
        an expression amount outside 0..1.

Example:
    >>> projected = talkface.project_face(face, talkface.FaceState(pose=talkface.Pose(beta_deg=12)))
    >>> projected.image_xy.shape
)doc");
}

}  // namespace

void bind_face_state(py::module_& m) {
    bind_expression(m);
    bind_mouth(m);
    bind_pose_and_state(m);
    bind_projection(m);
}

}  // namespace talkface::python

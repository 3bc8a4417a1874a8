// FaceModel and FaceColors in Python: points as (x, y) tuples or a (72, 2) float64 array, FAPUs by
// name, colours as "#rrggbb".
#include "bind.hpp"

namespace talkface::python {

namespace {

// Member by member because FaceModel's and FaceColors' operator== are in-class friends, which
// TALKFACE_API does not reach: the shared libtalkface does not export them (face_model.hpp should
// declare them `friend TALKFACE_API bool operator==`).

void set_points(FaceModel& face,
                const py::array_t<double, py::array::c_style | py::array::forcecast>& points) {
    if (points.ndim() != 2 || points.shape(0) != static_cast<py::ssize_t>(FaceModel::kPointCount) ||
        points.shape(1) != 2) {
        throw InvalidArgument("points", "expected shape (" + std::to_string(FaceModel::kPointCount) +
                                            ", 2), got " + shape_text(points));
    }
    const auto view = points.unchecked<2>();
    // All or nothing: a non-finite value in row 40 must not leave rows 0..39 moved.
    FaceModel moved = face;
    const auto& ids = FaceModel::point_ids();
    for (std::size_t row = 0; row < ids.size(); ++row) {
        const auto index = static_cast<py::ssize_t>(row);
        moved.set_point(ids[row], Point2{view(index, 0), view(index, 1)});
    }
    face = std::move(moved);
}

py::dict fapus_dict(const FaceModel& face) {
    py::dict fapus;
    const auto& names = FaceModel::fapu_names();
    for (std::size_t i = 0; i < names.size(); ++i) fapus[py::str(names[i])] = face.fapus()[i];
    return fapus;
}

}  // namespace

void bind_face_model(py::module_& m) {
    py::class_<FaceColors>(m, "FaceColors", R"doc(
The colours a face is drawn with (part of the face file), each a "#rrggbb" string.

FaceModel.colors returns a copy: change it and assign it back.

Example:
    >>> colors = face.colors; colors.hair = "#602010"
    >>> face.colors = colors
)doc")
        .def(py::init<>(), "The default colours.")
        .def_readwrite("skin", &FaceColors::skin, "skin, \"#rrggbb\"")
        .def_readwrite("hair", &FaceColors::hair, "hair, \"#rrggbb\"")
        .def_readwrite("brows", &FaceColors::brows, "eyebrows, \"#rrggbb\"")
        .def_readwrite("eye_white", &FaceColors::eye_white, "white of the eyes, \"#rrggbb\"")
        .def_readwrite("iris", &FaceColors::iris, "iris, \"#rrggbb\"")
        .def_readwrite("lips", &FaceColors::lips, "lips, \"#rrggbb\"")
        .def_readwrite("mouth_inside", &FaceColors::mouth_inside, "inside of the open mouth, \"#rrggbb\"")
        .def_readwrite("outline", &FaceColors::outline, "outlines, \"#rrggbb\"")
        .def(
            "__eq__", [](const FaceColors& a, const FaceColors& b) { return a == b; },
            py::is_operator())
        .def("__repr__", [](const FaceColors& colors) {
            return "talkface.FaceColors(skin='" + to_hex(colors.skin) + "', hair='" + to_hex(colors.hair) +
                   "', ...)";
        });

    py::class_<FaceModel>(m, "FaceModel", R"doc(
A neutral cartoon face: 72 named feature points in image pixels (y down) and 12 FAPUs (pixels).

Point ids are the thesis's MPEG-4 numbers ("3.2", "8.3", "hair.1" .. "hair.23", "EyeballLeft", ...;
"left" is the image left); FaceModel.point_ids() lists them. A value: copy.copy() and == work, and it
pickles through its face-file text.

Example:
    >>> face = talkface.FaceModel.default()
    >>> face.point("3.2"), face.fapu("d")
)doc")
        .def(py::init<>(), R"doc(
The built-in default face (same as FaceModel.default()).

Example:
    >>> face = talkface.FaceModel()
    >>> face.name
)doc")
        .def_static("default", &FaceModel::default_face, R"doc(
The built-in default face, compiled into the library.

Returns:
    FaceModel: a new face.

Example:
    >>> face = talkface.FaceModel.default()
    >>> len(face.points())
)doc")
        .def_static("default_face", &FaceModel::default_face, R"doc(
The built-in default face (the C++ name of FaceModel.default()).

Example:
    >>> face = talkface.FaceModel.default_face()
    >>> face.fapu("MW0")
)doc")
        .def_static(
            "load", [](const std::filesystem::path& path) { return FaceModel::load(path.string()); },
            py::arg("path"), R"doc(
Reads a face file (docs/face-format.md). FAPUs the file leaves out are measured from the points.

Args:
    path (str | os.PathLike): the face file.

Raises:
    talkface.FileError: the file cannot be read (also an OSError; .filename is the path).
    talkface.ParseError: its content is wrong; the message names "path:line:column" and the point.

Example:
    >>> face = talkface.FaceModel.load("face.xml")
    >>> face.point("8.3")
)doc")
        .def_static("from_xml", &FaceModel::from_xml, py::arg("xml"), py::arg("source_name") = "<string>",
                    R"doc(
Parses the text of a face file.

Args:
    xml (str): the file's content.
    source_name (str): stands for the path in error messages.

Raises:
    talkface.ParseError: as load() does, naming source_name:line:column.

Example:
    >>> face = talkface.FaceModel.from_xml(text, "face.xml")
    >>> face == talkface.FaceModel.default()
)doc")
        .def(
            "save",
            [](const FaceModel& face, const std::filesystem::path& path) { face.save(path.string()); },
            py::arg("path"), R"doc(
Writes the face file atomically (a temporary file renamed over path): on failure path is untouched.
FaceModel.load(path) gives back an equal face, bit for bit.

Args:
    path (str | os.PathLike): where to write.

Raises:
    talkface.FileError: it cannot be written.

Example:
    >>> face.save("face.xml")
    >>> talkface.FaceModel.load("face.xml") == face
)doc")
        .def("to_xml", &FaceModel::to_xml, R"doc(
The face file's text (what save() writes).

Example:
    >>> text = face.to_xml()
    >>> talkface.FaceModel.from_xml(text) == face
)doc")
        .def_static("point_ids", &FaceModel::point_ids, R"doc(
The 72 point ids in file order, as a list of str.

Example:
    >>> ids = talkface.FaceModel.point_ids()
    >>> ids[0], len(ids)
)doc")
        .def_static("fapu_names", &FaceModel::fapu_names, R"doc(
The 12 FAPU names in file order: d, EyebrowH, EyebrowH2, LeftEyeH, RightEyeH, UpperLipH, LowerLipH,
MNS0, MW0, JawH, r1, r2.

Example:
    >>> talkface.FaceModel.fapu_names()[0]
    'd'
)doc")
        .def_static("is_point_id", &FaceModel::is_point_id, py::arg("id"), R"doc(
Whether id names one of the 72 points.

Args:
    id (str): a point id such as "8.3".

Example:
    >>> talkface.FaceModel.is_point_id("8.3"), talkface.FaceModel.is_point_id("8.5")
    (True, False)
)doc")
        .def("point", &FaceModel::point, py::arg("id"), R"doc(
A point's image position.

Args:
    id (str): a point id such as "3.2".

Returns:
    tuple[float, float]: (x, y) in image pixels, y down.

Raises:
    talkface.InvalidArgument: an unknown id (the message names it).

Example:
    >>> x, y = face.point("3.2")
    >>> face.set_point("3.2", (x, y - 2.0))
)doc")
        .def("set_point", &FaceModel::set_point, py::arg("id"), py::arg("image_xy"), R"doc(
Moves a point.

Args:
    id (str): a point id.
    image_xy (tuple[float, float]): the new (x, y), image pixels.

Raises:
    talkface.InvalidArgument: an unknown id, or a coordinate not finite or beyond +-1e6.

Example:
    >>> face.set_point("8.3", (140.0, 212.5))
    >>> face.point("8.3")
)doc")
        .def(
            "points", [](const FaceModel& face) { return points_to_array(face.points()); }, R"doc(
All 72 points as a new (72, 2) float64 array of (x, y) image pixels, in point_ids() order.

Example:
    >>> xy = face.points()
    >>> xy[talkface.FaceModel.point_ids().index("3.2")]
)doc")
        .def("set_points", &set_points, py::arg("points"), R"doc(
Moves all 72 points at once; all or nothing.

Args:
    points (numpy.ndarray): shape (72, 2), (x, y) image pixels in point_ids() order; converted to float64.

Raises:
    talkface.InvalidArgument: the shape is wrong ("points: expected shape (72, 2), got (70, 2)") or a
        value is not finite or lies beyond +-1e6.

Example:
    >>> xy = face.points(); xy[:, 0] += 10.0
    >>> face.set_points(xy)
)doc")
        .def("fapu", &FaceModel::fapu, py::arg("name"), R"doc(
A FAPU (facial animation parameter unit) in pixels.

Args:
    name (str): one of FaceModel.fapu_names(), e.g. "d" (eyeball distance), "MW0" (mouth width).

Raises:
    talkface.InvalidArgument: an unknown name.

Example:
    >>> face.fapu("d")
    >>> face.fapu("MW0") / face.fapu("d")
)doc")
        .def("set_fapu", &FaceModel::set_fapu, py::arg("name"), py::arg("value_px"), R"doc(
Sets a FAPU.

Args:
    name (str): one of FaceModel.fapu_names().
    value_px (float): pixels, finite, positive and at most 1e7.

Raises:
    talkface.InvalidArgument: an unknown name or a value out of that range.

Example:
    >>> face.set_fapu("JawH", 20.0)
    >>> face.fapu("JawH")
)doc")
        .def("fapus", &fapus_dict, R"doc(
All 12 FAPUs as a new dict {name: pixels}, in fapu_names() order.

Example:
    >>> fapus = face.fapus()
    >>> fapus["d"] == face.fapu("d")
)doc")
        .def_property(
            "colors", [](const FaceModel& face) { return face.colors(); }, &FaceModel::set_colors, R"doc(
The colours the face is drawn with (a copy: change it and assign it back).

Example:
    >>> colors = face.colors; colors.skin = "#f0c8a0"
    >>> face.colors = colors
)doc")
        .def_property("name", &FaceModel::name, &FaceModel::set_name, R"doc(
A label, e.g. "default" (str).

Example:
    >>> face.name = "announcer"
    >>> face.name
)doc")
        .def(
            "__eq__", [](const FaceModel& a, const FaceModel& b) { return a == b; },
            py::is_operator())
        .def("__copy__", [](const FaceModel& face) { return FaceModel(face); })
        .def(
            "__deepcopy__", [](const FaceModel& face, const py::dict&) { return FaceModel(face); },
            py::arg("memo"))
        .def(py::pickle([](const FaceModel& face) { return py::make_tuple(face.to_xml()); },
                        [](const py::tuple& state) {
                            return FaceModel::from_xml(state[0].cast<std::string>(), "<pickle>");
                        }))
        .def("__repr__", [](const FaceModel& face) {
            return py::str("<talkface.FaceModel {!r} d={!r} px>").format(face.name(), face.fapu("d"));
        });
    m.attr("FaceModel").attr("kPointCount") = FaceModel::kPointCount;
    m.attr("FaceModel").attr("kFapuCount") = FaceModel::kFapuCount;
    m.attr("FaceModel").attr("kFileFormatVersion") = FaceModel::kFileFormatVersion;
}

}  // namespace talkface::python

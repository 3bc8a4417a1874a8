// Shared by the bind_*.cpp files of the _talkface module: one bind_ function per public object, and
// the conversions every file must see identically (pybind11 requires a type caster to be visible in
// every translation unit that binds the type).
#ifndef TALKFACE_BINDINGS_PYTHON_BIND_HPP
#define TALKFACE_BINDINGS_PYTHON_BIND_HPP

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <optional>
#include <string>
#include <utility>

#include "talkface/talkface.hpp"

namespace talkface::python {

namespace py = pybind11;

void bind_errors(py::module_& m);
void bind_face_model(py::module_& m);
void bind_face_lift(py::module_& m);
void bind_rotation3d(py::module_& m);
void bind_face_state(py::module_& m);
void bind_svg_animator(py::module_& m);
void bind_frame_renderer(py::module_& m);
void bind_transcript(py::module_& m);
void bind_timeline_json(py::module_& m);
void bind_timing_formats(py::module_& m);
void bind_lip_sync(py::module_& m);
void bind_expression_simulator(py::module_& m);
void bind_animation(py::module_& m);
void bind_speech_aligner(py::module_& m);
void bind_web_page(py::module_& m);
void bind_photo(py::module_& m);  // the _talkface_photo module (photo_module.cpp)
void bind_video_writer(py::module_& m);

// The progress callable as a ProgressCallback, for the long calls (alignment, video). The work runs
// without the GIL, so each report takes it back. An exception the callable raises cancels the work
// and is kept, to be raised in place of talkface.Cancelled once the library has unwound. With no
// callable, each report still checks for signals, so that Ctrl-C stops long work with
// KeyboardInterrupt.
class PythonProgress {
public:
    explicit PythonProgress(py::object progress) : progress_(std::move(progress)) {}

    // Called on the working thread, without the GIL.
    bool report(double fraction, const std::string& stage) {
        py::gil_scoped_acquire gil;
        try {
            if (progress_.is_none()) {
                if (PyErr_CheckSignals() != 0) throw py::error_already_set();
                return true;
            }
            const py::object result = progress_(fraction, stage);
            if (result.is_none()) return true;
            const int is_true = PyObject_IsTrue(result.ptr());
            if (is_true < 0) throw py::error_already_set();
            return is_true == 1;
        } catch (py::error_already_set& error) {
            error_ = std::move(error);
            return false;
        }
    }

    // Called with the GIL once the work was cancelled.
    void raise_callback_error() {
        if (error_) throw std::move(*error_);
    }

private:
    py::object progress_;
    std::optional<py::error_already_set> error_;
};

// Runs `work(callback)` without the GIL; called with it.
template <typename Work>
auto run_without_gil(const py::object& progress, Work&& work) {
    PythonProgress bridge(progress);
    try {
        py::gil_scoped_release release;
        return work([&bridge](double fraction, const std::string& stage) { return bridge.report(fraction, stage); });
    } catch (const Cancelled&) {
        bridge.raise_callback_error();
        throw;
    }
}

// A float64 array of `rows` x `columns`, C order (a copy the caller owns).
inline py::array_t<double> new_matrix(py::ssize_t rows, py::ssize_t columns) {
    return py::array_t<double>({rows, columns});
}

// "(70, 2)": an array's shape as numpy prints it, for error messages. Inline: both extension
// modules (_talkface, _talkface_photo) use it.
inline std::string shape_text(const py::array& array) {
    std::string text = "(";
    for (py::ssize_t axis = 0; axis < array.ndim(); ++axis) {
        if (axis > 0) text += ", ";
        text += std::to_string(array.shape(axis));
    }
    return text + (array.ndim() == 1 ? ",)" : ")");
}

// Points as an (N, 2) array, in order.
template <typename Points>
py::array_t<double> points_to_array(const Points& points) {
    auto array = new_matrix(static_cast<py::ssize_t>(points.size()), 2);
    auto view = array.mutable_unchecked<2>();
    py::ssize_t row = 0;
    for (const Point2& point : points) {
        view(row, 0) = point.x;
        view(row, 1) = point.y;
        ++row;
    }
    return array;
}

// The ids of named points (LiftedPoint, ProjectedPoint), in order: Python reads a face's points as
// a list of ids beside a numpy array of coordinates.
template <typename NamedPoint>
std::vector<std::string> ids_of(const std::vector<NamedPoint>& points) {
    std::vector<std::string> ids;
    ids.reserve(points.size());
    for (const NamedPoint& point : points) ids.push_back(point.id);
    return ids;
}

}  // namespace talkface::python

namespace pybind11::detail {

// Point2 crosses as a tuple (x, y): image pixels read as Python users expect ("face.point('3.2') ->
// (x, y)"); any sequence of two numbers is accepted.
template <>
struct type_caster<talkface::Point2> {
    PYBIND11_TYPE_CASTER(talkface::Point2, const_name("tuple[float, float]"));

    bool load(handle source, bool convert) {
        if (!isinstance<sequence>(source) || isinstance<str>(source)) return false;
        const auto items = reinterpret_borrow<sequence>(source);
        if (items.size() != 2) return false;
        make_caster<double> x;
        make_caster<double> y;
        if (!x.load(items[0], convert) || !y.load(items[1], convert)) return false;
        value = talkface::Point2{cast_op<double>(x), cast_op<double>(y)};
        return true;
    }

    static handle cast(const talkface::Point2& point, return_value_policy, handle) {
        return make_tuple(point.x, point.y).release();
    }
};

// Point3 crosses as a tuple (x, y, z) in the local frame.
template <>
struct type_caster<talkface::Point3> {
    PYBIND11_TYPE_CASTER(talkface::Point3, const_name("tuple[float, float, float]"));

    bool load(handle source, bool convert) {
        if (!isinstance<sequence>(source) || isinstance<str>(source)) return false;
        const auto items = reinterpret_borrow<sequence>(source);
        if (items.size() != 3) return false;
        make_caster<double> x;
        make_caster<double> y;
        make_caster<double> z;
        if (!x.load(items[0], convert) || !y.load(items[1], convert) || !z.load(items[2], convert)) {
            return false;
        }
        value = talkface::Point3{cast_op<double>(x), cast_op<double>(y), cast_op<double>(z)};
        return true;
    }

    static handle cast(const talkface::Point3& point, return_value_policy, handle) {
        return make_tuple(point.x, point.y, point.z).release();
    }
};

// Rgb crosses as "#rrggbb" (read: "#rrggbb" or "#rgb"), the form of the face file and of SVG.
template <>
struct type_caster<talkface::Rgb> {
    PYBIND11_TYPE_CASTER(talkface::Rgb, const_name("str"));

    bool load(handle source, bool) {
        if (!isinstance<str>(source)) return false;
        value = talkface::rgb_from_hex(source.cast<std::string>());
        return true;
    }

    static handle cast(const talkface::Rgb& colour, return_value_policy, handle) {
        return str(talkface::to_hex(colour)).release();
    }
};

}  // namespace pybind11::detail

#endif

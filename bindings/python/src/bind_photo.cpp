// Face from a photo (talkface/face_from_photo.hpp), in the _talkface_photo module that links
// talkface::photo: talkface.face_from_photo() with the confidence of every feature,
// FaceModel.from_photo() for the face alone. A photo is a path or a numpy uint8
// array (H, W) grey, (H, W, 3) RGB or (H, W, 4) RGBA.
#include <filesystem>
#include <optional>
#include <variant>

#include "bind.hpp"
#include "talkface/face_from_photo.hpp"

namespace talkface::python {

namespace {

using Photo = std::variant<std::filesystem::path, py::array>;

PhotoOptions make_options(const std::string& locator, int face_index, const std::string& cascade_dir,
                          const std::string& dlib_model_path, int min_face_width_px) {
    PhotoOptions options;
    options.locator = photo_locator_from_name(locator);
    options.face_index = face_index;
    options.cascade_dir = cascade_dir;
    options.dlib_model_path = dlib_model_path;
    options.min_face_width_px = min_face_width_px;
    return options;
}

// Checks the array under the GIL; the pixels are read later without it, so the array is kept as a
// C-contiguous uint8 copy or view that the caller's frame holds alive.
py::array_t<std::uint8_t, py::array::c_style> checked_pixels(const py::array& array, PixelFormat& format) {
    if (!py::isinstance<py::array_t<std::uint8_t>>(array)) {
        throw InvalidArgument("photo", "expected a uint8 array, got dtype " + py::str(array.dtype()).cast<std::string>());
    }
    auto pixels = py::array_t<std::uint8_t, py::array::c_style | py::array::forcecast>::ensure(array);
    if (pixels.ndim() == 2) {
        format = PixelFormat::gray8;
    } else if (pixels.ndim() == 3 && pixels.shape(2) == 3) {
        format = PixelFormat::rgb8;
    } else if (pixels.ndim() == 3 && pixels.shape(2) == 4) {
        format = PixelFormat::rgba8;
    } else {
        throw InvalidArgument("photo", "expected shape (H, W), (H, W, 3) or (H, W, 4), got " + shape_text(array));
    }
    return pixels;
}

PhotoFaceResult extract(const Photo& photo, const PhotoOptions& options) {
    if (const auto* path = std::get_if<std::filesystem::path>(&photo)) {
        py::gil_scoped_release release;
        return face_from_photo_file(path->string(), options);
    }
    PixelFormat format = PixelFormat::rgb8;
    const auto pixels = checked_pixels(std::get<py::array>(photo), format);
    const int channels = pixels.ndim() == 2 ? 1 : static_cast<int>(pixels.shape(2));
    const ImageView view{pixels.data(), static_cast<int>(pixels.shape(1)), static_cast<int>(pixels.shape(0)),
                         static_cast<int>(pixels.shape(1)) * channels, format};
    py::gil_scoped_release release;
    return face_from_photo(view, options);
}

constexpr const char* kPhotoArguments = R"doc(
Args:
    photo: a path (PNG or JPEG) or a numpy uint8 array (H, W), (H, W, 3) RGB or
        (H, W, 4) RGBA.
    locator: "thesis" (OpenCV only), "dlib" (68-point model) or "automatic" (dlib where installed).
    face_index: which face when the photo shows several, 0 = leftmost; -1 refuses such a photo.
    cascade_dir: folder of OpenCV's Haar cascades; "" = opencv-data's.
    dlib_model_path: dlib's shape_predictor_68_face_landmarks.dat; "" = libdlib-data's.
    min_face_width_px: the smallest face accepted, its detected width in pixels (at least 16).

Raises:
    talkface.InvalidArgument (a ValueError) naming the photo: no face, several faces, face too small,
        too dark, not frontal enough; a malformed array.
    FileNotFoundError / OSError: the photo, a Haar cascade or the dlib model cannot be read; the
        photo is not a PNG or JPEG, is broken or truncated, or is over 100 megapixels.

The GIL is released while the photo is read.
)doc";

}  // namespace

void bind_photo(py::module_& m) {
    py::class_<PhotoFeature>(m, "PhotoFeature", R"doc(
One located feature of a photo and how sure the locator is of it.

Example:
    >>> weak = [f.name for f in result.features if f.from_prior]
)doc")
        .def_readonly("name", &PhotoFeature::name, "\"left_eye\", \"mouth\", \"hair\", ... (left = image left)")
        .def_readonly("confidence", &PhotoFeature::confidence, "0 (not found) .. 1 (certain)")
        .def_readonly("from_prior", &PhotoFeature::from_prior,
                      "True when the points come from the default face's proportions (not found)")
        .def_readonly("source", &PhotoFeature::source, "\"haar\", \"thesis\", \"dlib\", \"regions\" or \"prior\"")
        .def("__repr__", [](const PhotoFeature& f) {
            return "PhotoFeature(" + f.name + ", confidence=" + std::to_string(f.confidence) +
                   (f.from_prior ? ", from_prior" : "") + ")";
        });

    py::class_<PhotoFaceResult>(m, "PhotoFaceResult", R"doc(
What talkface.face_from_photo() found: the face (photo pixels) and every feature's confidence.

Example:
    >>> result = talkface.face_from_photo("me.jpg")
    >>> result.face.save("me.xml"); result.confidence("mouth")
)doc")
        .def_readonly("face", &PhotoFaceResult::face, "the FaceModel, in the photo's pixels")
        .def_readonly("features", &PhotoFaceResult::features, "list of PhotoFeature")
        .def_property_readonly(
            "locator", [](const PhotoFaceResult& r) { return std::string(photo_locator_name(r.locator_used)); },
            "\"thesis\" or \"dlib\": the locator that was used")
        .def_property_readonly(
            "face_box",
            [](const PhotoFaceResult& r) {
                return py::make_tuple(r.face_box.x, r.face_box.y, r.face_box.width, r.face_box.height);
            },
            "(x, y, width, height) of the detected face, photo pixels")
        .def_readonly("faces_found", &PhotoFaceResult::faces_found, "faces detected in the photo")
        .def("confidence", &PhotoFaceResult::confidence, py::arg("feature_name"), R"doc(
The confidence (0..1) of the named feature.

Raises:
    talkface.InvalidArgument: for an unknown name.

Example:
    >>> result.confidence("left_eye")
)doc")
        .def(
            "write_overlay",
            [](const PhotoFaceResult& r, const std::filesystem::path& photo, const std::filesystem::path& output) {
                py::gil_scoped_release release;
                write_photo_overlay(photo.string(), r, output.string());
            },
            py::arg("photo"), py::arg("output_png"), R"doc(
Writes the photo with the extracted points drawn on it as a PNG (atomically).

Raises:
    FileNotFoundError / OSError: the photo cannot be read or the PNG written.

Example:
    >>> result.write_overlay("me.jpg", "me-points.png")
)doc");

    m.def("has_dlib_locator", &has_dlib_locator, R"doc(
Whether this build has the dlib 68-point locator.

Example:
    >>> talkface.has_dlib_locator()
)doc");

    m.def(
        "face_from_photo",
        [](const Photo& photo, const std::string& locator, int face_index, const std::string& cascade_dir,
           const std::string& dlib_model_path, int min_face_width_px) {
            return extract(
                photo, make_options(locator, face_index, cascade_dir, dlib_model_path, min_face_width_px));
        },
        py::arg("photo"), py::kw_only(), py::arg("locator") = "automatic", py::arg("face_index") = -1,
        py::arg("cascade_dir") = "", py::arg("dlib_model_path") = "",
        py::arg("min_face_width_px") = PhotoOptions{}.min_face_width_px,
        (std::string(R"doc(
A face model from a frontal photo of a neutral face, with the confidence of every feature.
)doc") + kPhotoArguments +
         R"doc(
Example:
    >>> result = talkface.face_from_photo("me.jpg", locator="thesis")
    >>> [f.name for f in result.features if f.from_prior]
)doc")
            .c_str());

    // talkface.FaceModel.from_photo (talkface/__init__.py) calls this, importing the module on demand.
    m.def(
        "face_model_from_photo",
        [](const Photo& photo, const std::string& locator, int face_index, const std::string& cascade_dir,
           const std::string& dlib_model_path, int min_face_width_px) {
            return extract(photo,
                           make_options(locator, face_index, cascade_dir, dlib_model_path, min_face_width_px))
                .face;
        },
        py::arg("photo"), py::kw_only(), py::arg("locator") = "automatic", py::arg("face_index") = -1,
        py::arg("cascade_dir") = "", py::arg("dlib_model_path") = "",
        py::arg("min_face_width_px") = PhotoOptions{}.min_face_width_px,
        (std::string(R"doc(
The face model (photo pixels) of a frontal photo of a neutral face; talkface.face_from_photo() also
gives each feature's confidence.
)doc") + kPhotoArguments +
         R"doc(
Example:
    >>> face = talkface.FaceModel.from_photo("me.jpg")
    >>> face.save("me.xml")
)doc")
            .c_str());
}

}  // namespace talkface::python

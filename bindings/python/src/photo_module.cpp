// The _talkface_photo extension module: face from a photo, apart from _talkface so that
// `import talkface` loads no OpenCV; talkface/__init__.py imports this on the first photo call.
#include "bind.hpp"

PYBIND11_MODULE(_talkface_photo, m) {
    namespace py = pybind11;
    m.doc() = R"doc(
talkface's face from a photo (the compiled photo stage; use talkface.face_from_photo and
talkface.FaceModel.from_photo, which import this on demand).
)doc";
    // FaceModel and the exception types are _talkface's: registered first, so results and errors
    // cross as those types.
    py::module_::import("talkface._talkface");
    talkface::python::bind_photo(m);
}

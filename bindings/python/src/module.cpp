// The _talkface extension module. Users `import talkface` (bindings/python/talkface/__init__.py), which
// re-exports everything here.
#include "bind.hpp"

PYBIND11_MODULE(_talkface, m) {
    namespace py = pybind11;
    using namespace talkface::python;

    m.doc() = R"doc(
talkface: talking cartoon faces (the compiled core; import talkface, not _talkface).
)doc";
    m.attr("__version__") = TALKFACE_VERSION_STRING;
    m.def("version", &talkface::version, R"doc(
The version of the loaded talkface library, "MAJOR.MINOR.PATCH" (compare with __version__, the
version the module was built against).

Example:
    >>> talkface.version()
    >>> talkface.version() == talkface.__version__
)doc");

    bind_errors(m);
    bind_face_model(m);
    bind_face_lift(m);
    bind_rotation3d(m);
    bind_face_state(m);
    bind_svg_animator(m);
    bind_transcript(m);
    bind_timeline_json(m);
    bind_lip_sync(m);
    bind_expression_simulator(m);
    bind_animation(m);
    bind_speech_aligner(m);
    bind_web_page(m);
}

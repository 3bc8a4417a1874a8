// FrameLayout, AlphaMode, FrameOptions and FrameRenderer in Python: frames as numpy arrays
// (H, W, 4) uint8, drawn without the GIL.
#include <mutex>

#include "bind.hpp"

namespace talkface::python {

namespace {

// A FrameRenderer keeps its last frame and cache: one frame at a time. Python threads that share a
// renderer take turns on this lock, taken after the GIL is released.
struct SharedFrameRenderer {
    FrameRenderer renderer;
    std::mutex mutex;
};

}  // namespace

void bind_frame_renderer(py::module_& m) {
    py::enum_<FrameLayout>(m, "FrameLayout", "Where the face stands in a frame.")
        .value("announcer", FrameLayout::announcer,
               "thesis 7.2: on a stage of the frame's size, standing on its bottom edge (the default)")
        .value("face", FrameLayout::face, "the face's SVG canvas fitted into the frame and centred");
    py::enum_<AlphaMode>(m, "AlphaMode", "How the bytes of a pixel carry alpha.")
        .value("straight", AlphaMode::straight, "R, G, B not multiplied by A (PNG, Pillow, FFmpeg's rgba)")
        .value("premultiplied", AlphaMode::premultiplied, "R, G, B multiplied by A / 255");

    py::class_<FrameOptions>(m, "FrameOptions", R"doc(
How frames are drawn; checked when a FrameRenderer is made. Colours are "#rrggbb" strings.

Example:
    >>> options = talkface.FrameOptions(width_px=640, height_px=360, background=None)
    >>> talkface.FrameRenderer(face, options)
)doc")
        .def(py::init([](int width_px, int height_px, FrameLayout layout, std::optional<Rgb> background,
                         bool draw_clothes, Rgb clothes, double stroke_width_in_d, std::optional<Point2> face_origin_px,
                         double face_d_px, AlphaMode alpha, FaceLook look) {
                 FrameOptions options;
                 options.width_px = width_px;
                 options.height_px = height_px;
                 options.layout = layout;
                 options.background = background;
                 options.draw_clothes = draw_clothes;
                 options.clothes = clothes;
                 options.stroke_width_in_d = stroke_width_in_d;
                 options.face_origin_px = face_origin_px;
                 options.face_d_px = face_d_px;
                 options.alpha = alpha;
                 options.look = look;
                 return options;
             }),
             py::arg("width_px") = FrameOptions{}.width_px, py::arg("height_px") = FrameOptions{}.height_px,
             py::arg("layout") = FrameOptions{}.layout, py::arg("background") = FrameOptions{}.background,
             py::arg("draw_clothes") = FrameOptions{}.draw_clothes, py::arg("clothes") = FrameOptions{}.clothes,
             py::arg("stroke_width_in_d") = FrameOptions{}.stroke_width_in_d,
             py::arg("face_origin_px") = FrameOptions{}.face_origin_px,
             py::arg("face_d_px") = FrameOptions{}.face_d_px, py::arg("alpha") = FrameOptions{}.alpha,
             py::arg("look") = FrameOptions{}.look, R"doc(
Args:
    width_px, height_px (int): frame size, 1..7680 by 1..4320.
    layout (FrameLayout): announcer (the face on a stage, the default) or face.
    background (str | None): colour "#rrggbb" under everything; None leaves the frame transparent.
    draw_clothes (bool): draw the clothes layer (neck and shoulders).
    clothes (str): clothes colour "#rrggbb".
    stroke_width_in_d (float): outline width, in units of d (eyeball distance).
    face_origin_px ((float, float) | None): announcer: where the face's rotation origin O stands,
        frame pixels; None: centred, standing on the bottom edge.
    face_d_px (float): announcer: the face's eye distance d in frame pixels; 0: as tall as the frame.
    alpha (AlphaMode): straight (the default) or premultiplied.
    look (FaceLook): outlined (the thesis's cartoon, the default) or flat (no outlines).

Raises:
    talkface.InvalidArgument: a colour is not "#rrggbb" or "#rgb".

Example:
    >>> talkface.FrameOptions(layout=talkface.FrameLayout.face, width_px=480, height_px=560)
)doc")
        .def_readwrite("width_px", &FrameOptions::width_px, "frame width, pixels")
        .def_readwrite("height_px", &FrameOptions::height_px, "frame height, pixels")
        .def_readwrite("layout", &FrameOptions::layout, "where the face stands")
        .def_readwrite("background", &FrameOptions::background, "\"#rrggbb\" or None (transparent)")
        .def_readwrite("draw_clothes", &FrameOptions::draw_clothes, "draw the clothes layer")
        .def_readwrite("clothes", &FrameOptions::clothes, "clothes colour, \"#rrggbb\"")
        .def_readwrite("look", &FrameOptions::look, "how the shapes are painted (FaceLook)")
        .def_readwrite("stroke_width_in_d", &FrameOptions::stroke_width_in_d, "outline width, units of d")
        .def_readwrite("face_origin_px", &FrameOptions::face_origin_px, "announcer: O in frame pixels, or None")
        .def_readwrite("face_d_px", &FrameOptions::face_d_px, "announcer: d in frame pixels (0: fit the height)")
        .def_readwrite("alpha", &FrameOptions::alpha, "straight or premultiplied alpha")
        .def("__repr__", [](const FrameOptions& o) {
            return py::str("talkface.FrameOptions(width_px={!r}, height_px={!r}, layout={}, background={!r}, "
                           "draw_clothes={!r}, clothes={!r}, stroke_width_in_d={!r}, face_origin_px={!r}, "
                           "face_d_px={!r}, alpha={}, look={})")
                .format(o.width_px, o.height_px, py::cast(o.layout), o.background, o.draw_clothes, o.clothes,
                        o.stroke_width_in_d, o.face_origin_px, o.face_d_px, py::cast(o.alpha), py::cast(o.look));
        });

    py::class_<SharedFrameRenderer>(m, "FrameRenderer", R"doc(
Draws face states as RGBA pixels with cairo: the layers of SvgAnimator's SVG (background, hair,
clothes, face), antialiased, at any size. What does not move is drawn once, and only the region the
head covers is drawn again each frame. Frames come back as numpy arrays (H, W, 4) uint8.

Example:
    >>> renderer = talkface.FrameRenderer(talkface.FaceModel.default())
    >>> frame = renderer.render_frame_rgba(talkface.FaceState())
    >>> frame.shape
    (720, 1280, 4)
)doc")
        .def(py::init([](const FaceModel& face, const FrameOptions& options) {
                 return new SharedFrameRenderer{FrameRenderer(face, options), {}};
             }),
             py::arg("face"), py::arg("options") = FrameOptions{}, R"doc(
Args:
    face (FaceModel): the neutral face.
    options (FrameOptions): size, layout, colours, alpha.

Raises:
    talkface.InvalidArgument (a ValueError) naming an option out of range.
)doc")
        .def_property_readonly("face", [](const SharedFrameRenderer& r) { return r.renderer.face(); },
                               "the neutral face")
        .def_property_readonly("options", [](const SharedFrameRenderer& r) { return r.renderer.options(); },
                               "the options it was made with")
        .def_property_readonly("width_px", [](const SharedFrameRenderer& r) { return r.renderer.width_px(); },
                               "frame width, pixels")
        .def_property_readonly("height_px", [](const SharedFrameRenderer& r) { return r.renderer.height_px(); },
                               "frame height, pixels")
        .def(
            "render_frame_rgba",
            [](SharedFrameRenderer& shared, const FaceState& state) {
                FrameRenderer& renderer = shared.renderer;
                py::array_t<std::uint8_t> frame({static_cast<py::ssize_t>(renderer.height_px()),
                                                 static_cast<py::ssize_t>(renderer.width_px()), py::ssize_t{4}});
                std::uint8_t* pixels = frame.mutable_data();
                const FaceState state_copy = state;
                {
                    py::gil_scoped_release release;
                    const std::lock_guard<std::mutex> lock(shared.mutex);
                    renderer.render_frame_rgba(state_copy, pixels, renderer.stride_bytes());
                }
                return frame;
            },
            py::arg("state"), R"doc(
The face at `state` as a new array (height_px, width_px, 4) of uint8: R, G, B, A, alpha as the
options say. Releases the GIL while it draws; threads sharing a renderer take turns.

Raises:
    talkface.InvalidArgument: the state does not fit the face (as project_face).

Example:
    >>> state = talkface.FaceState(); state.mouth = talkface.mouth_controls(face, talkface.MouthShape.a)
    >>> PIL.Image.fromarray(renderer.render_frame_rgba(state)).save("frame.png")
)doc")
        .def(
            "set_background_image",
            [](SharedFrameRenderer& shared, const py::array& image) {
                if (!py::isinstance<py::array_t<std::uint8_t>>(image)) {
                    throw InvalidArgument("image", "expected a uint8 array, got dtype " +
                                                       py::str(image.dtype()).cast<std::string>());
                }
                auto pixels = py::array_t<std::uint8_t, py::array::c_style | py::array::forcecast>::ensure(image);
                if (pixels.ndim() != 3 || pixels.shape(2) != 4) {
                    throw InvalidArgument("image", "expected shape (H, W, 4) RGBA, got " + shape_text(image));
                }
                const int height = static_cast<int>(pixels.shape(0));
                const int width = static_cast<int>(pixels.shape(1));
                py::gil_scoped_release release;
                const std::lock_guard<std::mutex> lock(shared.mutex);
                shared.renderer.set_background_image(pixels.data(), width, height, 4 * static_cast<std::size_t>(width));
            },
            py::arg("image"), R"doc(
Draws a picture over the background colour, covering the frame (scaled to fill it, centred, the
overflow cropped), under the face.

Args:
    image (numpy.ndarray): (H, W, 4) uint8, straight-alpha RGBA; copied.

Raises:
    talkface.InvalidArgument: another dtype or shape.

Example:
    >>> renderer.set_background_image(numpy.asarray(PIL.Image.open("studio.png").convert("RGBA")))
)doc")
        .def("__repr__", [](const SharedFrameRenderer& r) {
            return py::str("<talkface.FrameRenderer {}x{}>").format(r.renderer.width_px(), r.renderer.height_px());
        });
}

}  // namespace talkface::python

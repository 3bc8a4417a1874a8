// FaceLook, SvgOptions, SvgAnimationOptions and SvgAnimator in Python; rendering runs without the GIL.
#include "bind.hpp"

namespace talkface::python {

void bind_svg_animator(py::module_& m) {
    m.attr("kMaxSvgDecimals") = kMaxSvgDecimals;
    py::enum_<FaceLook>(m, "FaceLook", "How a face's shapes are painted (SvgOptions.look, FrameOptions.look).")
        .value("outlined", FaceLook::outlined, "the thesis's cartoon: filled shapes with dark outlines (the default)")
        .value("flat", FaceLook::flat, "no outlines: flat fills told apart by colour, soft shades");
    py::class_<SvgOptions>(m, "SvgOptions", R"doc(
How a face is drawn; checked when an SvgAnimator is made. Colours are "#rrggbb" strings.

Example:
    >>> options = talkface.SvgOptions(background=None, draw_clothes=False)
    >>> talkface.SvgAnimator(face, options)
)doc")
        .def(py::init([](std::optional<Rgb> background, bool draw_clothes, Rgb clothes,
                         double stroke_width_in_d, int decimals, int width_px, int height_px, FaceLook look) {
                 SvgOptions options;
                 options.background = background;
                 options.draw_clothes = draw_clothes;
                 options.clothes = clothes;
                 options.look = look;
                 options.stroke_width_in_d = stroke_width_in_d;
                 options.decimals = decimals;
                 options.width_px = width_px;
                 options.height_px = height_px;
                 return options;
             }),
             py::arg("background") = SvgOptions{}.background,
             py::arg("draw_clothes") = SvgOptions{}.draw_clothes, py::arg("clothes") = SvgOptions{}.clothes,
             py::arg("stroke_width_in_d") = SvgOptions{}.stroke_width_in_d,
             py::arg("decimals") = SvgOptions{}.decimals, py::arg("width_px") = SvgOptions{}.width_px,
             py::arg("height_px") = SvgOptions{}.height_px, py::arg("look") = SvgOptions{}.look, R"doc(
Args:
    background (str | None): background colour "#rrggbb"; None leaves it transparent.
    draw_clothes (bool): draw the clothes layer (neck and shoulders).
    clothes (str): clothes colour "#rrggbb".
    stroke_width_in_d (float): outline width, in units of d (eyeball distance).
    decimals (int): digits after the point in coordinates, 0..kMaxSvgDecimals (6).
    width_px, height_px (int): canvas size, pixels; 0 fits the face at any pose with a margin.
    look (FaceLook): outlined (the thesis's cartoon, the default) or flat (no outlines).

Raises:
    talkface.InvalidArgument: a colour is not "#rrggbb" or "#rgb".

Example:
    >>> talkface.SvgOptions(width_px=480, height_px=560)
    >>> talkface.SvgOptions(background="#ffffff", decimals=1)
)doc")
        .def_readwrite("background", &SvgOptions::background, "\"#rrggbb\" or None (transparent)")
        .def_readwrite("draw_clothes", &SvgOptions::draw_clothes, "draw the clothes layer")
        .def_readwrite("clothes", &SvgOptions::clothes, "clothes colour, \"#rrggbb\"")
        .def_readwrite("look", &SvgOptions::look, "how the shapes are painted (FaceLook)")
        .def_readwrite("stroke_width_in_d", &SvgOptions::stroke_width_in_d, "outline width, units of d")
        .def_readwrite("decimals", &SvgOptions::decimals, "digits after the point (0..kMaxSvgDecimals)")
        .def_readwrite("width_px", &SvgOptions::width_px, "canvas width, pixels (0 = fit)")
        .def_readwrite("height_px", &SvgOptions::height_px, "canvas height, pixels (0 = fit)")
        .def("__repr__", [](const SvgOptions& o) {
            return py::str(
                       "talkface.SvgOptions(background={!r}, draw_clothes={!r}, clothes={!r}, "
                       "stroke_width_in_d={!r}, decimals={!r}, width_px={!r}, height_px={!r}, look={})")
                .format(o.background, o.draw_clothes, o.clothes, o.stroke_width_in_d, o.decimals, o.width_px,
                        o.height_px, py::cast(o.look));
        });

    py::enum_<AnimationEncoding>(m, "AnimationEncoding", R"doc(
How an animation becomes SVG: keyframes (the default; each moving element animated between key
frames by SMIL, small files) or frames (thesis 6.3.2: one group per frame shown in turn).
)doc")
        .value("keyframes", AnimationEncoding::keyframes)
        .value("frames", AnimationEncoding::frames);

    py::class_<SvgAnimationOptions>(m, "SvgAnimationOptions", R"doc(
How an animation is written: the encoding, and for key frames the largest distance in pixels between
what the browser interpolates and the frame at that time.

Example:
    >>> options = talkface.SvgAnimationOptions(encoding=talkface.AnimationEncoding.frames)
)doc")
        .def(py::init([](AnimationEncoding encoding, double tolerance_px) {
                 SvgAnimationOptions options;
                 options.encoding = encoding;
                 options.tolerance_px = tolerance_px;
                 return options;
             }),
             py::arg("encoding") = SvgAnimationOptions{}.encoding,
             py::arg("tolerance_px") = SvgAnimationOptions{}.tolerance_px)
        .def_readwrite("encoding", &SvgAnimationOptions::encoding)
        .def_readwrite("tolerance_px", &SvgAnimationOptions::tolerance_px)
        .def("__repr__", [](const SvgAnimationOptions& options) {
            return std::string("talkface.SvgAnimationOptions(encoding=") +
                   animation_encoding_name(options.encoding) + ", tolerance_px=" +
                   std::to_string(options.tolerance_px) + ")";
        });

    py::class_<SvgAnimator>(m, "SvgAnimator", R"doc(
Draws a face as SVG 1.1 in four layers (background, hair, clothes, face). Holds a copy of its face and
options. render_svg() and write_svg() release the GIL, so threads may render in parallel.

Example:
    >>> animator = talkface.SvgAnimator(talkface.FaceModel.default())
    >>> svg = animator.render_svg(talkface.FaceState())
)doc")
        .def(py::init<FaceModel, SvgOptions>(), py::arg("face"), py::arg("options") = SvgOptions{}, R"doc(
Args:
    face (FaceModel): the neutral face (copied).
    options (SvgOptions): how to draw it (copied).

Raises:
    talkface.InvalidArgument: an option is out of range (the message names it).

Example:
    >>> animator = talkface.SvgAnimator(face, talkface.SvgOptions(background=None))
    >>> animator.options.background is None
)doc")
        .def_property_readonly(
            "face", [](const SvgAnimator& animator) { return animator.face(); }, "the neutral face (a copy)")
        .def_property_readonly(
            "options", [](const SvgAnimator& animator) { return animator.options(); },
            "the drawing options (a copy)")
        .def(
            "render_svg",
            [](const SvgAnimator& animator, const FaceState& state) {
                const FaceState state_copy = state;  // the caller's object may change once the GIL is free
                std::string svg;
                {
                    py::gil_scoped_release release;
                    svg = animator.render_svg(state_copy);
                }
                return svg;
            },
            py::arg("state"), R"doc(
A standalone SVG document (str) of the face at state. Releases the GIL while it works.

Args:
    state (FaceState): pose (degrees), expression, mouth.

Raises:
    talkface.InvalidArgument: as project_face() does (an angle outside +-15 degrees, say).

Example:
    >>> svg = animator.render_svg(talkface.FaceState(pose=talkface.Pose(beta_deg=10)))
    >>> svg.startswith("<?xml")
)doc")
        .def(
            "write_svg",
            [](const SvgAnimator& animator, const std::filesystem::path& path, const FaceState& state) {
                const std::string path_text = path.string();
                const FaceState state_copy = state;
                py::gil_scoped_release release;
                animator.write_svg(path_text, state_copy);
            },
            py::arg("path"), py::arg("state"), R"doc(
Writes render_svg(state) to path through a temporary file and a rename: a failure leaves no partial
file. Releases the GIL while it works.

Args:
    path (str | os.PathLike): the SVG file to write.
    state (FaceState): pose (degrees), expression, mouth.

Raises:
    talkface.FileError: it cannot be written (also an OSError; .filename is the path).
    talkface.InvalidArgument: as render_svg().

Example:
    >>> animator.write_svg("face.svg", talkface.FaceState())
    >>> open("face.svg").read(5)
)doc")
        .def(
            "render_animation_svg",
            [](const SvgAnimator& animator, const Animation& animation, const SvgAnimationOptions& options) {
                const Animation animation_copy = animation;
                py::gil_scoped_release release;
                return animator.render_animation_svg(animation_copy, options);
            },
            py::arg("animation"), py::arg("options") = SvgAnimationOptions{}, R"doc(
A standalone SVG document (str) that plays the animation from document time 0 (root class
"tf-animation"), on the same canvas as render_svg(). Releases the GIL while it works.

Args:
    animation (Animation): from talkface.animate().
    options (SvgAnimationOptions): the encoding (key frames by default).

Raises:
    talkface.InvalidArgument: the animation has no frames, or an option is out of range.

Example:
    >>> svg = animator.render_animation_svg(talkface.animate(face, timeline, simulator))
    >>> "<animate" in svg
)doc")
        .def(
            "write_animation_svg",
            [](const SvgAnimator& animator, const std::filesystem::path& path, const Animation& animation,
               const SvgAnimationOptions& options) {
                const std::string path_text = path.string();
                const Animation animation_copy = animation;
                py::gil_scoped_release release;
                animator.write_animation_svg(path_text, animation_copy, options);
            },
            py::arg("path"), py::arg("animation"), py::arg("options") = SvgAnimationOptions{}, R"doc(
Writes render_animation_svg() to path through a temporary file and a rename. Releases the GIL.

Args:
    path (str | os.PathLike): the SVG file to write.
    animation (Animation): from talkface.animate().
    options (SvgAnimationOptions): the encoding.

Raises:
    talkface.FileError: it cannot be written; talkface.InvalidArgument: as render_animation_svg().

Example:
    >>> animator.write_animation_svg("talk.svg", animation)
    >>> open("talk.svg").read(5)
)doc")
        .def(
            "render_animation_lottie",
            [](const SvgAnimator& animator, const Animation& animation, double tolerance_px) {
                const Animation animation_copy = animation;
                LottieOptions options;
                options.tolerance_px = tolerance_px;
                py::gil_scoped_release release;
                return animator.render_animation_lottie(animation_copy, options);
            },
            py::arg("animation"), py::arg("tolerance_px") = LottieOptions{}.tolerance_px, R"doc(
The animation as one Lottie document (a JSON str, as lottie-web, lottie-android, lottie-ios and
rlottie play it): the same drawing as render_animation_svg() as Lottie shape layers, every moving
number animated between key frames within tolerance_px of every frame. Lottie carries no sound:
play the recording beside it. Releases the GIL while it works.

Args:
    animation (Animation): from talkface.animate().
    tolerance_px (float): the largest distance between an interpolated coordinate and the frame's (> 0).

Raises:
    talkface.InvalidArgument: the animation has no frames, or tolerance_px is not > 0.

Example:
    >>> lottie = json.loads(animator.render_animation_lottie(animation))
    >>> lottie["fr"]
)doc")
        .def(
            "write_animation_lottie",
            [](const SvgAnimator& animator, const std::filesystem::path& path, const Animation& animation,
               double tolerance_px) {
                const std::string path_text = path.string();
                const Animation animation_copy = animation;
                LottieOptions options;
                options.tolerance_px = tolerance_px;
                py::gil_scoped_release release;
                animator.write_animation_lottie(path_text, animation_copy, options);
            },
            py::arg("path"), py::arg("animation"), py::arg("tolerance_px") = LottieOptions{}.tolerance_px, R"doc(
Writes render_animation_lottie() to path through a temporary file and a rename. Releases the GIL.

Args:
    path (str | os.PathLike): the Lottie JSON file to write.
    animation (Animation): from talkface.animate().
    tolerance_px (float): as render_animation_lottie().

Raises:
    talkface.FileError: it cannot be written; talkface.InvalidArgument: as render_animation_lottie().

Example:
    >>> animator.write_animation_lottie("talk.json", animation)
)doc");
}

}  // namespace talkface::python

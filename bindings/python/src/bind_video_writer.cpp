// VideoFormat, VideoOptions and VideoWriter in Python; encoding runs without the GIL.
#include "bind.hpp"

#include <memory>
#include <optional>

namespace talkface::python {

namespace {

using SampleArray = py::array_t<float, py::array::c_style | py::array::forcecast>;
using PixelArray = py::array_t<std::uint8_t, py::array::c_style>;

// A VideoWriter and the sound array it reads while frames are written (VideoWriter keeps only a
// view), so the array lives as long as the writer needs it. An exception in a with block drops the
// writer at once (its temporary file goes with it), not when Python collects the object.
struct PyVideoWriter {
    std::optional<VideoWriter> writer;
    std::optional<SampleArray> samples;
    bool is_finished = false;

    VideoWriter& get() {
        if (!writer) throw InvalidArgument("VideoWriter", "was abandoned by an exception in its with block");
        return *writer;
    }
};

}  // namespace

void bind_video_writer(py::module_& m) {
    py::enum_<VideoFormat>(m, "VideoFormat", R"doc(
The kind of video file, told by the output's extension: mp4 (H.264 + AAC), webm (VP9 + Opus, alpha
if transparent), webp and gif (animated, no sound; gif: one palette, 1..50 fps), png_sequence
(OUT-000000.png, ...).
)doc")
        .value("mp4", VideoFormat::mp4)
        .value("webm", VideoFormat::webm)
        .value("webp", VideoFormat::webp)
        .value("png_sequence", VideoFormat::png_sequence)
        .value("gif", VideoFormat::gif);

    m.def("video_format_from_path", &video_format_from_path, py::arg("path"), R"doc(
The format of an output path by its extension (either case).

Raises:
    talkface.InvalidArgument: an unknown extension (named, with the known ones).

Example:
    >>> talkface.video_format_from_path("talk.mp4")
    VideoFormat.mp4
)doc");

    py::class_<VideoOptions>(m, "VideoOptions", R"doc(
How a video is encoded; checked when a VideoWriter is opened (or by check_video_options).

Example:
    >>> options = talkface.VideoOptions(width_px=640, height_px=360, fps=25)
)doc")
        .def(py::init([](int width_px, int height_px, double fps, int crf, bool transparent) {
                 VideoOptions options;
                 options.width_px = width_px;
                 options.height_px = height_px;
                 options.fps = fps;
                 options.crf = crf;
                 options.transparent = transparent;
                 return options;
             }),
             py::arg("width_px") = VideoOptions{}.width_px, py::arg("height_px") = VideoOptions{}.height_px,
             py::arg("fps") = VideoOptions{}.fps, py::arg("crf") = VideoOptions{}.crf,
             py::arg("transparent") = VideoOptions{}.transparent, R"doc(
Args:
    width_px, height_px (int): frame size; 2..7680 by 2..4320 (either way round), even for .mp4 and .webm.
    fps (float): frames per second, 1..120.
    crf (int): constant quality, lower is better: H.264 0..51, VP9 0..63; -1 the default (20, 32).
    transparent (bool): keep the frames' alpha channel (.webm, .webp, .gif, .png only).

Example:
    >>> talkface.VideoOptions(transparent=True)
)doc")
        .def_readwrite("width_px", &VideoOptions::width_px, "frame width, pixels")
        .def_readwrite("height_px", &VideoOptions::height_px, "frame height, pixels")
        .def_readwrite("fps", &VideoOptions::fps, "frames per second")
        .def_readwrite("crf", &VideoOptions::crf, "constant quality (-1: the default)")
        .def_readwrite("transparent", &VideoOptions::transparent, "keep the alpha channel")
        .def("__repr__", [](const VideoOptions& o) {
            return py::str("talkface.VideoOptions(width_px={!r}, height_px={!r}, fps={!r}, crf={!r}, transparent={!r})")
                .format(o.width_px, o.height_px, o.fps, o.crf, o.transparent);
        });

    m.def("check_video_options", &check_video_options, py::arg("path"), py::arg("options") = VideoOptions{}, R"doc(
Checks options for an output at path, as VideoWriter does, without creating anything.

Raises:
    talkface.InvalidArgument: naming the option (width_px, height_px, fps, crf, transparent) or the
        extension, with what was expected.

Example:
    >>> talkface.check_video_options("talk.mp4", talkface.VideoOptions(width_px=1281))  # raises
)doc");

    py::class_<PyVideoWriter>(m, "VideoWriter", R"doc(
Encodes frames of RGBA pixels and a speech into a video through FFmpeg's libraries. Everything is
written to a temporary file beside the output and renamed by finish(); a writer dropped unfinished
(or left by an exception in a with block) leaves no file. write_frame() and finish() release the GIL.

Example:
    >>> with talkface.VideoWriter("talk.mp4", talkface.VideoOptions(width_px=640, height_px=360)) as video:
    ...     video.add_audio_file("speech.wav")
    ...     for frame in frames:             # numpy (360, 640, 4) uint8
    ...         video.write_frame(frame)
)doc")
        .def(py::init([](const std::string& path, const VideoOptions& options) {
                 return std::make_unique<PyVideoWriter>(PyVideoWriter{VideoWriter(path, options), std::nullopt, false});
             }),
             py::arg("path"), py::arg("options") = VideoOptions{}, R"doc(
Args:
    path (str): the output, .mp4, .webm, .webp, .gif or .png (a numbered sequence).
    options (VideoOptions): size, frame rate, quality, transparency.

Raises:
    talkface.InvalidArgument: an option out of range, an unknown extension, or an encoder missing
        from the system's FFmpeg (named).
    talkface.FileError: no temporary file can be made beside path.

Example:
    >>> video = talkface.VideoWriter("chat.webp", talkface.VideoOptions(width_px=320, height_px=180))
)doc")
        .def_property_readonly("format", [](PyVideoWriter& w) { return w.get().format(); }, "from the extension")
        .def_property_readonly("options", [](PyVideoWriter& w) { return w.get().options(); }, "as given (a copy)")
        .def_property_readonly("frame_count", [](PyVideoWriter& w) { return w.get().frame_count(); },
                               "frames written so far")
        .def(
            "add_audio",
            [](PyVideoWriter& w, const SampleArray& samples, int sample_rate_hz) {
                if (samples.ndim() != 1 && samples.ndim() != 2) {
                    throw InvalidArgument("samples",
                                          "expected shape (frames,) or (frames, channels), got " + shape_text(samples));
                }
                AudioView audio;
                audio.samples = samples.data();
                audio.frame_count = static_cast<std::size_t>(samples.shape(0));
                audio.channel_count = samples.ndim() == 2 ? static_cast<int>(samples.shape(1)) : 1;
                audio.sample_rate_hz = sample_rate_hz;
                w.get().add_audio(audio);
                w.samples = samples;  // read during write_frame() and finish()
            },
            py::arg("samples"), py::arg("sample_rate_hz"), R"doc(
The sound, from frame 0 (mixed down to mono). The array is kept (a float32 copy if it was not one)
until the writer is done. .webp, .gif and .png ignore it. Before the first frame, at most once.

Args:
    samples (numpy.ndarray): shape (frames,) or (frames, channels), values in -1..1.
    sample_rate_hz (int): samples per second.

Raises:
    talkface.InvalidArgument: a malformed array, a second call, or a call after a frame.

Example:
    >>> video.add_audio(numpy.zeros(16000, numpy.float32), 16000)
)doc")
        .def(
            "add_audio_file", [](PyVideoWriter& w, const std::string& audio_path) { w.get().add_audio_file(audio_path); },
            py::arg("audio_path"), R"doc(
The sound from an audio file (WAV, FLAC, OGG ...), as add_audio().

Raises:
    talkface.FileError: the file cannot be read. talkface.ParseError: it is not audio.

Example:
    >>> video.add_audio_file("speech.wav")
)doc")
        .def(
            "write_frame",
            [](PyVideoWriter& w, const PixelArray& frame) {
                VideoWriter& writer = w.get();
                const VideoOptions& options = writer.options();
                if (frame.ndim() != 3 || frame.shape(0) != options.height_px || frame.shape(1) != options.width_px ||
                    frame.shape(2) != 4) {
                    throw InvalidArgument("frame", "expected shape (" + std::to_string(options.height_px) + ", " +
                                                       std::to_string(options.width_px) + ", 4) uint8, got " +
                                                       shape_text(frame));
                }
                const std::uint8_t* pixels = frame.data();
                py::gil_scoped_release release;
                writer.write_frame(pixels, static_cast<std::size_t>(options.width_px) * 4);
            },
            py::arg("frame"), R"doc(
Appends a frame: a C-contiguous uint8 array of shape (height_px, width_px, 4), R, G, B, A (straight
alpha). Frame k is shown at k / fps. Releases the GIL: do not write to the array meanwhile.

Raises:
    talkface.InvalidArgument: the wrong shape. talkface.FileError: the output cannot be written.

Example:
    >>> video.write_frame(numpy.zeros((720, 1280, 4), numpy.uint8))
)doc")
        .def(
            "finish",
            [](PyVideoWriter& w) {
                VideoWriter& writer = w.get();
                {
                    py::gil_scoped_release release;
                    writer.finish();
                }
                w.is_finished = true;
                w.samples.reset();
            },
            R"doc(
Encodes the rest of the sound, closes the file and renames it into place. Call once.

Raises:
    talkface.InvalidArgument: no frame was written, or finish() was called already.
    talkface.FileError: the file cannot be written or renamed.

Example:
    >>> video.finish()
)doc")
        .def("__enter__", [](PyVideoWriter& w) -> PyVideoWriter& { return w; }, py::return_value_policy::reference)
        .def(
            "__exit__",
            [](PyVideoWriter& w, const py::object& exception_type, const py::object&, const py::object&) {
                // Finished only when the block ended normally (unless finish() was called in it);
                // after an exception the writer is dropped and leaves no file.
                if (!exception_type.is_none()) {
                    w.writer.reset();
                    w.samples.reset();
                    return false;
                }
                VideoWriter& writer = w.get();
                if (!w.is_finished) {
                    py::gil_scoped_release release;
                    writer.finish();
                }
                return false;
            },
            py::arg("exception_type"), py::arg("exception"), py::arg("traceback"));

    py::class_<FaceVideoOptions>(m, "FaceVideoOptions", R"doc(
How the face becomes a video: the VideoOptions (size, fps, quality, transparency), where the face
stands (a FrameLayout: announcer, on a stage where the announcer page stands it, the default; face,
its own canvas fitted into the frame), the background colour (None: transparent) and a picture
drawn over it.

Example:
    >>> options = talkface.FaceVideoOptions(video=talkface.VideoOptions(width_px=640, height_px=360),
    ...                                     background="#ffffff")
)doc")
        .def(py::init([](const VideoOptions& video, FrameLayout layout, std::optional<Rgb> background,
                         const std::string& background_image_path, std::optional<Point2> face_origin_px,
                         double face_d_px, FaceLook look, bool draw_clothes, Rgb clothes,
                         double stroke_width_in_d) {
                 FaceVideoOptions options;
                 options.video = video;
                 options.frame.layout = layout;
                 options.frame.background = background;
                 options.frame.face_origin_px = face_origin_px;
                 options.frame.face_d_px = face_d_px;
                 options.frame.look = look;
                 options.frame.draw_clothes = draw_clothes;
                 options.frame.clothes = clothes;
                 options.frame.stroke_width_in_d = stroke_width_in_d;
                 options.background_image_path = background_image_path;
                 return options;
             }),
             py::arg("video") = VideoOptions{}, py::arg("layout") = FrameOptions{}.layout,
             py::arg("background") = FrameOptions{}.background, py::arg("background_image_path") = "",
             py::arg("face_origin_px") = py::none(), py::arg("face_d_px") = 0.0,
             py::arg("look") = FrameOptions{}.look, py::arg("draw_clothes") = FrameOptions{}.draw_clothes,
             py::arg("clothes") = FrameOptions{}.clothes,
             py::arg("stroke_width_in_d") = FrameOptions{}.stroke_width_in_d,
             R"doc(
Args:
    video (VideoOptions): size, frame rate, quality, transparency.
    layout (FrameLayout): announcer (the default) or face.
    background (str | None): "#rrggbb", or None for none (transparent where nothing is drawn).
    background_image_path (str): a picture (PNG, JPEG, WebP, SVG ...) covering the frame; "" for none.
    face_origin_px (tuple[float, float] | None): announcer: where the face's rotation origin (the
        neck) stands, frame pixels; None: where the announcer page stands it.
    face_d_px (float): announcer: the face's eye distance in frame pixels; 0: as the page sizes it.
    look (FaceLook): outlined (the thesis's cartoon, the default) or flat (no outlines).
    draw_clothes (bool): draw the clothes layer (neck and shoulders).
    clothes (str): the clothes' colour, "#rrggbb".
    stroke_width_in_d (float): outline width, in units of d (> 0).

Raises:
    talkface.InvalidArgument: a malformed colour. Options out of range are refused by render_video.

Example:
    >>> talkface.FaceVideoOptions(layout=talkface.FrameLayout.face, background=None)
)doc")
        .def_readwrite("video", &FaceVideoOptions::video, "size, frame rate, quality, transparency")
        .def_readwrite("background_image_path", &FaceVideoOptions::background_image_path,
                       "a picture over the colour")
        .def_property(
            "background", [](const FaceVideoOptions& o) { return o.frame.background; },
            [](FaceVideoOptions& o, std::optional<Rgb> colour) { o.frame.background = colour; },
            "\"#rrggbb\" or None (transparent)")
        .def_property(
            "layout", [](const FaceVideoOptions& o) { return o.frame.layout; },
            [](FaceVideoOptions& o, FrameLayout layout) { o.frame.layout = layout; }, "a FrameLayout")
        .def_property(
            "face_origin_px", [](const FaceVideoOptions& o) { return o.frame.face_origin_px; },
            [](FaceVideoOptions& o, std::optional<Point2> origin) { o.frame.face_origin_px = origin; },
            "(x, y) of the rotation origin in frame pixels, or None")
        .def_property(
            "face_d_px", [](const FaceVideoOptions& o) { return o.frame.face_d_px; },
            [](FaceVideoOptions& o, double d) { o.frame.face_d_px = d; },
            "the eye distance in frame pixels; 0: as the page")
        .def_property(
            "look", [](const FaceVideoOptions& o) { return o.frame.look; },
            [](FaceVideoOptions& o, FaceLook look) { o.frame.look = look; },
            "how the shapes are painted (FaceLook)")
        .def_property(
            "draw_clothes", [](const FaceVideoOptions& o) { return o.frame.draw_clothes; },
            [](FaceVideoOptions& o, bool draw) { o.frame.draw_clothes = draw; },
            "the clothes layer (neck and shoulders)")
        .def_property(
            "clothes", [](const FaceVideoOptions& o) { return o.frame.clothes; },
            [](FaceVideoOptions& o, Rgb colour) { o.frame.clothes = colour; },
            "the clothes' colour, \"#rrggbb\"")
        .def_property(
            "stroke_width_in_d", [](const FaceVideoOptions& o) { return o.frame.stroke_width_in_d; },
            [](FaceVideoOptions& o, double width) { o.frame.stroke_width_in_d = width; },
            "outline width, in units of d");

    m.def(
        "render_video",
        [](const std::string& path, const FaceModel& face, const Animation& animation, const std::string& audio_path,
           const FaceVideoOptions& options, const py::object& progress) {
            const FaceModel face_copy = face;
            const Animation animation_copy = animation;  // the caller's objects may change once the GIL is free
            run_without_gil(progress, [&](const ProgressCallback& callback) {
                render_video(path, face_copy, animation_copy, audio_path, options, callback);
                return 0;
            });
        },
        py::arg("path"), py::arg("face"), py::arg("animation"), py::arg("audio_path") = "",
        py::arg("options") = FaceVideoOptions{}, py::arg("progress") = py::none(), R"doc(
Writes a video of `face` playing `animation` with the speech at audio_path ("" for none): frame k
shows the animation at k / fps, as many frames as cover the speech. Releases the GIL while it works;
`progress(fraction, stage)` is called with it, and returning False cancels (talkface.Cancelled).
Written through a temporary file: a failure or a cancel leaves none.

Args:
    path (str): .mp4, .webm, .webp, .gif or .png (a numbered sequence).
    face (FaceModel): the neutral face the animation was made from.
    animation (Animation): from talkface.animate().
    audio_path (str): the speech, WAV, FLAC or OGG.
    options (FaceVideoOptions): size, fps, layout, background.
    progress (callable | None): progress(fraction, stage) -> bool | None.

Raises:
    talkface.InvalidArgument: an option out of range (named) or an encoder missing from FFmpeg.
    talkface.FileError: the audio, the picture or the output cannot be read or written.
    talkface.Cancelled: progress returned False.

Example:
    >>> talkface.render_video("talk.mp4", face, animation, "speech.wav")
)doc");
}

}  // namespace talkface::python

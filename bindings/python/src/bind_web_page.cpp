// WebPageApp, WebPageAudio, WebLink, WebPageOptions, build_web_page and write_web_page in Python;
// building a page runs without the GIL.
#include "bind.hpp"

namespace talkface::python {

void bind_web_page(py::module_& m) {
    py::enum_<WebPageApp>(m, "WebPageApp", R"doc(
What a page is for: plain (the face and the audio controls), announcer (thesis 7.2: the face on a
stage over a colour or an image) or audiobook (7.3: title, text with the spoken sentence highlighted,
links, the face beside them).
)doc")
        .value("plain", WebPageApp::plain)
        .value("announcer", WebPageApp::announcer)
        .value("audiobook", WebPageApp::audiobook);

    py::enum_<WebPageAudio>(m, "WebPageAudio", R"doc(
How a page carries its audio: compressed (encoded anew as Opus in WebM, mono, for speech, and
embedded: plays in Chromium, Firefox and Safari 17.4+), original (the audio file's own bytes
embedded) or link (the page links audio_url; keep the file beside the page).
)doc")
        .value("compressed", WebPageAudio::compressed)
        .value("original", WebPageAudio::original)
        .value("link", WebPageAudio::link);

    py::class_<WebLink>(m, "WebLink", R"doc(
A link of the audio book's page: the text shown and an http:, https:, mailto: or relative URL.

Example:
    >>> talkface.WebLink("thesis", "https://example.org/thesis.pdf")
)doc")
        .def(py::init([](std::string text, std::string url) { return WebLink{std::move(text), std::move(url)}; }),
             py::arg("text"), py::arg("url"))
        .def_readwrite("text", &WebLink::text)
        .def_readwrite("url", &WebLink::url)
        .def("__repr__", [](const WebLink& link) {
            return "talkface.WebLink(" + py::repr(py::str(link.text)).cast<std::string>() + ", " +
                   py::repr(py::str(link.url)).cast<std::string>() + ")";
        });

    py::class_<WebPageOptions>(m, "WebPageOptions", R"doc(
How a page is built. Sizes are CSS pixels; colours "#rrggbb". Checked when the page is built.

Args:
    app (WebPageApp): plain, announcer or audiobook.
    title (str): the page's title; "" takes the first sentence (its first 30 characters and an ellipsis when longer).
    links (list[WebLink]): audio book links.
    animation (SvgAnimationOptions): the face's encoding.
    audio (WebPageAudio): compressed (the default), original or link.
    audio_bitrate_bps (int): compressed: the Opus bit rate, 6000 to 128000; 0 takes 11000.
    audio_url (str): link: the link, relative to the page ("" takes the audio file's name).
    stage_width_px, stage_height_px (int), stage_colour (str), background_image_path (str): the
        announcer's stage.
    face_origin_px ((x, y) | None), face_d_px (float): where the announcer's neck stands and its eye
        distance; None and 0 fit the face to the stage.

Example:
    >>> options = talkface.WebPageOptions(app=talkface.WebPageApp.audiobook, title="春曉")
)doc")
        .def(py::init([](WebPageApp app, std::string title, std::vector<WebLink> links, SvgAnimationOptions animation,
                         WebPageAudio audio, int audio_bitrate_bps, std::string audio_url, int stage_width_px, int stage_height_px,
                         Rgb stage_colour, std::string background_image_path, std::optional<Point2> face_origin_px,
                         double face_d_px) {
                 WebPageOptions options;
                 options.app = app;
                 options.title = std::move(title);
                 options.links = std::move(links);
                 options.animation = animation;
                 options.audio = audio;
                 options.audio_bitrate_bps = audio_bitrate_bps;
                 options.audio_url = std::move(audio_url);
                 options.stage_width_px = stage_width_px;
                 options.stage_height_px = stage_height_px;
                 options.stage_colour = stage_colour;
                 options.background_image_path = std::move(background_image_path);
                 options.face_origin_px = face_origin_px;
                 options.face_d_px = face_d_px;
                 return options;
             }),
             py::arg("app") = WebPageApp::plain, py::arg("title") = "", py::arg("links") = std::vector<WebLink>{},
             py::arg("animation") = SvgAnimationOptions{}, py::arg("audio") = WebPageAudio::compressed,
             py::arg("audio_bitrate_bps") = 0, py::arg("audio_url") = "", py::arg("stage_width_px") = WebPageOptions{}.stage_width_px,
             py::arg("stage_height_px") = WebPageOptions{}.stage_height_px,
             py::arg("stage_colour") = WebPageOptions{}.stage_colour, py::arg("background_image_path") = "",
             py::arg("face_origin_px") = py::none(), py::arg("face_d_px") = 0.0)
        .def_readwrite("app", &WebPageOptions::app)
        .def_readwrite("title", &WebPageOptions::title)
        .def_readwrite("links", &WebPageOptions::links)
        .def_readwrite("animation", &WebPageOptions::animation)
        .def_readwrite("audio", &WebPageOptions::audio)
        .def_readwrite("audio_bitrate_bps", &WebPageOptions::audio_bitrate_bps)
        .def_readwrite("audio_url", &WebPageOptions::audio_url)
        .def_readwrite("stage_width_px", &WebPageOptions::stage_width_px)
        .def_readwrite("stage_height_px", &WebPageOptions::stage_height_px)
        .def_readwrite("stage_colour", &WebPageOptions::stage_colour)
        .def_readwrite("background_image_path", &WebPageOptions::background_image_path)
        .def_readwrite("face_origin_px", &WebPageOptions::face_origin_px)
        .def_readwrite("face_d_px", &WebPageOptions::face_d_px);

    m.def(
        "build_web_page",
        [](const SvgAnimator& animator, const Animation& animation, const Timeline& timeline,
           const std::filesystem::path& audio_path, const WebPageOptions& options) {
            const Animation animation_copy = animation;
            const Timeline timeline_copy = timeline;
            const WebPageOptions options_copy = options;
            const std::string audio = audio_path.string();
            py::gil_scoped_release release;
            return build_web_page(animator, animation_copy, timeline_copy, audio, options_copy);
        },
        py::arg("animator"), py::arg("animation"), py::arg("timeline"), py::arg("audio_path"),
        py::arg("options") = WebPageOptions{}, R"doc(
The web page (str): one self-contained HTML file with the animation inline, the audio embedded (or
linked) and a script that makes the audio's clock drive the face. Every caller text is escaped.
Releases the GIL while it works.

Args:
    animator (SvgAnimator): the face and how it is drawn.
    animation (Animation): from talkface.animate() on the same face and timeline.
    timeline (Timeline): the aligned timeline (its sentences are the audio book's text).
    audio_path (str | os.PathLike): the speech (.ogg .wav .flac .mp3 ...).
    options (WebPageOptions): the app and its settings.

Raises:
    talkface.FileError: the audio or background image cannot be read.
    talkface.InvalidArgument: an option out of range, a link with a refused scheme (javascript:).

Example:
    >>> html = talkface.build_web_page(talkface.SvgAnimator(face), animation, timeline, "speech.ogg")
    >>> html.startswith("<!DOCTYPE html>")
)doc");

    m.def(
        "write_web_page",
        [](const std::filesystem::path& path, const SvgAnimator& animator, const Animation& animation,
           const Timeline& timeline, const std::filesystem::path& audio_path, const WebPageOptions& options) {
            const Animation animation_copy = animation;
            const Timeline timeline_copy = timeline;
            const WebPageOptions options_copy = options;
            const std::string page = path.string();
            const std::string audio = audio_path.string();
            py::gil_scoped_release release;
            write_web_page(page, animator, animation_copy, timeline_copy, audio, options_copy);
        },
        py::arg("path"), py::arg("animator"), py::arg("animation"), py::arg("timeline"), py::arg("audio_path"),
        py::arg("options") = WebPageOptions{}, R"doc(
Writes build_web_page() to path through a temporary file and a rename: a failure never leaves half a
page, and a page already at path stays until the new one is whole. Releases the GIL.

Raises:
    talkface.FileError: the page cannot be written, or as build_web_page().

Example:
    >>> talkface.write_web_page("talk.html", talkface.SvgAnimator(face), animation, timeline, "speech.ogg")
)doc");
}

}  // namespace talkface::python

// The animation editor in Python: animate() and Animation with its key-frame exports; animation runs
// without the GIL.
#include "bind.hpp"

namespace talkface::python {

void bind_animation(py::module_& m) {
    py::class_<Animation>(m, "Animation", R"doc(
A finished animation: fps, duration_s, the mouth key frames, the expression events it was made with,
and frames: one FaceState per frame (frame i shows time i / fps). project_face(face, frame) gives a
frame's points; SvgAnimator(face).render_svg(frame) its picture. The list attributes are copies.

Example:
    >>> animation = talkface.animate(face, timeline, simulator)
    >>> talkface.project_face(face, animation.frames[10]).image_xy
)doc")
        .def_readonly("fps", &Animation::fps, "frames per second")
        .def_readonly("duration_s", &Animation::duration_s, "the later of the timeline's and the simulator's end")
        .def_readonly("mouth_key_frames", &Animation::mouth_key_frames, "list[MouthKeyFrame] (a copy)")
        .def_readonly("events", &Animation::events, "list[ExpressionEvent] (a copy)")
        .def_readonly("frames", &Animation::frames, "list[FaceState], one per frame (a copy)")
        .def("__len__", [](const Animation& a) { return a.frames.size(); })
        .def(
            "key_frames_json",
            [](const Animation& a) {
                const Animation copy = a;
                py::gil_scoped_release release;
                return key_frames_json(copy.mouth_key_frames, copy.events, copy.fps, copy.duration_s);
            },
            R"doc(
The key frames as JSON, one item per line, times with at most 3 decimals:
{"fps":25,"duration":s, "mouth":[{"time":s,"shape":"a","syllable":k}], "events":[{"kind":"blink",
"start":s,"end":s,"amount":x}]}: the animation's frame rate and length (seconds) first; "syllable"
is null for a rest. The same animation always gives the same text.

Example:
    >>> document = json.loads(animation.key_frames_json())
    >>> document["mouth"][0]
)doc")
        .def(
            "key_frames_tsv",
            [](const Animation& a) {
                const std::vector<MouthKeyFrame> key_frames = a.mouth_key_frames;
                py::gil_scoped_release release;
                return key_frames_tsv(key_frames);
            },
            R"doc(
The mouth key frames as "time<TAB>shape" lines, no header.

Example:
    >>> animation.key_frames_tsv().splitlines()[0]
    '0\tm'
)doc")
        .def("__repr__", [](const Animation& a) {
            return py::str("<talkface.Animation: {} frames at {!r} fps, {} mouth key frames, {} events>")
                .format(a.frames.size(), a.fps, a.mouth_key_frames.size(), a.events.size());
        });

    m.def(
        "animate",
        [](const FaceModel& neutral, const Timeline& timeline, const ExpressionSimulator& expressions,
           const LipSyncOptions& options) {
            // Copies: another Python thread may change the caller's objects once the GIL is free
            // (the simulator cannot be copied; its thread rule is in its docstring).
            const FaceModel neutral_copy = neutral;
            const Timeline timeline_copy = timeline;
            const LipSyncOptions options_copy = options;
            py::gil_scoped_release release;
            return animate(neutral_copy, timeline_copy, expressions, options_copy);
        },
        py::arg("neutral"), py::arg("timeline"), py::arg("expressions"), py::arg("options") = LipSyncOptions{},
        R"doc(
Builds every frame (thesis 5.4): lips from the timeline's syllables (mouth_key_frames, mouth_frames),
pose, blinks and brows from the simulator's events in effect. Releases the GIL while it works.

Args:
    neutral (FaceModel): the neutral face.
    timeline (Timeline): aligned sentences and syllables.
    expressions (ExpressionSimulator): the events (simulated and the caller's).
    options (LipSyncOptions): fps, rests, interpolation, speed limit.

Raises:
    talkface.InvalidArgument: a syllable whose pinyin is not Mandarin or whose times are wrong (named
        by index, pinyin and times), or an option out of range.

Example:
    >>> animation = talkface.animate(face, timeline, talkface.ExpressionSimulator(timeline, 7))
    >>> len(animation.frames), animation.key_frames_tsv()
)doc");
    m.def("key_frames_json", &key_frames_json, py::arg("mouth_key_frames"), py::arg("events"), py::arg("fps"),
          py::arg("duration_s"), py::call_guard<py::gil_scoped_release>(), R"doc(
Key frames and events as the keyframes JSON document (see Animation.key_frames_json), with the
frame rate they sit on and the animation's length in seconds.

Raises:
    talkface.InvalidArgument: fps not > 0, or duration_s negative or not finite.

Example:
    >>> talkface.key_frames_json(talkface.mouth_key_frames(timeline), simulator.events(), 25.0, 3.2)
    >>> talkface.key_frames_json([], [], 25.0, 0.0)
)doc");
    m.def("key_frames_tsv", &key_frames_tsv, py::arg("mouth_key_frames"), py::call_guard<py::gil_scoped_release>(),
          R"doc(
Mouth key frames as "time<TAB>shape" lines (see Animation.key_frames_tsv).

Example:
    >>> talkface.key_frames_tsv(talkface.mouth_key_frames(timeline))
    >>> talkface.key_frames_tsv([])
)doc");
}

}  // namespace talkface::python

// Lip movement in Python: a syllable's mouth shapes, the onset table, mouth key frames and the mouth
// of every frame.
#include <array>

#include "bind.hpp"

namespace talkface::python {

void bind_lip_sync(py::module_& m) {
    m.def("syllable_mouth_shapes", &syllable_mouth_shapes, py::arg("pinyin"), R"doc(
The mouth shapes of one Mandarin syllable, 1 to 4, in the order shown (thesis 5.2.2):
"bo" -> [m, u, o], "hao" -> [h, a, u]. Numbered or toneless pinyin; u-umlaut as v, "u:" or "ü".

Raises:
    talkface.InvalidArgument: not a Mandarin syllable (the message names it).

Example:
    >>> [talkface.mouth_shape_name(s) for s in talkface.syllable_mouth_shapes("bo1")]
    ['m', 'u', 'o']
)doc");
    m.def("mandarin_syllables", &mandarin_syllables, R"doc(
Every toneless syllable syllable_mouth_shapes() accepts, sorted by byte value (a new list).

Example:
    >>> "zhuang" in talkface.mandarin_syllables()
    True
)doc");

    py::class_<MouthKeyFrame>(m, "MouthKeyFrame", R"doc(
One mouth key frame: the mouth reaches shape at time_s; syllable is the index of the syllable the
shape belongs to, or None for the rest (m) of a pause.

Example:
    >>> key = animation.mouth_key_frames[1]
    >>> key.time_s, talkface.mouth_shape_name(key.shape), key.syllable
)doc")
        .def(py::init([](double time_s, MouthShape shape, std::optional<std::size_t> syllable) {
                 return MouthKeyFrame{time_s, shape, syllable};
             }),
             py::arg("time_s") = 0.0, py::arg("shape") = MouthShape::m, py::arg("syllable") = py::none(), R"doc(
Args:
    time_s (float): seconds.
    shape (MouthShape): the shape reached.
    syllable (int | None): index into Timeline.syllables, None for a rest.

Example:
    >>> talkface.MouthKeyFrame(0.5, talkface.MouthShape.a, 0)
    >>> talkface.MouthKeyFrame(0.0)
)doc")
        .def_readwrite("time_s", &MouthKeyFrame::time_s, "seconds")
        .def_readwrite("shape", &MouthKeyFrame::shape, "MouthShape")
        .def_readwrite("syllable", &MouthKeyFrame::syllable, "syllable index, or None for a rest")
        .def("__eq__", [](const MouthKeyFrame& a, const MouthKeyFrame& b) { return a == b; })
        .def("__repr__", [](const MouthKeyFrame& k) {
            return py::str("talkface.MouthKeyFrame({!r}, talkface.MouthShape.{}, {!r})")
                .format(k.time_s, py::cast(k.shape).attr("name"), k.syllable);
        });

    py::enum_<MouthInterpolation>(m, "MouthInterpolation", R"doc(
How the mouth moves between two key frames: linear (the thesis, 5.4) or smooth (cosine ease).

Example:
    >>> talkface.LipSyncOptions(interpolation=talkface.MouthInterpolation.smooth)
    >>> talkface.MouthInterpolation.linear
)doc")
        .value("linear", MouthInterpolation::linear)
        .value("smooth", MouthInterpolation::smooth);

    py::class_<ShapeOnsetTable>(m, "ShapeOnsetTable", R"doc(
When the later shapes of a syllable start, as fractions of its duration (thesis 5.3): two_shapes
holds 1 value, three_shapes 2, four_shapes 3; each row must rise strictly inside (0, 1), which
mouth_key_frames() and animate() check and name ("ShapeOnsetTable::three_shapes").

Example:
    >>> table = talkface.ShapeOnsetTable(two_shapes=[0.3])
    >>> talkface.LipSyncOptions(onsets=table)
)doc")
        .def(py::init([](std::array<double, 1> two_shapes, std::array<double, 2> three_shapes,
                         std::array<double, 3> four_shapes) {
                 return ShapeOnsetTable{two_shapes, three_shapes, four_shapes};
             }),
             py::arg("two_shapes") = ShapeOnsetTable{}.two_shapes,
             py::arg("three_shapes") = ShapeOnsetTable{}.three_shapes,
             py::arg("four_shapes") = ShapeOnsetTable{}.four_shapes, R"doc(
Args:
    two_shapes (list[float]): 1 onset; the thesis's 0.1905.
    three_shapes (list[float]): 2 onsets; 0.1688, 0.6025.
    four_shapes (list[float]): 3 onsets; 0.2847, 0.5297, 0.7412.

Raises:
    TypeError: a row of the wrong length.

Example:
    >>> talkface.ShapeOnsetTable()
    >>> talkface.ShapeOnsetTable(three_shapes=[0.2, 0.6])
)doc")
        .def_readwrite("two_shapes", &ShapeOnsetTable::two_shapes, "1 fraction of the syllable")
        .def_readwrite("three_shapes", &ShapeOnsetTable::three_shapes, "2 fractions of the syllable, rising")
        .def_readwrite("four_shapes", &ShapeOnsetTable::four_shapes, "3 fractions of the syllable, rising")
        .def("__eq__",
             [](const ShapeOnsetTable& a, const ShapeOnsetTable& b) {
                 return a.two_shapes == b.two_shapes && a.three_shapes == b.three_shapes &&
                        a.four_shapes == b.four_shapes;
             })
        .def("__repr__", [](const ShapeOnsetTable& t) {
            return py::str("talkface.ShapeOnsetTable(two_shapes={!r}, three_shapes={!r}, four_shapes={!r})")
                .format(t.two_shapes, t.three_shapes, t.four_shapes);
        });

    py::class_<LipSyncOptions>(m, "LipSyncOptions", R"doc(
Options of the lip movement; checked when used (mouth_key_frames, animate), which names the one out of
range. The onset table inside a syllable is the thesis's (5.3) unless onsets is set.

Example:
    >>> options = talkface.LipSyncOptions(fps=30.0)
    >>> talkface.animate(face, timeline, simulator, options)
)doc")
        .def(py::init([](double fps, double rest_min_pause_s, double rest_transition_s,
                         MouthInterpolation interpolation, double max_speed_mns0_per_s, const ShapeOnsetTable& onsets) {
                 LipSyncOptions options;
                 options.onsets = onsets;
                 options.fps = fps;
                 options.rest_min_pause_s = rest_min_pause_s;
                 options.rest_transition_s = rest_transition_s;
                 options.interpolation = interpolation;
                 options.max_speed_mns0_per_s = max_speed_mns0_per_s;
                 return options;
             }),
             py::arg("fps") = LipSyncOptions{}.fps, py::arg("rest_min_pause_s") = LipSyncOptions{}.rest_min_pause_s,
             py::arg("rest_transition_s") = LipSyncOptions{}.rest_transition_s,
             py::arg("interpolation") = LipSyncOptions{}.interpolation,
             py::arg("max_speed_mns0_per_s") = LipSyncOptions{}.max_speed_mns0_per_s,
             py::arg("onsets") = ShapeOnsetTable{}, R"doc(
Args:
    fps (float): frames per second; key frames sit on frames.
    rest_min_pause_s (float): a gap between syllables at least this long is a pause (mouth at rest).
    rest_transition_s (float): time to reach and to leave the rest, seconds.
    interpolation (MouthInterpolation): linear or smooth.
    max_speed_mns0_per_s (float): speed limit of the mouth control points, MNS0 per second.
    onsets (ShapeOnsetTable): when the later shapes of a syllable start (thesis 5.3).

Example:
    >>> talkface.LipSyncOptions()
    >>> talkface.LipSyncOptions(fps=50.0, interpolation=talkface.MouthInterpolation.smooth)
)doc")
        .def_readwrite("fps", &LipSyncOptions::fps, "frames per second")
        .def_readwrite("rest_min_pause_s", &LipSyncOptions::rest_min_pause_s, "seconds")
        .def_readwrite("rest_transition_s", &LipSyncOptions::rest_transition_s, "seconds")
        .def_readwrite("interpolation", &LipSyncOptions::interpolation, "MouthInterpolation")
        .def_readwrite("max_speed_mns0_per_s", &LipSyncOptions::max_speed_mns0_per_s, "MNS0 per second")
        .def_readwrite("onsets", &LipSyncOptions::onsets,
                       "ShapeOnsetTable (a copy: assign a changed table back to change the options)")
        .def("__repr__", [](const LipSyncOptions& o) {
            return py::str("talkface.LipSyncOptions(fps={!r}, rest_min_pause_s={!r}, rest_transition_s={!r}, "
                           "interpolation={!r}, max_speed_mns0_per_s={!r})")
                .format(o.fps, o.rest_min_pause_s, o.rest_transition_s, o.interpolation, o.max_speed_mns0_per_s);
        });

    m.def(
        "mouth_key_frames",
        [](const Timeline& timeline, const LipSyncOptions& options) {
            const Timeline timeline_copy = timeline;
            const LipSyncOptions options_copy = options;
            py::gil_scoped_release release;
            return mouth_key_frames(timeline_copy, options_copy);
        },
        py::arg("timeline"), py::arg("options") = LipSyncOptions{}, R"doc(
The mouth key frames of a timeline, in rising time, each on a frame: the rest (m) at 0 and in pauses,
then each syllable's shapes at their onsets (thesis 5.3).

Raises:
    talkface.InvalidArgument: a syllable whose pinyin is not Mandarin or whose times are wrong (named
        by index, pinyin and times), or an option out of range.

Example:
    >>> keys = talkface.mouth_key_frames(timeline)
    >>> [(k.time_s, talkface.mouth_shape_name(k.shape)) for k in keys]
)doc");
    m.def(
        "mouth_frames",
        [](const FaceModel& neutral, const std::vector<MouthKeyFrame>& key_frames, std::size_t frame_count,
           const LipSyncOptions& options) {
            const FaceModel neutral_copy = neutral;
            const LipSyncOptions options_copy = options;
            py::gil_scoped_release release;
            return mouth_frames(neutral_copy, key_frames, frame_count, options_copy);
        },
        py::arg("neutral"), py::arg("key_frames"), py::arg("frame_count"), py::arg("options") = LipSyncOptions{},
        R"doc(
The mouth control points of frames 0 .. frame_count - 1 (frame i shows time i / fps): key frames
interpolated, then speed-limited; closures (m, f) are held on their frames. Releases the GIL.

Raises:
    talkface.InvalidArgument: an option out of range, or key frames not in rising time.

Example:
    >>> mouths = talkface.mouth_frames(face, talkface.mouth_key_frames(timeline), 50)
    >>> mouths[10].down
)doc");
}

}  // namespace talkface::python

// The timeline JSON in Python: timeline_to_json(), timeline_from_json(), load_timeline_json(),
// save_timeline_json() (include/talkface/timeline_json.hpp), the same bytes as the command and C.
#include "bind.hpp"

namespace talkface::python {

void bind_timeline_json(py::module_& m) {
    m.attr("TIMELINE_JSON_VERSION") = kTimelineJsonVersion;
    m.def(
        "timeline_to_json",
        [](const Timeline& timeline, bool with_times) {
            TimelineJsonOptions options;
            options.with_times = with_times;
            const Timeline timeline_copy = timeline;
            py::gil_scoped_release release;
            return timeline_to_json(timeline_copy, options);
        },
        py::arg("timeline"), py::arg("with_times") = true, R"doc(
The timeline as the timeline JSON (docs/timeline-format.md): {"version": 1, "sentences": [...],
"syllables": [...], "duration": s, "warnings": [...]}, one item per line, characters as UTF-8,
times in shortest round-trip form, so timeline_from_json() reads back an equal timeline. The same
bytes as `talkface align --json` and tf_timeline_to_json.

Args:
    timeline (Timeline): what to write.
    with_times (bool): False leaves out every time and aligner figure, as `talkface syllables
        --json` does.

Example:
    >>> text = talkface.timeline_to_json(timeline)
    >>> talkface.timeline_from_json(text).syllables == timeline.syllables
)doc");
    m.def(
        "timeline_from_json",
        [](std::string_view text, const std::string& source_name) {
            py::gil_scoped_release release;
            return timeline_from_json(text, source_name);
        },
        py::arg("text"), py::arg("source_name") = "<timeline>", R"doc(
Reads the timeline JSON. Keys left out take their defaults (times 0, confidence 1), so the output
of `talkface syllables --json` reads too; keys this version does not know are skipped.

Args:
    text (str): the document.
    source_name (str): names the document in messages (a path, say).

Raises:
    talkface.ParseError: not JSON, a missing or mistyped key, a negative time, an end before its
        start, or a "version" newer than TIMELINE_JSON_VERSION; the message names
        source:line:column and the item ('syllables[3].start'), also in .line and .item.

Example:
    >>> timeline = talkface.timeline_from_json(open("aligned.json").read(), "aligned.json")
)doc");
    m.def(
        "load_timeline_json",
        [](const std::filesystem::path& path) {
            const std::string json_path = path.string();
            py::gil_scoped_release release;
            return load_timeline_json(json_path);
        },
        py::arg("path"),
        R"doc(
Reads a timeline JSON file as timeline_from_json() does; messages name the path.

Raises:
    talkface.FileError: the file cannot be read (also an OSError).
    talkface.ParseError: as timeline_from_json().

Example:
    >>> timeline = talkface.load_timeline_json("aligned.json")
)doc");
    m.def(
        "save_timeline_json",
        [](const std::filesystem::path& path, const Timeline& timeline, bool with_times) {
            TimelineJsonOptions options;
            options.with_times = with_times;
            const std::string json_path = path.string();
            const Timeline timeline_copy = timeline;
            py::gil_scoped_release release;
            save_timeline_json(json_path, timeline_copy, options);
        },
        py::arg("path"), py::arg("timeline"), py::arg("with_times") = true, R"doc(
Writes timeline_to_json() to a file, whole or not at all (a temporary file renamed over it).

Raises:
    talkface.FileError: it cannot be written; the file is then left as it was.

Example:
    >>> talkface.save_timeline_json("aligned.json", timeline)
)doc");
}

}  // namespace talkface::python

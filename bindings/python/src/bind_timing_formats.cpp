// Timing exports and imports in Python (include/talkface/timing_formats.hpp): export_to_string(),
// export_to_file(), read_timing_string(), read_timing_file(), write_timing_string(),
// time_transcript(), and the format lists. The same bytes as the command and C.
#include "bind.hpp"

namespace talkface::python {

namespace {

ExportInput export_input(const Timeline& timeline, const Animation& animation, const std::string& audio_path) {
    ExportInput input;
    input.timeline = timeline;
    input.mouth_key_frames = animation.mouth_key_frames;
    input.fps = animation.fps;
    input.frames = animation.frames;
    input.audio_path = audio_path;
    return input;
}

}  // namespace

void bind_timing_formats(py::module_& m) {
    m.def("export_format_names", &export_format_names, R"doc(
The export formats: ["rhubarb-tsv", "rhubarb-json", "rhubarb-xml", "moho", "live2d", "textgrid",
"srt", "vtt"] (docs/timing-formats.md).
)doc");
    m.def("export_format_for_path", &export_format_for_path, py::arg("path"), R"doc(
The export format a file name asks for (.tsv .xml .dat .motion3.json .TextGrid .srt .vtt).

Raises:
    talkface.InvalidArgument: another suffix (named, with the formats), or a plain .json.
)doc");
    m.def(
        "export_to_string",
        [](const Timeline& timeline, const Animation& animation, const std::string& format,
           const std::string& audio_path) {
            const ExportInput input = export_input(timeline, animation, audio_path);
            py::gil_scoped_release release;
            return export_to_string(input, format);
        },
        py::arg("timeline"), py::arg("animation"), py::arg("format"), py::arg("audio_path") = "", R"doc(
The speech's timing in a tool's format, spanning 0 to timeline.duration_s: Rhubarb Lip Sync cues
(rhubarb-tsv, rhubarb-json, rhubarb-xml), Moho switch data (moho), a Live2D motion3.json (live2d),
a Praat TextGrid (textgrid), subtitles (srt, vtt).

Args:
    timeline (Timeline): aligned; duration_s is the audio's length.
    animation (Animation): talkface.animate(face, timeline, simulator): its key frames and frames.
    format (str): one of export_format_names().
    audio_path (str): the recording, written into Rhubarb's metadata.soundFile.

Raises:
    talkface.InvalidArgument: an unknown format (named, with the formats), or duration_s <= 0.

Example:
    >>> tsv = talkface.export_to_string(timeline, animation, "rhubarb-tsv")
    >>> tsv.splitlines()[0]
    '0.00\tX'
)doc");
    m.def(
        "export_to_file",
        [](const std::filesystem::path& path, const Timeline& timeline, const Animation& animation,
           const std::string& format, const std::string& audio_path) {
            const ExportInput input = export_input(timeline, animation, audio_path);
            py::gil_scoped_release release;
            export_to_file(path.string(), input, format);
        },
        py::arg("path"), py::arg("timeline"), py::arg("animation"), py::arg("format") = "",
        py::arg("audio_path") = "", R"doc(
export_to_string() written to a file, whole or not at all; format "" takes it from the suffix.

Raises:
    talkface.InvalidArgument: as export_to_string(), or a suffix that names no format.
    talkface.FileError: it cannot be written; the file is then left as it was.

Example:
    >>> talkface.export_to_file("speech.TextGrid", timeline, animation)
)doc");
    m.def("timing_format_names", &timing_format_names, R"doc(
The timing import formats: ["textgrid", "srt", "vtt", "words-json", "timeline-json"].
)doc");
    m.def(
        "read_timing_string",
        [](std::string_view text, const std::string& format, const Timeline& transcript, double duration_s,
           const std::string& source_name) {
            const Timeline transcript_copy = transcript;
            py::gil_scoped_release release;
            return read_timing_string(text, format, transcript_copy, duration_s, source_name);
        },
        py::arg("text"), py::arg("format"), py::arg("transcript"), py::arg("duration_s") = 0.0,
        py::arg("source_name") = "<timing>", R"doc(
The transcript timed by a timing document instead of the aligner: a TextGrid's syllables or words
tier, SRT or WebVTT cues (sentence times; WebVTT's cue timestamps give syllable starts), a JSON
list of {"text", "start", "end"} (words-json), or the timeline JSON.

Args:
    text (str): the document.
    format (str): one of timing_format_names(), or "json" (either JSON).
    transcript (Timeline): from read_transcript() / load_transcript().
    duration_s (float): the audio's length; times past it are refused (0: not checked).
    source_name (str): names the document in messages.

Raises:
    talkface.ParseError: a malformed document, times out of order or past duration_s, or a text
        that parts from the transcript (the message names source:line and the first place
        they part).

Example:
    >>> timeline = talkface.read_timing_string(open("mfa.TextGrid").read(), "textgrid", transcript, 4.2)
)doc");
    m.def(
        "read_timing_file",
        [](const std::filesystem::path& path, const Timeline& transcript, double duration_s,
           const std::string& format) {
            const Timeline transcript_copy = transcript;
            py::gil_scoped_release release;
            return read_timing_file(path.string(), transcript_copy, duration_s, format);
        },
        py::arg("path"), py::arg("transcript"), py::arg("duration_s") = 0.0, py::arg("format") = "", R"doc(
read_timing_string() of a file; format "" takes it from the suffix (.TextGrid .srt .vtt .json).

Raises:
    talkface.FileError: it cannot be read. talkface.ParseError: as read_timing_string().

Example:
    >>> timeline = talkface.read_timing_file("words.json", transcript, 4.2)
)doc");
    m.def(
        "write_timing_string",
        [](const Timeline& timeline, const std::string& format) {
            const Timeline timeline_copy = timeline;
            py::gil_scoped_release release;
            return write_timing_string(timeline_copy, format);
        },
        py::arg("timeline"), py::arg("format"), R"doc(
The timeline in an import format, so that read_timing_string() gives its times back (syllable by
syllable for textgrid and words-json, sentence by sentence for srt and vtt).

Example:
    >>> back = talkface.read_timing_string(talkface.write_timing_string(timeline, "textgrid"),
    ...                                    "textgrid", transcript)
)doc");
    m.def(
        "time_transcript",
        [](const std::filesystem::path& timing_path, const std::filesystem::path& audio_path,
           const Timeline& transcript, const std::string& format, const std::optional<AlignOptions>& options) {
            const Timeline transcript_copy = transcript;
            const AlignOptions options_copy = options.value_or(AlignOptions{});
            py::gil_scoped_release release;
            return time_transcript(timing_path.string(), audio_path.string(), transcript_copy, options_copy, format);
        },
        py::arg("timing_path"), py::arg("audio_path"), py::arg("transcript"), py::arg("format") = "",
        py::arg("options") = py::none(), R"doc(
The transcript spoken in a recording, timed by a timing file instead of aligning the whole
recording (what `--timing FILE` does): word and syllable timings as read_timing_file() reads them;
subtitle cues that give sentence times only pin the aligner: each sentence is searched only inside
its cues (the models are learned, and a wrong text refused, over the whole recording); cues that
time every syllable (WebVTT cue timestamps, as the vtt export writes) are read as they are.
`options` (AlignOptions, None: the defaults) are the pinned aligner's: check decides what a wrong
text does; lenient reports a stretch inside the cues that does not say its text
(Timeline.mismatches) rather than refusing. Releases the GIL.

Raises:
    talkface.ParseError, talkface.FileError: as read_timing_file() and SpeechAligner.align_file().
    talkface.AlignmentError: as SpeechAligner.align_file().
    ValueError: naming lenient if options.lenient and the file times every syllable itself
        (textgrid, words-json, timeline-json, cues with a timestamp per syllable): nothing is aligned.

Example:
    >>> timeline = talkface.time_transcript("speech.srt", "speech.wav", transcript)
)doc");
    m.def(
        "audio_duration_s",
        [](const std::filesystem::path& path) {
            const std::string audio_path = path.string();
            py::gil_scoped_release release;
            return audio_duration_s(audio_path);
        },
        py::arg("audio_path"), R"doc(
The length of a recording in seconds, from its header.

Example:
    >>> talkface.audio_duration_s("speech.wav")
)doc");
}

}  // namespace talkface::python

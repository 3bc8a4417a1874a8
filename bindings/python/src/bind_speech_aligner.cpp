// The speech aligner in Python: SentenceCutMode, AlignOptions, SpeechAligner (align_file, align),
// and the picture of an alignment.
#include <optional>
#include <utility>

#include "bind.hpp"

namespace talkface::python {

namespace {

using SampleArray = py::array_t<float, py::array::c_style | py::array::forcecast>;

// The view of a (frames,) or (frames, channels) array; its shape is checked here, the rest by the
// aligner.
AudioView audio_view(const SampleArray& samples, int sample_rate_hz) {
    if (samples.ndim() != 1 && samples.ndim() != 2) {
        throw InvalidArgument("samples", "expected shape (frames,) or (frames, channels), got " + shape_text(samples));
    }
    if (samples.size() == 0) throw InvalidArgument("samples", "empty audio: shape " + shape_text(samples));
    if (samples.ndim() == 2 && samples.shape(1) > samples.shape(0)) {
        throw InvalidArgument("samples", "expected shape (frames, channels), got " + shape_text(samples) +
                                             ": more channels than frames; pass samples.T for a (channels, frames) "
                                             "array");
    }
    AudioView audio;
    audio.samples = samples.data();
    audio.frame_count = static_cast<std::size_t>(samples.shape(0));
    audio.channel_count = samples.ndim() == 2 ? static_cast<int>(samples.shape(1)) : 1;
    audio.sample_rate_hz = sample_rate_hz;
    return audio;
}

}  // namespace

void bind_speech_aligner(py::module_& m) {
    py::enum_<SentenceCutMode>(m, "SentenceCutMode", R"doc(
How the audio is cut into sentence utterances: automatic (noise level and pause lengths learned from
the audio, the transcript's sentence count picks the pauses) or first_pause (thesis Algorithm 3.1 from
the pause between the first two sentences, AlignOptions.first_pause_start_s .. first_pause_end_s).

Example:
    >>> talkface.AlignOptions(sentence_cut=talkface.SentenceCutMode.first_pause,
    ...                       first_pause_start_s=1.8, first_pause_end_s=2.4)
)doc")
        .value("automatic", SentenceCutMode::automatic)
        .value("first_pause", SentenceCutMode::first_pause);

    py::enum_<CheckMode>(m, "CheckMode", R"doc(
What the aligner does when the audio does not sound like its transcript (a missing or extra sentence,
the wrong text, a sentence alone in its file whose text lacks its last words: speech runs on 0.4 s or
more past its last syllable that generic speech fits better): refuse (the default: strong
evidence raises talkface.AlignmentError), warn (the finding goes to Timeline.warnings and the
syllables are aligned as with the checks off) or off (no checks). A finding names the sentence, its
times and the evidence; a line of a few syllables gives weak evidence, a warning in every mode.

Example:
    >>> talkface.AlignOptions(check=talkface.CheckMode.warn)
)doc")
        .value("refuse", CheckMode::refuse)
        .value("warn", CheckMode::warn)
        .value("off", CheckMode::off);

    py::class_<AlignOptions>(m, "AlignOptions", R"doc(
Options of SpeechAligner; checked when a SpeechAligner is made, which names the one out of range.
The defaults suit ordinary recordings.

Example:
    >>> options = talkface.AlignOptions(c1=0.9)
    >>> aligner = talkface.SpeechAligner(options)
)doc")
        .def(py::init([](SentenceCutMode sentence_cut, double first_pause_start_s, double first_pause_end_s,
                         double c1, double c2, CheckMode check, bool lenient) {
                 AlignOptions options;
                 options.sentence_cut = sentence_cut;
                 options.first_pause_start_s = first_pause_start_s;
                 options.first_pause_end_s = first_pause_end_s;
                 options.c1 = c1;
                 options.c2 = c2;
                 options.check = check;
                 options.lenient = lenient;
                 return options;
             }),
             py::arg("sentence_cut") = AlignOptions{}.sentence_cut,
             py::arg("first_pause_start_s") = AlignOptions{}.first_pause_start_s,
             py::arg("first_pause_end_s") = AlignOptions{}.first_pause_end_s, py::arg("c1") = AlignOptions{}.c1,
             py::arg("c2") = AlignOptions{}.c2, py::arg("check") = AlignOptions{}.check,
             py::arg("lenient") = AlignOptions{}.lenient, R"doc(
Args:
    sentence_cut (SentenceCutMode): automatic or first_pause.
    first_pause_start_s, first_pause_end_s (float): first_pause mode: the pause between the first two
        sentences, seconds from the start of the audio.
    c1 (float): Algorithm 3.1 step 3, shortest pause as a share of the first one, 0.5..1.
    c2 (float): Algorithm 3.1 step 4, loudest silence as a multiple of the first pause's peak, 1..1.5.
    check (CheckMode): refuse, warn or off: what a transcript that does not match the audio does.
    lenient (bool): align a transcript that differs from the speech by a word or two rather than
        refuse it: each stretch that does not say its text is fitted as generic speech and reported
        in Timeline.mismatches (and warnings); the checks then refuse nothing.

Example:
    >>> talkface.AlignOptions()
    >>> talkface.AlignOptions(talkface.SentenceCutMode.first_pause, 1.8, 2.4)
)doc")
        .def_readwrite("sentence_cut", &AlignOptions::sentence_cut, "SentenceCutMode")
        .def_readwrite("first_pause_start_s", &AlignOptions::first_pause_start_s, "seconds")
        .def_readwrite("first_pause_end_s", &AlignOptions::first_pause_end_s, "seconds")
        .def_readwrite("c1", &AlignOptions::c1, "Algorithm 3.1 step 3, 0.5..1")
        .def_readwrite("c2", &AlignOptions::c2, "Algorithm 3.1 step 4, 1..1.5")
        .def_readwrite("check", &AlignOptions::check, "CheckMode")
        .def_readwrite("lenient", &AlignOptions::lenient, "bool: report what does not match rather than refuse")
        .def("__repr__", [](const AlignOptions& o) {
            return py::str("talkface.AlignOptions(sentence_cut={!r}, first_pause_start_s={!r}, "
                           "first_pause_end_s={!r}, c1={!r}, c2={!r}, check={!r}, lenient={!r})")
                .format(o.sentence_cut, o.first_pause_start_s, o.first_pause_end_s, o.c1, o.c2, o.check, o.lenient);
        });

    m.attr("kLowAlignmentConfidence") = kLowAlignmentConfidence;

    py::class_<SpeechAligner>(m, "SpeechAligner", R"doc(
Aligns a recorded speech with its transcript (thesis chapter 3): each sentence gets start_s and end_s,
each syllable start_s (where its initial consonant starts), end_s, final_start_s (where its vowel
starts) and a confidence; the timeline's duration_s is the audio's length. A syllable whose confidence
is below talkface.kLowAlignmentConfidence (0.5) is one to check: its start may be more than 100 ms off.
The confidence (not a probability) grows with the evidence for the syllable's place (its sounds' fit,
a change of spectrum where it starts, lengths near their priors at the local pace, its neighbours'
evidence, whether the aligner's other searches start it at the same frame, how sure the search is of
its start; lenient alignment weighs the same but the last) and is calibrated on the recording, so the
threshold holds per condition: on the benchmark's
development speech (a person and two voices made of the same speaker's) no condition (noise, rooms,
music, phone, fast speech) has more than 10% of its syllables within 100 ms under it (the person's
3.0-7.8%, 5.2% pooled), and it catches 79% of those more than 100 ms off (held out: 2.0-8.9% and 82%;
the other voices 5.3-7.5% and 73%). Audio is read in blocks: an
hour of speech aligns in bounded memory.

The GIL is released while aligning, so alignments on several threads run at once; one aligner may be
shared by them.

Progress: progress(fraction, stage) is called on the calling thread, often enough to draw a progress
bar, with fraction 0..1 never decreasing (1 only as the call returns; work done again that no plan
foresees, such as the recording read again at another phase, fills the last 5% by halves) and stage
"reading", "sentences" or "syllables". Returning False (any false value but None) cancels with
talkface.Cancelled. An exception the callable raises stops the alignment and propagates as it is (a
KeyboardInterrupt stays a KeyboardInterrupt), not as Cancelled.
Without a callable, Ctrl-C still stops the alignment with KeyboardInterrupt.

Example:
    >>> aligner = talkface.SpeechAligner()
    >>> timeline = aligner.align_file("speech.wav", talkface.load_transcript("speech.txt"))
)doc")
        .def(py::init<AlignOptions>(), py::arg("options") = AlignOptions{}, R"doc(
Args:
    options (AlignOptions): how sentences are cut.

Raises:
    talkface.InvalidArgument: an option out of range (.parameter is "c1", "c2", "first_pause" or
        "sentence_cut").

Example:
    >>> talkface.SpeechAligner()
    >>> talkface.SpeechAligner(talkface.AlignOptions(c2=1.3))
)doc")
        .def_property_readonly(
            "options", [](const SpeechAligner& aligner) { return aligner.options(); }, "AlignOptions (a copy)")
        .def(
            "align_file",
            [](const SpeechAligner& aligner, const std::filesystem::path& path, const Timeline& transcript,
               const py::object& progress) {
                const std::string audio_path = path.string();
                // A copy: another Python thread may change the caller's timeline once the GIL is free.
                const Timeline transcript_copy = transcript;
                return run_without_gil(progress, [&](const ProgressCallback& callback) {
                    return aligner.align_file(audio_path, transcript_copy, callback);
                });
            },
            py::arg("path"), py::arg("transcript"), py::arg("progress") = py::none(), R"doc(
Aligns an audio file (WAV, FLAC, Ogg, MP3, AAC/M4A, Opus, AMR, AC-3, or a video's sound track: MP4, MOV,
MKV, WebM, MPEG-TS, MPEG; any rate, mono or stereo; of several sound tracks, the one that sounds like speech,
named in the result's warnings) with its transcript. Releases the GIL while it works.

Args:
    path (str | os.PathLike): the audio file.
    transcript (Timeline): from read_transcript() or load_transcript().
    progress (Callable[[float, str], bool | None] | None): see the class's docstring.

Returns:
    Timeline: the transcript's sentences and syllables with their times, seconds.

Raises:
    talkface.FileError: the file cannot be opened or read (also an OSError; .filename is the path).
    talkface.ParseError: it is not audio talkface reads.
    talkface.InvalidArgument: the audio is empty or silent, or the transcript has no syllables.
    talkface.AlignmentError: audio and transcript do not match (a missing or extra sentence, the wrong
        text, a text that lacks its last words); the message names the file, the sentence and its times.
    talkface.Cancelled: progress returned False.

Example:
    >>> timeline = aligner.align_file("speech.wav", transcript, progress=lambda f, s: print(s, f))
    >>> [(s.text, s.start_s) for s in timeline.syllables]
)doc")
        .def(
            "align",
            [](const SpeechAligner& aligner, const SampleArray& samples, int sample_rate_hz,
               const Timeline& transcript, const py::object& progress) {
                const AudioView audio = audio_view(samples, sample_rate_hz);
                const Timeline transcript_copy = transcript;
                return run_without_gil(progress, [&](const ProgressCallback& callback) {
                    return aligner.align(audio, transcript_copy, callback);
                });
            },
            py::arg("samples"), py::arg("sample_rate_hz"), py::arg("transcript"), py::arg("progress") = py::none(),
            R"doc(
Aligns samples in memory as align_file() does; the same audio gives the same timeline. Releases the
GIL while it works: do not write to the array meanwhile.

Args:
    samples (numpy.ndarray): float32 in -1..1, shape (frames,) for mono or (frames, channels),
        channels mixed down to mono; other float types are converted (a copy).
    sample_rate_hz (int): samples per second per channel (e.g. 16000).
    transcript (Timeline): from read_transcript() or load_transcript().
    progress (Callable[[float, str], bool | None] | None): see the class's docstring.

Raises:
    talkface.InvalidArgument: samples of another shape, empty, or with more channels than frames
        (.parameter "samples"); a rate out of range ("audio.sample_rate_hz"); a transcript without
        syllables.
    talkface.AlignmentError, talkface.Cancelled: as align_file().

Example:
    >>> samples, rate_hz = soundfile.read("speech.ogg", dtype="float32")  # (frames, channels)
    >>> timeline = aligner.align(samples, rate_hz, transcript)
)doc")
        .def("__repr__", [](const SpeechAligner& aligner) {
            return py::str("<talkface.SpeechAligner: {!r}>").format(aligner.options());
        });

    m.def(
        "alignment_plot_svg",
        [](const std::filesystem::path& audio_path, const Timeline& timeline) {
            const std::string audio = audio_path.string();
            const Timeline timeline_copy = timeline;
            py::gil_scoped_release release;
            return alignment_plot_svg(audio, timeline_copy);
        },
        py::arg("audio_path"), py::arg("timeline"), R"doc(
The picture of an alignment (thesis Figures 3.5 and 3.8) as an SVG document: the audio's waveform,
each sentence in one of two alternating colours, each syllable's start marked and labelled.

Args:
    audio_path (str | os.PathLike): the audio file that was aligned (read again, in blocks).
    timeline (Timeline): what SpeechAligner.align_file() returned for it.

Raises:
    talkface.FileError, talkface.ParseError: the audio cannot be read.

Example:
    >>> svg = talkface.alignment_plot_svg("speech.wav", timeline)
)doc");
    m.def(
        "write_alignment_plot_svg",
        [](const std::filesystem::path& svg_path, const std::filesystem::path& audio_path, const Timeline& timeline) {
            const std::string svg = svg_path.string();
            const std::string audio = audio_path.string();
            const Timeline timeline_copy = timeline;
            py::gil_scoped_release release;
            write_alignment_plot_svg(svg, audio, timeline_copy);
        },
        py::arg("svg_path"), py::arg("audio_path"), py::arg("timeline"), R"doc(
Writes alignment_plot_svg(audio_path, timeline) to svg_path through a temporary file that is
renamed: a failure leaves no file behind.

Raises:
    talkface.FileError: the audio cannot be read or svg_path cannot be written.
    talkface.ParseError: the audio is not audio talkface reads.

Example:
    >>> talkface.write_alignment_plot_svg("speech.svg", "speech.wav", timeline)
)doc");
}

}  // namespace talkface::python

// Timelines and transcripts in Python: Sentence, Syllable, WrittenForm, Timeline, read_transcript(),
// load_transcript(), is_valid_pinyin().
#include "bind.hpp"

namespace talkface::python {

namespace {

TranscriptOptions transcript_options(bool read_pinyin, bool keep_directions,
                                     const std::string& encoding = "") {
    TranscriptOptions options;
    options.read_pinyin = read_pinyin;
    options.keep_directions = keep_directions;
    options.encoding = encoding;
    return options;
}

}  // namespace

void bind_transcript(py::module_& m) {
    py::class_<Sentence>(m, "Sentence", R"doc(
A sentence of the transcript and, once aligned, when it is spoken (seconds).

Example:
    >>> s = talkface.Sentence("你好。", start_s=0.5, end_s=1.2)
    >>> s.end_s - s.start_s
)doc")
        .def(py::init([](std::string text, double start_s, double end_s, bool starts_paragraph) {
                 return Sentence{std::move(text), start_s, end_s, starts_paragraph};
             }),
             py::arg("text") = "", py::arg("start_s") = 0.0, py::arg("end_s") = 0.0,
             py::arg("starts_paragraph") = false, R"doc(
Args:
    text (str): the sentence as written, punctuation included.
    start_s, end_s (float): seconds from the start of the audio (0 before alignment).
    starts_paragraph (bool): whether a blank line of the transcript stands before it, beginning a
        new paragraph (the audio book's page keeps paragraphs).

Example:
    >>> talkface.Sentence("你好。")
    >>> talkface.Sentence("你好。", 0.5, 1.2)
)doc")
        .def_readwrite("text", &Sentence::text, "the sentence as written, UTF-8")
        .def_readwrite("start_s", &Sentence::start_s, "seconds from the start of the audio")
        .def_readwrite("end_s", &Sentence::end_s, "seconds; end_s >= start_s")
        .def_readwrite("starts_paragraph", &Sentence::starts_paragraph,
                       "whether a blank line stands before it: a new paragraph begins (never the first sentence)")
        .def("__eq__",
             [](const Sentence& a, const Sentence& b) {
                 return a.text == b.text && a.start_s == b.start_s && a.end_s == b.end_s &&
                        a.starts_paragraph == b.starts_paragraph;
             })
        .def("__repr__", [](const Sentence& s) {
            return py::str("talkface.Sentence({!r}, start_s={!r}, end_s={!r})").format(s.text, s.start_s, s.end_s);
        });

    py::class_<Syllable>(m, "Syllable", R"doc(
One syllable: one character of the transcript that has a reading, with its times once aligned.

Example:
    >>> s = talkface.Syllable("好", "hao3", sentence=0, start_s=0.5, end_s=0.8)
    >>> talkface.syllable_mouth_shapes(s.pinyin)
)doc")
        .def(py::init([](std::string text, std::string pinyin, std::size_t sentence, double start_s, double end_s,
                         std::optional<double> final_start_s, double confidence, bool pause_after,
                         bool generic_speech) {
                 return Syllable{std::move(text), std::move(pinyin), sentence,    start_s,       end_s,
                                 final_start_s,   confidence,        pause_after, generic_speech};
             }),
             py::arg("text") = "", py::arg("pinyin") = "", py::arg("sentence") = 0, py::arg("start_s") = 0.0,
             py::arg("end_s") = 0.0, py::arg("final_start_s") = py::none(), py::arg("confidence") = 1.0,
             py::arg("pause_after") = false, py::arg("generic_speech") = false, R"doc(
Args:
    text (str): the character (or the pinyin syllable when the transcript is pinyin).
    pinyin (str): numbered pinyin, u-umlaut written v: "lv4", "hang2".
    sentence (int): index into Timeline.sentences.
    start_s, end_s (float): seconds; start_s is where the initial consonant starts.
    final_start_s (float | None): where the final (vowel) starts, when measured.
    confidence (float): 0..1, how sure the aligner is of the times (not a probability); below
        talkface.kLowAlignmentConfidence (0.5) the syllable may be more than 100 ms off: check it (on
        the benchmark's human speech that flags at most 10% of right syllables in every condition,
        5.2% pooled, and catches 79% of those more than 100 ms off; SpeechAligner says more).
    pause_after (bool): the transcript marks a pause after it (，、：).
    generic_speech (bool): part of a word no table reads (an English word the dictionary lacks): the
        aligner fits it as any speech; its pinyin is talkface.kGenericSpeechPinyin ("de5"), which only
        shapes the mouth.

Example:
    >>> talkface.Syllable("行", "hang2")
    >>> talkface.Syllable("媽", "ma1", 0, 0.5, 0.8, final_start_s=0.58)
)doc")
        .def_readwrite("text", &Syllable::text, "the character, UTF-8")
        .def_readwrite("pinyin", &Syllable::pinyin, "numbered pinyin, u-umlaut written v")
        .def_readwrite("sentence", &Syllable::sentence, "index into Timeline.sentences")
        .def_readwrite("start_s", &Syllable::start_s, "where its initial consonant starts, seconds")
        .def_readwrite("end_s", &Syllable::end_s, "seconds")
        .def_readwrite("final_start_s", &Syllable::final_start_s, "where its final starts, seconds, or None")
        .def_readwrite("confidence", &Syllable::confidence, "0..1")
        .def_readwrite("pause_after", &Syllable::pause_after, "a pause the transcript marks after it")
        .def_readwrite("generic_speech", &Syllable::generic_speech,
                       "part of a word no table reads, aligned as any speech")
        .def("__eq__",
             [](const Syllable& a, const Syllable& b) {
                 return a.text == b.text && a.pinyin == b.pinyin && a.sentence == b.sentence &&
                        a.start_s == b.start_s && a.end_s == b.end_s && a.final_start_s == b.final_start_s &&
                        a.confidence == b.confidence && a.pause_after == b.pause_after &&
                        a.generic_speech == b.generic_speech;
             })
        .def("__repr__", [](const Syllable& s) {
            return py::str("talkface.Syllable({!r}, {!r}, sentence={!r}, start_s={!r}, end_s={!r}, "
                           "final_start_s={!r}, confidence={!r}, pause_after={!r}, generic_speech={!r})")
                .format(s.text, s.pinyin, s.sentence, s.start_s, s.end_s, s.final_start_s, s.confidence,
                        s.pause_after, s.generic_speech);
        });
    m.attr("kGenericSpeechPinyin") = kGenericSpeechPinyin;

    py::class_<WrittenForm>(m, "WrittenForm", R"doc(
A stretch of the transcript read by rule (a number, date, time, amount, letters, an English word)
and the syllables it became: timeline.syllables[first_syllable : first_syllable + syllable_count].

Example:
    >>> timeline = talkface.read_transcript("2026年")
    >>> form = timeline.written_forms[0]
    >>> form.text, [s.pinyin for s in timeline.syllables[form.first_syllable:][:form.syllable_count]]
    ('2026年', ['er4', 'ling2', 'er4', 'liu4', 'nian2'])
)doc")
        .def(py::init([](std::string text, std::size_t first_syllable, std::size_t syllable_count) {
                 return WrittenForm{std::move(text), first_syllable, syllable_count};
             }),
             py::arg("text") = "", py::arg("first_syllable") = 0, py::arg("syllable_count") = 0, R"doc(
Args:
    text (str): the form as the page shows it, UTF-8: "2026年", "3:30", "iPhone".
    first_syllable (int): index into Timeline.syllables of its first syllable.
    syllable_count (int): how many syllables it became.

Example:
    >>> talkface.WrittenForm("OK", first_syllable=3, syllable_count=2)
)doc")
        .def_readwrite("text", &WrittenForm::text, "the form as written, UTF-8")
        .def_readwrite("first_syllable", &WrittenForm::first_syllable, "index of its first syllable")
        .def_readwrite("syllable_count", &WrittenForm::syllable_count, "how many syllables it became")
        .def("__eq__",
             [](const WrittenForm& a, const WrittenForm& b) {
                 return a.text == b.text && a.first_syllable == b.first_syllable &&
                        a.syllable_count == b.syllable_count;
             })
        .def("__repr__", [](const WrittenForm& f) {
            return py::str("talkface.WrittenForm({!r}, first_syllable={!r}, syllable_count={!r})")
                .format(f.text, f.first_syllable, f.syllable_count);
        });

    m.attr("MISMATCH_LOUDNESS_STEP_S") = kMismatchLoudnessStepS;
    py::class_<TextMismatch>(m, "TextMismatch", R"doc(
A stretch where the speech does not say the transcript's text, found by lenient alignment
(AlignOptions(lenient=True)): its time span, the syllables it stands for
(timeline.syllables[first_syllable : first_syllable + syllable_count], spread over the stretch at
its loudness dips with confidence 0), the text expected there, and the audio's loudness over it
(loudness: one value 0..1 per MISMATCH_LOUDNESS_STEP_S = 0.02 s from start_s; 0 silence, 1 the
recording's loud speech), which the mouth follows there instead of the syllables' shapes.
syllable_count is 0 where the speech has words the transcript lacks; start_s == end_s where the
speech leaves the text out.

Example:
    >>> aligned = talkface.SpeechAligner(talkface.AlignOptions(lenient=True)).align_file("a.wav", timeline)
    >>> [(m.start_s, m.end_s, m.expected_text) for m in aligned.mismatches]
)doc")
        .def(py::init([](double start_s, double end_s, std::size_t first_syllable, std::size_t syllable_count,
                         std::string expected_text, std::vector<double> loudness) {
                 return TextMismatch{start_s, end_s, first_syllable, syllable_count, std::move(expected_text),
                                     std::move(loudness)};
             }),
             py::arg("start_s") = 0.0, py::arg("end_s") = 0.0, py::arg("first_syllable") = 0,
             py::arg("syllable_count") = 0, py::arg("expected_text") = "",
             py::arg("loudness") = std::vector<double>{}, R"doc(
Args:
    start_s, end_s (float): the stretch of audio, seconds.
    first_syllable (int): index into Timeline.syllables of the first syllable it stands for.
    syllable_count (int): how many syllables it stands for (0: speech the transcript lacks).
    expected_text (str): what the transcript says there, UTF-8.
    loudness (list[float]): the audio's loudness, 0..1, one value per 0.02 s from start_s (empty:
        not measured; the mouth then shows the syllables' shapes).
)doc")
        .def_readwrite("start_s", &TextMismatch::start_s, "seconds")
        .def_readwrite("end_s", &TextMismatch::end_s, "seconds")
        .def_readwrite("first_syllable", &TextMismatch::first_syllable, "index of the first syllable it stands for")
        .def_readwrite("syllable_count", &TextMismatch::syllable_count, "how many syllables it stands for")
        .def_readwrite("expected_text", &TextMismatch::expected_text, "what the transcript says there, UTF-8")
        .def_readwrite("loudness", &TextMismatch::loudness,
                       "list[float] (a copy): the audio's loudness 0..1, one value per 0.02 s from start_s")
        .def("__eq__",
             [](const TextMismatch& a, const TextMismatch& b) {
                 return a.start_s == b.start_s && a.end_s == b.end_s && a.first_syllable == b.first_syllable &&
                        a.syllable_count == b.syllable_count && a.expected_text == b.expected_text &&
                        a.loudness == b.loudness;
             })
        .def("__repr__", [](const TextMismatch& mismatch) {
            return py::str("talkface.TextMismatch(start_s={!r}, end_s={!r}, first_syllable={!r}, syllable_count={!r}, "
                           "expected_text={!r})")
                .format(mismatch.start_s, mismatch.end_s, mismatch.first_syllable, mismatch.syllable_count,
                        mismatch.expected_text);
        });

    py::class_<Timeline>(m, "Timeline", R"doc(
Sentences and syllables in transcript order, with what the reader skipped (warnings) and the length of
the audio. The list attributes are copies: change one and assign it back
(timeline.syllables = syllables), as for any list of C++ values.

Example:
    >>> timeline = talkface.read_transcript("你好。")
    >>> [s.pinyin for s in timeline.syllables]
    ['ni3', 'hao3']
)doc")
        .def(py::init([](std::vector<Sentence> sentences, std::vector<Syllable> syllables,
                         std::vector<std::string> warnings, double duration_s,
                         std::vector<WrittenForm> written_forms, std::vector<TextMismatch> mismatches) {
                 return Timeline{std::move(sentences), std::move(syllables), std::move(warnings), duration_s,
                                 std::move(written_forms), std::move(mismatches)};
             }),
             py::arg("sentences") = std::vector<Sentence>{}, py::arg("syllables") = std::vector<Syllable>{},
             py::arg("warnings") = std::vector<std::string>{}, py::arg("duration_s") = 0.0,
             py::arg("written_forms") = std::vector<WrittenForm>{},
             py::arg("mismatches") = std::vector<TextMismatch>{}, R"doc(
Args:
    sentences (list[Sentence]): in transcript order.
    syllables (list[Syllable]): in transcript order, each naming its sentence.
    warnings (list[str]): what the transcript reader skipped; after alignment, also what the aligner
        says of the recording (a damaged or cut file, a header whose length disagrees with its sound,
        each naming the file) and of the match (a finding of CheckMode.warn, a transcript with no
        Mandarin reading, which cannot be checked).
    duration_s (float): length of the audio, seconds.
    written_forms (list[WrittenForm]): the forms read by rule, in order, none overlapping.
    mismatches (list[TextMismatch]): where the speech does not say the text (lenient alignment).

Example:
    >>> talkface.Timeline([talkface.Sentence("好。", 0.2, 0.6)],
    ...                   [talkface.Syllable("好", "hao3", 0, 0.2, 0.6)], duration_s=1.0)
)doc")
        .def_readwrite("sentences", &Timeline::sentences, "list[Sentence] (a copy)")
        .def_readwrite("syllables", &Timeline::syllables, "list[Syllable] (a copy)")
        .def_readwrite(
            "warnings", &Timeline::warnings,
            "list[str]: what the reader skipped, and where; after alignment, what the aligner says "
            "of the recording and the match")
        .def_readwrite("duration_s", &Timeline::duration_s,
                       "length of the audio, seconds (0 before alignment)")
        .def_readwrite("written_forms", &Timeline::written_forms,
                       "list[WrittenForm] (a copy): numbers, dates, letters, English words read by rule")
        .def_readwrite(
            "mismatches", &Timeline::mismatches,
            "list[TextMismatch] (a copy): where the speech does not say the text (lenient alignment)")
        .def("__repr__", [](const Timeline& t) {
            return py::str("<talkface.Timeline: {} sentences, {} syllables, {} warnings, duration_s={!r}>")
                .format(t.sentences.size(), t.syllables.size(), t.warnings.size(), t.duration_s);
        });

    m.def(
        "read_transcript",
        [](std::string_view text, const std::string& source_name, bool read_pinyin, bool keep_directions) {
            py::gil_scoped_release release;
            return read_transcript(text, transcript_options(read_pinyin, keep_directions), source_name);
        },
        py::arg("text"), py::arg("source_name") = "<transcript>", py::arg("read_pinyin") = true,
        py::arg("keep_directions") = false, R"doc(
Reads a transcript (Traditional or Simplified characters, or numbered pinyin) into sentences and
syllables, times all 0. Sentences end at 。！？；… and . ! ? ;. A polyphonic character is read by the
built-in phrase table; fix a reading in place: 行{hang2}. Written forms are read as a native reader
says them (2026年 二零二六年, 85% 百分之八十五, AI ei ai, iPhone ai feng; docs/written-forms.md), each
kept in Timeline.written_forms; fix one in place: 2026{两千零二十六}. Characters without a reading
are skipped and reported in Timeline.warnings ("source:line:column: ..."). A script's stage
directions (a bracket of sounds and actions: （笑） [掌声] 【音乐】) and, in a dialogue, its speaker
labels at line starts (主持人： A:) are not said: left out with a warning (docs/transcripts.md).

Args:
    text (str): the transcript.
    source_name (str): names the text in messages.
    read_pinyin (bool): read runs of Latin letters that spell Mandarin syllables as syllables
        (otherwise as letters or English words).
    keep_directions (bool): read stage directions and speaker labels as text.

Raises:
    talkface.ParseError: a reading fix that is not Mandarin (行{hxng2}, 5{★}), an unclosed "{"
        (names source:line:column).

Example:
    >>> timeline = talkface.read_transcript("長期下來，傷害不斷累積。")
    >>> timeline.syllables[0].pinyin
    'chang2'
)doc");
    m.def(
        "load_transcript",
        [](const std::filesystem::path& path, bool read_pinyin, const std::string& encoding,
           bool keep_directions) {
            const std::string transcript_path = path.string();
            py::gil_scoped_release release;
            return load_transcript(transcript_path,
                                   transcript_options(read_pinyin, keep_directions, encoding));
        },
        py::arg("path"), py::arg("read_pinyin") = true, py::arg("encoding") = "",
        py::arg("keep_directions") = false,
        R"doc(
Reads a transcript file as read_transcript() does; messages name the path. The file is UTF-8,
UTF-16 or UTF-32 with a byte order mark, or in `encoding`; or SRT or WebVTT subtitles or a Praat
TextGrid, whose text is read: a sentence per cue (unless its text runs on, ending in ， or :), cue
numbers, times and markup dropped (docs/transcripts.md).

Args:
    path (str | os.PathLike): the file.
    read_pinyin (bool): as read_transcript().
    encoding (str): the file's encoding when it has no byte order mark, a name iconv knows:
        "gb18030" (GBK), "big5", "big5-hkscs", "utf-16le", ...; "" means UTF-8.
    keep_directions (bool): as read_transcript().

Raises:
    talkface.FileError: the file cannot be read (also an OSError).
    talkface.InvalidArgument: an encoding iconv does not know.
    talkface.ParseError: as read_transcript(); bytes not in the encoding (not UTF-8: the message
        names the encodings that read them as Chinese, GB18030, Big5 or UTF-16); a malformed
        subtitle or TextGrid.

Example:
    >>> timeline = talkface.load_transcript("story.txt")
    >>> timeline.warnings
)doc");
    m.def("is_valid_pinyin", &is_valid_pinyin, py::arg("syllable"), R"doc(
True if syllable is a legal Mandarin syllable in numbered pinyin ("hang2", "lv4", "ma5").

Example:
    >>> talkface.is_valid_pinyin("hang2")
    True
)doc");
}

}  // namespace talkface::python

"""Timing exports and imports in Python: export_to_string / export_to_file from an animation,
every import format read back (round trips), refusals that name the file and the place, and the
format lists (the same codecs as the command and C)."""
import json

import pytest

import talkface


def spoken():
    """你好，世界。 from 0.5 s, a syllable every 0.25 s, 2 s of audio."""
    timeline = talkface.read_transcript("你好，世界。")
    syllables = timeline.syllables
    for index, syllable in enumerate(syllables):
        syllable.start_s = 0.5 + 0.25 * index
        syllable.end_s = syllable.start_s + 0.25
    timeline.syllables = syllables
    sentences = timeline.sentences
    sentences[0].start_s, sentences[0].end_s = 0.5, 1.5
    timeline.sentences = sentences
    timeline.duration_s = 2.0
    return timeline


@pytest.fixture
def animation():
    timeline = spoken()
    return talkface.animate(talkface.FaceModel.default(), timeline, talkface.ExpressionSimulator(timeline, 5))


def test_exports_span_the_audio(animation):
    timeline = spoken()
    tsv = talkface.export_to_string(timeline, animation, "rhubarb-tsv")
    assert tsv.startswith("0.00\tX\n") and tsv.endswith("\n2.00\tX\n")
    cues = json.loads(talkface.export_to_string(timeline, animation, "rhubarb-json", audio_path="/a/b.wav"))
    assert cues["metadata"] == {"soundFile": "/a/b.wav", "duration": 2.0}
    assert cues["mouthCues"][0]["start"] == 0 and cues["mouthCues"][-1]["end"] == 2.0
    motion = json.loads(talkface.export_to_string(timeline, animation, "live2d"))
    assert motion["Meta"]["CurveCount"] == len(motion["Curves"]) == 9
    assert talkface.export_to_string(timeline, animation, "srt") == "1\n00:00:00,500 --> 00:00:01,500\n你好，世界。\n"
    assert "lottie" not in talkface.export_format_names()


def test_export_to_file_takes_the_format_from_the_suffix(tmp_path, animation):
    path = tmp_path / "speech.TextGrid"
    talkface.export_to_file(path, spoken(), animation)
    assert path.read_text(encoding="utf-8").startswith('File type = "ooTextFile"\nObject class = "TextGrid"\n')
    with pytest.raises(talkface.InvalidArgument, match=r'no export format for suffix "\.xyz"'):
        talkface.export_to_file(tmp_path / "cues.xyz", spoken(), animation)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["speech.TextGrid"]


@pytest.mark.parametrize("fmt", ["textgrid", "words-json", "timeline-json", "vtt"])
def test_every_syllable_format_round_trips(fmt):
    timeline = spoken()
    text = talkface.write_timing_string(timeline, fmt)
    back = talkface.read_timing_string(text, fmt, talkface.read_transcript("你好，世界。"), 2.0)
    assert [(s.start_s, s.end_s) for s in back.syllables] == pytest.approx(
        [(s.start_s, s.end_s) for s in timeline.syllables])
    assert back.duration_s == 2.0


def test_srt_round_trips_the_sentences(tmp_path):
    path = tmp_path / "speech.srt"
    path.write_text(talkface.write_timing_string(spoken(), "srt"), encoding="utf-8")
    back = talkface.read_timing_file(path, talkface.read_transcript("你好，世界。"), 2.0)
    assert (back.sentences[0].start_s, back.sentences[0].end_s) == (0.5, 1.5)


@pytest.mark.parametrize("fmt, suffix", [("srt", "srt"), ("vtt", "vtt"), ("words-json", "json")])
@pytest.mark.parametrize("encoding", ["utf-16", "utf-16-be", "utf-8-sig"])
def test_a_file_saved_as_utf16_or_with_a_byte_order_mark_reads_as_its_utf8(tmp_path, fmt, suffix, encoding):
    # What Windows Notepad's "Unicode" and subtitle editors save; the BOM says which.
    text = talkface.write_timing_string(spoken(), fmt)
    plain, marked = tmp_path / f"plain.{suffix}", tmp_path / f"marked.{suffix}"
    plain.write_text(text, encoding="utf-8")
    marked.write_bytes((b"\xfe\xff" if encoding == "utf-16-be" else b"") + text.encode(encoding))
    transcript = talkface.read_transcript("你好，世界。")
    want = talkface.read_timing_file(plain, transcript, 2.0)
    got = talkface.read_timing_file(marked, transcript, 2.0)
    assert [(s.start_s, s.end_s) for s in got.syllables] == [(s.start_s, s.end_s) for s in want.syllables]


def test_a_timing_that_parts_from_the_transcript_names_the_place():
    words = '[{"text": "你好", "start": 0.5, "end": 1.0},\n {"text": "世間", "start": 1.0, "end": 1.5}]'
    with pytest.raises(talkface.ParseError, match=r'words\.json:2: "世間": "間" parts from the transcript at '
                                                  r'sentence 1 .*syllable 4 "界"') as caught:
        talkface.read_timing_string(words, "json", talkface.read_transcript("你好，世界。"), 2.0, "words.json")
    assert caught.value.line == 2
    with pytest.raises(talkface.ParseError, match=r"past the end of the audio \(1\.2 s\)"):
        talkface.read_timing_string(words, "words-json", talkface.read_transcript("你好，世界。"), 1.2)


def test_time_transcript_reads_a_word_timing_against_the_recording(tmp_path):
    import pathlib
    clips = pathlib.Path(__file__).parents[2] / "tests" / "data" / "speech"
    transcript = talkface.load_transcript(clips / "one_sentence.txt")
    duration_s = talkface.audio_duration_s(clips / "one_sentence.wav")
    words = [{"text": s.text, "start": 0.1 + 0.2 * k, "end": 0.3 + 0.2 * k} for k, s in enumerate(transcript.syllables)]
    timing = tmp_path / "words.json"
    timing.write_text(json.dumps(words, ensure_ascii=False), encoding="utf-8")
    timeline = talkface.time_transcript(timing, clips / "one_sentence.wav", transcript)
    assert timeline.duration_s == duration_s
    assert timeline.syllables[1].start_s == pytest.approx(0.3)


def test_time_transcript_pins_the_aligner_to_a_subtitle_cue(tmp_path):
    import pathlib
    clips = pathlib.Path(__file__).parents[2] / "tests" / "data" / "speech"
    transcript = talkface.load_transcript(clips / "one_sentence.txt")
    cue = tmp_path / "cue.srt"  # the sentence is spoken 0.30-2.79 s; its cue says 0.60-2.50
    cue.write_text("1\n00:00:00,600 --> 00:00:02,500\n小朋友們在公園裡放風箏。\n", encoding="utf-8")
    timeline = talkface.time_transcript(cue, clips / "one_sentence.wav", transcript)
    assert len(timeline.syllables) == len(transcript.syllables)
    assert all(0.6 - 1e-9 <= s.start_s < s.end_s <= 2.5 + 1e-9 for s in timeline.syllables)
    # The same cue saved by Windows Notepad as "Unicode" (UTF-16 with its byte order mark).
    notepad = tmp_path / "notepad.srt"
    notepad.write_text(cue.read_text(encoding="utf-8"), encoding="utf-16")
    again = talkface.time_transcript(notepad, clips / "one_sentence.wav", transcript)
    assert [s.start_s for s in again.syllables] == [s.start_s for s in timeline.syllables]


def test_time_transcript_takes_the_aligners_options_lenient_among_them(tmp_path):
    import pathlib
    clips = pathlib.Path(__file__).parents[2] / "tests" / "data" / "speech"
    transcript = talkface.read_transcript("小朋友们在里放风筝。")  # the clip says 公园 too
    cue = tmp_path / "cue.srt"
    cue.write_text("1\n00:00:00,200 --> 00:00:03,100\n小朋友们在里放风筝。\n", encoding="utf-8")
    lenient = talkface.AlignOptions(lenient=True)
    timeline = talkface.time_transcript(cue, clips / "lenient_espeak.flac", transcript, options=lenient)
    assert [(m.first_syllable, m.syllable_count) for m in timeline.mismatches] == [(5, 0)]
    words = tmp_path / "words.json"
    words.write_text('[{"text": "小朋友们在里放风筝", "start": 0.3, "end": 2.9}]', encoding="utf-8")
    with pytest.raises(ValueError, match="times every syllable itself"):
        talkface.time_transcript(words, clips / "lenient_espeak.flac", transcript, options=lenient)
    assert talkface.time_transcript(words, clips / "lenient_espeak.flac", transcript).mismatches == []

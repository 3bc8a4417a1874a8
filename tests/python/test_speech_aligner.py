"""The speech aligner in Python: SpeechAligner.align_file and .align on the test clips, AlignOptions and
their checks, progress and cancellation, the callback's own exceptions, numpy shapes, and two
alignments at once on two threads (the GIL is released while aligning)."""
import pathlib
import subprocess
import sys
import threading
import wave

import numpy
import pytest

import talkface

sys.path.insert(0, str(pathlib.Path(__file__).parents[1] / "common"))
import damaged_copies  # noqa: E402

CLIPS_DIR = pathlib.Path(__file__).parents[2] / "tests" / "data" / "speech"
CLIP = CLIPS_DIR / "one_sentence.wav"  # 3.09 s, 16 kHz mono 16-bit: 小朋友們在公園裡放風箏。
DURATION_S = 3.09052


def clip_transcript(name="one_sentence"):
    return talkface.load_transcript(CLIPS_DIR / f"{name}.txt")


def read_wav(path):
    """(samples as float32 in -1..1, shape (frames,) or (frames, channels), rate) of a 16-bit PCM WAV,
    scaled as libsndfile scales it (x / 32768)."""
    with wave.open(str(path), "rb") as file:
        assert file.getsampwidth() == 2
        frames = numpy.frombuffer(file.readframes(file.getnframes()), dtype="<i2")
        channels, rate_hz = file.getnchannels(), file.getframerate()
    samples = frames.astype(numpy.float32) / numpy.float32(32768)
    return (samples if channels == 1 else samples.reshape(-1, channels)), rate_hz


def times(timeline):
    return [(s.start_s, s.end_s, s.final_start_s, s.confidence) for s in timeline.syllables]


@pytest.fixture(scope="module")
def from_file():
    return talkface.SpeechAligner().align_file(CLIP, clip_transcript())


def test_align_file_gives_ordered_times_inside_the_audio(from_file):
    transcript = clip_transcript()
    assert [s.text for s in from_file.sentences] == [s.text for s in transcript.sentences]
    assert [(s.text, s.pinyin, s.sentence) for s in from_file.syllables] == [
        (s.text, s.pinyin, s.sentence) for s in transcript.syllables]
    assert len(from_file.syllables) == 11
    assert from_file.duration_s == pytest.approx(DURATION_S, abs=0.01)
    previous_end = 0.0
    for syllable in from_file.syllables:
        assert previous_end <= syllable.start_s < syllable.end_s <= from_file.duration_s
        assert syllable.final_start_s is None or syllable.start_s <= syllable.final_start_s <= syllable.end_s
        assert 0.0 <= syllable.confidence <= 1.0
        # A clean clip: none of its syllables comes out doubtful.
        assert syllable.confidence >= talkface.kLowAlignmentConfidence
        previous_end = syllable.end_s
    sentence = from_file.sentences[0]
    assert (sentence.start_s, sentence.end_s) == (from_file.syllables[0].start_s, from_file.syllables[-1].end_s)


def test_align_on_samples_gives_the_file_timeline(from_file):
    samples, rate_hz = read_wav(CLIP)
    aligner = talkface.SpeechAligner()
    assert times(aligner.align(samples, rate_hz, clip_transcript())) == times(from_file)
    # A float64 array is converted; two equal channels mix down to the same mono samples.
    assert times(aligner.align(samples.astype(numpy.float64), rate_hz, clip_transcript())) == times(from_file)
    stereo = numpy.ascontiguousarray(numpy.stack([samples, samples], axis=1))
    assert times(aligner.align(stereo, rate_hz, clip_transcript())) == times(from_file)


def test_two_threads_align_at_once_and_agree(from_file):
    aligner = talkface.SpeechAligner()
    transcript = clip_transcript()
    samples, rate_hz = read_wav(CLIP)
    results = [None, None]
    start = threading.Barrier(2)

    def align(slot, call):
        start.wait()
        results[slot] = call()

    threads = [
        threading.Thread(target=align, args=(0, lambda: aligner.align_file(CLIP, transcript))),
        threading.Thread(target=align, args=(1, lambda: aligner.align(samples, rate_hz, transcript,
                                                                        progress=lambda f, s: True))),
    ]
    for thread in threads:
        thread.start()
    for thread in threads:
        thread.join(timeout=300)
    assert times(results[0]) == times(from_file)
    assert times(results[1]) == times(from_file)


def test_progress_rises_through_the_stages():
    reports = []
    talkface.SpeechAligner().align_file(CLIP, clip_transcript(), progress=lambda f, s: reports.append((f, s)))
    fractions = [fraction for fraction, _ in reports]
    assert len(reports) >= 5
    assert fractions == sorted(fractions)
    assert fractions[0] == 0.0 and fractions[-1] == 1.0
    assert reports[0][1] == "reading" and reports[-1][1] == "syllables"
    assert {stage for _, stage in reports} <= {"reading", "sentences", "syllables"}


def test_returning_false_cancels():
    calls = []

    def progress(fraction, stage):
        calls.append(fraction)
        return fraction < 0.5

    with pytest.raises(talkface.Cancelled, match="cancelled") as caught:
        talkface.SpeechAligner().align_file(CLIP, clip_transcript(), progress=progress)
    assert caught.value.code == talkface.ErrorCode.cancelled
    assert calls[-1] >= 0.5 and all(fraction < 0.5 for fraction in calls[:-1])


def test_an_exception_in_progress_propagates_as_it_is():
    class Stop(Exception):
        pass

    def progress(fraction, stage):
        if stage == "sentences":
            raise Stop(f"stopped at {fraction:.2f}")
        return True

    with pytest.raises(Stop, match="stopped at"):
        talkface.SpeechAligner().align_file(CLIP, clip_transcript(), progress=progress)

    def interrupt(fraction, stage):
        raise KeyboardInterrupt

    samples, rate_hz = read_wav(CLIP)
    with pytest.raises(KeyboardInterrupt):
        talkface.SpeechAligner().align(samples, rate_hz, clip_transcript(), progress=interrupt)


def test_without_a_callable_an_interrupt_still_stops_the_alignment():
    # In a child process: a KeyboardInterrupt that came too late would otherwise hit pytest itself.
    script = f"""
import _thread, threading, wave, numpy, talkface
with wave.open({str(CLIP)!r}, "rb") as file:
    frames = numpy.frombuffer(file.readframes(file.getnframes()), dtype="<i2")
twenty_minutes = numpy.tile(frames.astype(numpy.float32) / 32768, 400)  # over a second of reading
threading.Timer(0.2, _thread.interrupt_main).start()
try:
    talkface.SpeechAligner().align(twenty_minutes, 16000, talkface.load_transcript({str(CLIPS_DIR / "one_sentence.txt")!r}))
except KeyboardInterrupt:
    print("KeyboardInterrupt")
"""
    result = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, timeout=120)
    assert result.stdout == "KeyboardInterrupt\n", result.stderr


def test_options_are_checked_and_reach_the_aligner():
    options = talkface.AlignOptions(c1=0.3)
    with pytest.raises(talkface.InvalidArgument, match="c1") as caught:
        talkface.SpeechAligner(options)
    assert caught.value.parameter == "c1"
    with pytest.raises(talkface.InvalidArgument, match="c2"):
        talkface.SpeechAligner(talkface.AlignOptions(c2=2.0))
    with pytest.raises(talkface.InvalidArgument, match="first_pause"):
        talkface.SpeechAligner(talkface.AlignOptions(sentence_cut=talkface.SentenceCutMode.first_pause))

    # two_sentences: 今天下午有雨。我们明天再去吧。 with the pause between them at 1.69-2.59 s.
    options = talkface.AlignOptions(talkface.SentenceCutMode.first_pause, 1.8, 2.4)
    aligner = talkface.SpeechAligner(options)
    assert aligner.options.sentence_cut == talkface.SentenceCutMode.first_pause
    assert aligner.options.first_pause_end_s == 2.4
    timeline = aligner.align_file(CLIPS_DIR / "two_sentences.wav", clip_transcript("two_sentences"))
    assert len(timeline.sentences) == 2
    assert 2.4 < timeline.sentences[1].start_s < 2.7
    inside_a_sentence = talkface.SpeechAligner(talkface.AlignOptions(talkface.SentenceCutMode.first_pause, 0.9, 0.92))
    with pytest.raises(talkface.AlignmentError):
        inside_a_sentence.align_file(CLIPS_DIR / "two_sentences.wav", clip_transcript("two_sentences"))


def test_mismatched_transcript_is_an_alignment_error_naming_where():
    aligner = talkface.SpeechAligner()
    extra = talkface.read_transcript("小朋友們在公園裡放風箏。今天下午有雨。")
    with pytest.raises(talkface.AlignmentError, match="one_sentence.wav: .*sentence") as caught:
        aligner.align_file(CLIP, extra)
    assert caught.value.code == talkface.ErrorCode.alignment
    with pytest.raises(talkface.AlignmentError, match='"我很好。"'):
        aligner.align_file(CLIP, talkface.read_transcript("我很好。"))


def test_bad_audio_and_transcript_are_named(tmp_path):
    aligner = talkface.SpeechAligner()
    missing = tmp_path / "no_such_speech.wav"
    with pytest.raises(talkface.FileError, match="no_such_speech.wav") as caught:
        aligner.align_file(missing, clip_transcript())
    assert isinstance(caught.value, OSError) and caught.value.filename == str(missing)
    with pytest.raises(talkface.InvalidArgument, match="transcript"):
        aligner.align_file(CLIP, talkface.read_transcript("♪♪."))


def test_numpy_shapes_are_checked_and_named():
    aligner = talkface.SpeechAligner()
    transcript = clip_transcript()
    samples, rate_hz = read_wav(CLIP)
    with pytest.raises(talkface.InvalidArgument, match=r"samples: expected shape \(frames,\) or \(frames, channels\), "
                                                       r"got \(2, 3, 4\)") as caught:
        aligner.align(numpy.zeros((2, 3, 4), dtype=numpy.float32), rate_hz, transcript)
    assert caught.value.parameter == "samples"
    with pytest.raises(talkface.InvalidArgument, match=r"got \(2, \d+\).*samples\.T"):
        aligner.align(numpy.stack([samples, samples]), rate_hz, transcript)
    with pytest.raises(talkface.InvalidArgument, match=r"samples: empty"):
        aligner.align(numpy.zeros(0, dtype=numpy.float32), rate_hz, transcript)
    with pytest.raises(talkface.InvalidArgument, match="sample_rate_hz"):
        aligner.align(samples, 100, transcript)
    with pytest.raises(TypeError):
        aligner.align("not samples", rate_hz, transcript)


def test_alignment_plot_marks_every_syllable_and_is_written_whole(tmp_path, from_file):
    import xml.etree.ElementTree as ET

    svg = talkface.alignment_plot_svg(CLIP, from_file)
    root = ET.fromstring(svg)
    labels = [t.text for t in root.iter("{http://www.w3.org/2000/svg}text") if t.text and not t.text.endswith(" s")]
    assert labels == [f"{s.text} {s.pinyin}" for s in from_file.syllables]
    out = tmp_path / "plot.svg"
    talkface.write_alignment_plot_svg(out, CLIP, from_file)
    assert out.read_text(encoding="utf-8") == svg
    with pytest.raises(talkface.FileError, match="no_such_speech.wav"):
        talkface.write_alignment_plot_svg(tmp_path / "never.svg", tmp_path / "no_such_speech.wav", from_file)
    assert not (tmp_path / "never.svg").exists()


def test_check_mode_refuses_warns_of_or_skips_a_wrong_text():
    wrong = talkface.read_transcript("我昨天在超市买了苹果和。")
    assert talkface.AlignOptions().check == talkface.CheckMode.refuse
    with pytest.raises(talkface.AlignmentError, match="is it another sentence, or are two sentences swapped"):
        talkface.SpeechAligner().align_file(CLIP, wrong)
    warned = talkface.SpeechAligner(talkface.AlignOptions(check=talkface.CheckMode.warn)).align_file(CLIP, wrong)
    findings = [w for w in warned.warnings if w.startswith("the transcript may not match the audio")]
    assert len(findings) == 1 and "sentence 1 (0." in findings[0]
    assert len(warned.syllables) == len(wrong.syllables)
    options = talkface.AlignOptions()
    options.check = talkface.CheckMode.off
    assert "check=<CheckMode.off: 2>" in repr(options)
    unchecked = talkface.SpeechAligner(options).align_file(CLIP, wrong)
    assert unchecked.warnings == []
    assert [s.start_s for s in unchecked.syllables] == [s.start_s for s in warned.syllables]


def test_lenient_reports_speech_the_transcript_lacks_and_keeps_the_rest():
    # espeak-ng says 小朋友们在公园里放风筝; the transcript lacks 公园 (tests/data/speech/make_clips.sh).
    transcript = talkface.read_transcript("小朋友们在里放风筝。")
    audio = CLIPS_DIR / "lenient_espeak.flac"
    options = talkface.AlignOptions(lenient=True)
    assert options.lenient and "lenient=True" in repr(options)
    assert not talkface.AlignOptions().lenient
    aligned = talkface.SpeechAligner(options).align_file(audio, transcript)
    assert len(aligned.mismatches) == 1
    mismatch = aligned.mismatches[0]
    assert (mismatch.first_syllable, mismatch.syllable_count, mismatch.expected_text) == (5, 0, "")
    assert 1.3 < mismatch.start_s < 1.5 and 1.8 < mismatch.end_s < 2.0
    assert any("speech the transcript lacks" in w for w in aligned.warnings)
    # A right text: nothing marked.
    right = talkface.load_transcript(CLIPS_DIR / "one_sentence.txt")
    assert talkface.SpeechAligner(options).align_file(CLIP, right).mismatches == []
    # The timeline JSON keeps them.
    again = talkface.timeline_from_json(talkface.timeline_to_json(aligned))
    assert again.mismatches == aligned.mismatches
    made = talkface.TextMismatch(start_s=1.0, end_s=1.5, first_syllable=2, syllable_count=1, expected_text="好")
    assert talkface.Timeline(mismatches=[made]).mismatches == [made]
    # The stretch's loudness, a value 0..1 every MISMATCH_LOUDNESS_STEP_S, which the mouth follows.
    assert talkface.MISMATCH_LOUDNESS_STEP_S == 0.02
    loudness = mismatch.loudness
    assert len(loudness) >= int((mismatch.end_s - mismatch.start_s) / talkface.MISMATCH_LOUDNESS_STEP_S)
    assert all(0.0 <= value <= 1.0 for value in loudness) and max(loudness) > 0.5
    assert again.mismatches[0].loudness == loudness
    made.loudness = [0.0, 1.0]
    assert made != talkface.TextMismatch(start_s=1.0, end_s=1.5, first_syllable=2, syllable_count=1, expected_text="好")
    assert talkface.TextMismatch(loudness=[0.5]).loudness == [0.5]


AUDIO_DIR = pathlib.Path(__file__).parents[2] / "tests" / "data" / "audio"


def assert_aligns_with_one_damage_warning(audio, needle):
    """A damaged copy of the clip aligns whole, with one warning naming its damage that contains needle."""
    aligned = talkface.SpeechAligner().align_file(audio, clip_transcript())
    assert len(aligned.syllables) == 11
    damage = [w for w in aligned.warnings if w.startswith(f"{audio}: the file is damaged: ")]
    assert len(damage) == 1 and needle in damage[0], aligned.warnings


def test_a_damaged_file_warns_where_its_sound_was_lost_or_refuses_saying_so_first(tmp_path):
    # The scratch costs the AAC decoder 0.64 s of packets: read as silence, the rest keeps its time.
    audio = damaged_copies.scratched_copy(AUDIO_DIR / "phone.m4a", tmp_path / "scratched.m4a", 1 / 3)
    assert_aligns_with_one_damage_warning(audio, "s of its sound could not be decoded, at 1.")
    # 0.7 s of 3.1 lost from a video's sound track: refused, the damage named before the text.
    video = damaged_copies.scratched_copy(AUDIO_DIR / "clip.mp4", tmp_path / "scratched.mp4", 1 / 3)
    with pytest.raises(talkface.AlignmentError, match=r"the file is damaged: 0\.\d+ s of its sound could not be "
                                                      r"decoded, at 0\.\d+-1\.\d+ s \(read as silence"):
        talkface.SpeechAligner().align_file(video, clip_transcript())
    # A WebM of one cluster scratched half way in: the demuxer skips the rest of the cluster, and
    # the sound up to the track's stated 3.098 s is named as lost.
    webm = damaged_copies.scratched_copy(AUDIO_DIR / "clip.webm", tmp_path / "scratched.webm", 1 / 2)
    assert_aligns_with_one_damage_warning(webm, "s of its sound could not be decoded, at 1.373-3.098 s")
    # A scratch in an Ogg page's header (its segment table, 40 bytes into the page at byte 1920): the
    # page claims more bytes than the file holds; it was called cut. Its second is named as lost.
    opus = damaged_copies.scratched_copy(AUDIO_DIR / "voice.opus", tmp_path / "scratched.opus", 1960.5 / 5869)
    with pytest.raises(talkface.AlignmentError, match=r"the file is damaged: 1 s of its sound could not be "
                                                      r"decoded, at 1\.014-2\.014 s \(read as silence"):
        talkface.SpeechAligner().align_file(opus, clip_transcript())


def test_a_video_whose_index_is_damaged_is_called_damaged_not_soundless(tmp_path):
    # 100 bytes scratched inside the index (moov, at the end of this file) hide its sound track:
    # it was called "a video without a sound track".
    video = damaged_copies.scratched_copy(AUDIO_DIR / "clip.mp4", tmp_path / "scratched.mp4", 0.95, count=100)
    with pytest.raises(talkface.ParseError, match=r"the file is damaged: its index \(the moov box, bytes 10710-12464, "
                                                  r"which says where its sound and picture lie\) breaks at byte 11834, "
                                                  r"and no sound track can be found"):
        talkface.SpeechAligner().align_file(video, clip_transcript())


def test_a_stale_wav_header_is_read_whole_and_said(tmp_path):
    # A recorder that stopped without bringing its header up to date: the data size states half.
    audio = damaged_copies.stale_wav_copy(CLIP, tmp_path / "stale.wav")
    aligned = talkface.SpeechAligner().align_file(audio, clip_transcript())
    assert aligned.duration_s == pytest.approx(DURATION_S, abs=0.01)
    assert len(aligned.syllables) == 11
    assert [w for w in aligned.warnings if w.startswith(str(audio))] == [
        f"{audio}: its header states 1.5 s of sound, the file holds 3.1 s (a header not brought up to date when "
        "the recording stopped, as a recorder that crashed or lost power leaves it); read to the end of the file"]

"""`talkface align AUDIO TRANSCRIPT`: the --json contract of SPEC "Contracts" on every test clip,
onsets against the clips' truth (and against a naive baseline), --plot, and failures that name
what was wrong and leave no file behind."""
import json
import os
import pathlib
import subprocess
import sys
import wave
import xml.etree.ElementTree as ET

import pytest

sys.path.insert(0, str(pathlib.Path(__file__).parents[1] / "common"))
import damaged_copies  # noqa: E402

CLI = os.environ["TALKFACE_CLI"]
SOURCE_DIR = pathlib.Path(os.environ.get("TALKFACE_SOURCE_DIR", pathlib.Path(__file__).parents[2]))
CLIPS_DIR = SOURCE_DIR / "tests" / "data" / "speech"
CLIPS = {"one_sentence": "wav", "two_sentences": "wav", "comma_pause": "flac", "stereo_44k": "ogg"}
AUDIO_DIR = SOURCE_DIR / "tests" / "data" / "audio"
SVG_NS = "{http://www.w3.org/2000/svg}"

# SPEC "Contracts"; `talkface align --help` documents the extra keys a syllable may carry.
CONTRACT_SYLLABLE_KEYS = ["text", "pinyin", "start", "end", "sentence"]
DOCUMENTED_EXTRA_SYLLABLE_KEYS = {"final_start", "confidence", "pause_after"}
ONSET_TOLERANCE_S = 0.100
ONSET_FLOOR = 0.80


def run(*args):
    return subprocess.run([CLI, *map(str, args)], capture_output=True, text=True, timeout=120)


def clip(name):
    return CLIPS_DIR / f"{name}.{CLIPS[name]}", CLIPS_DIR / f"{name}.txt"


def truth(name):
    return json.loads((CLIPS_DIR / f"{name}.json").read_text(encoding="utf-8"))


@pytest.fixture(scope="module")
def aligned():
    """Each clip's `align --json` document, aligned once for the module."""
    documents = {}
    for name in CLIPS:
        audio, transcript = clip(name)
        result = run("align", audio, transcript, "--json", "--quiet")
        assert result.returncode == 0, result.stderr
        documents[name] = json.loads(result.stdout)
    return documents


@pytest.mark.parametrize("name", list(CLIPS))
def test_json_has_the_contract_keys_and_ordered_times_inside_the_audio(aligned, name):
    document = aligned[name]
    expected = truth(name)
    assert list(document) == ["version", "sentences", "syllables", "duration", "warnings"]
    assert abs(document["duration"] - expected["duration"]) < 0.001
    assert document["warnings"] == []
    assert [s["text"] for s in document["sentences"]] == [s["text"] for s in expected["sentences"]]
    assert [(s["text"], s["pinyin"], s["sentence"]) for s in document["syllables"]] == [
        (s["text"], s["pinyin"], s["sentence"]) for s in expected["syllables"]]
    for sentence in document["sentences"]:
        assert list(sentence) == ["text", "start", "end"]
        assert 0 <= sentence["start"] < sentence["end"] <= expected["duration"] + 0.001
    previous_end = 0.0
    for index, syllable in enumerate(document["syllables"]):
        assert list(syllable)[:5] == CONTRACT_SYLLABLE_KEYS, index
        assert set(list(syllable)[5:]) <= DOCUMENTED_EXTRA_SYLLABLE_KEYS, index
        assert previous_end - 0.001 <= syllable["start"] < syllable["end"], index
        assert syllable["end"] <= expected["duration"] + 0.001, index
        sentence = document["sentences"][syllable["sentence"]]
        assert sentence["start"] - 0.001 <= syllable["start"] and syllable["end"] <= sentence["end"] + 0.001, index
        previous_end = syllable["end"]


def evenly_spread_onsets(syllable_count, duration_s):
    """The naive baseline: the syllables spread evenly over the whole audio, no listening at all."""
    return [duration_s * k / syllable_count for k in range(syllable_count)]


def share_within_tolerance(onsets, true_onsets):
    hits = sum(1 for onset, true_onset in zip(onsets, true_onsets) if abs(onset - true_onset) <= ONSET_TOLERANCE_S)
    return hits / len(true_onsets)


def test_onsets_are_near_the_truth_and_beat_an_even_spread(aligned):
    found, baseline, true_onsets = [], [], []
    for name, document in aligned.items():
        found += [s["start"] for s in document["syllables"]]
        baseline += evenly_spread_onsets(len(document["syllables"]), truth(name)["duration"])
        true_onsets += [s["start"] for s in truth(name)["syllables"]]
    share = share_within_tolerance(found, true_onsets)
    baseline_share = share_within_tolerance(baseline, true_onsets)
    assert baseline_share < ONSET_FLOOR, "the floor no longer tells the aligner from the naive baseline"
    assert share >= ONSET_FLOOR, f"{share:.0%} of {len(true_onsets)} onsets within 100 ms"
    assert share > baseline_share


def test_output_file_equals_stdout_and_plot_is_an_svg(tmp_path, aligned):
    audio, transcript = clip("two_sentences")
    out, plot = tmp_path / "aligned.json", tmp_path / "aligned.svg"
    result = run("align", audio, transcript, "--json", "--quiet", "-o", out, "--plot", plot)
    assert result.returncode == 0, result.stderr
    assert result.stdout == ""
    assert json.loads(out.read_text(encoding="utf-8")) == aligned["two_sentences"]
    root = ET.parse(plot).getroot()
    assert root.tag == SVG_NS + "svg"
    assert len(list(root.iter())) > 10


def test_table_form_lists_every_sentence():
    audio, transcript = clip("two_sentences")
    result = run("align", audio, transcript, "--quiet")
    assert result.returncode == 0, result.stderr
    lines = result.stdout.splitlines()
    assert [line.split()[:2] for line in lines if line.startswith("sentence")] == [["sentence", "1"],
                                                                                 ["sentence", "2"]]
    # The column heads come first and name every column of the syllable rows.
    assert lines[0].split() == ["text", "pinyin", "start", "final", "end", "confidence"]
    syllable_rows = [line.split() for line in lines[1:] if not line.startswith("sentence")]
    assert syllable_rows and all(len(row) == len(lines[0].split()) for row in syllable_rows)


def assert_nothing_written(tmp_path, *inputs):
    assert sorted(p.name for p in tmp_path.iterdir()) == sorted(p.name for p in inputs)


def test_missing_audio_names_it_and_writes_nothing(tmp_path):
    _, transcript = clip("one_sentence")
    missing = tmp_path / "no_such_speech.wav"
    result = run("align", missing, transcript, "--json", "-o", tmp_path / "out.json", "--plot", tmp_path / "p.svg")
    assert result.returncode in (1, 2)  # 2 when the ExistingFile validator catches it first
    assert str(missing) in result.stderr
    assert result.stdout == ""
    assert_nothing_written(tmp_path)


def test_unreadable_audio_exits_1_naming_it(tmp_path):
    _, transcript = clip("one_sentence")
    not_audio = tmp_path / "notes.wav"
    not_audio.write_text("not a sound file\n")
    result = run("align", not_audio, transcript, "--json", "-o", tmp_path / "out.json")
    assert result.returncode == 1
    assert result.stderr.startswith(f"talkface: error: {not_audio}")
    assert_nothing_written(tmp_path, not_audio)


@pytest.mark.parametrize("command", ["align", "keyframes"])
@pytest.mark.parametrize("text,said", [
    ("", "no text to align"),
    ("。。。！！", "no text to align"),
    ("🙂🙂", "no text to align"),  # emoji are unsaid and unwarned, as punctuation is (session 31)
])
def test_a_transcript_with_nothing_to_align_is_named_with_what_was_skipped(tmp_path, command, text, said):
    audio, _ = clip("one_sentence")
    transcript = tmp_path / "line.txt"
    transcript.write_text(text, encoding="utf-8")
    result = run(command, audio, transcript, "-o", tmp_path / "out")
    assert result.returncode == 1
    assert result.stderr.startswith(f"talkface: error: {transcript}: no ")
    assert said in result.stderr
    assert_nothing_written(tmp_path, transcript)


@pytest.mark.parametrize("clip_name,text,named", [
    ("one_sentence", "我很好。", '"我很好。"'),                           # the wrong text: the sentence is named
    ("two_sentences", "今天下午有雨。我们明天再去吧。他们都很好。", "sentence"),  # an extra sentence
])
def test_mismatched_transcript_exits_1_naming_the_sentence_and_writes_nothing(tmp_path, clip_name, text, named):
    audio, _ = clip(clip_name)
    transcript = tmp_path / "wrong.txt"
    transcript.write_text(text, encoding="utf-8")
    result = run("align", audio, transcript, "--json", "-o", tmp_path / "out.json", "--plot", tmp_path / "p.svg")
    assert result.returncode == 1
    assert result.stderr.startswith(f"talkface: error: {audio}: ")
    assert named in result.stderr
    assert result.stdout == ""
    assert_nothing_written(tmp_path, transcript)


def test_a_missing_file_is_a_usage_error_said_as_every_error_is(tmp_path):
    # STYLE.md section 8: every error reads "talkface: error: ...", the option's own check's too.
    _, transcript = clip("one_sentence")
    missing = tmp_path / "missing.wav"
    result = run("align", missing, transcript, "--json")
    assert result.returncode == 2
    assert result.stderr.startswith("talkface: error: ")
    assert str(missing) in result.stderr.splitlines()[0]
    assert result.stdout == ""


def test_option_out_of_range_is_a_usage_error():
    audio, transcript = clip("one_sentence")
    result = run("align", audio, transcript, "--c1", "0.2")
    assert result.returncode == 2
    assert "--c1" in result.stderr


@pytest.mark.parametrize("mode,code", [("refuse", 1), ("warn", 0), ("off", 0)])
def test_check_option_refuses_warns_or_skips(tmp_path, mode, code):
    audio, _ = clip("one_sentence")
    transcript = tmp_path / "wrong.txt"
    transcript.write_text("我昨天在超市买了苹果和。", encoding="utf-8")
    result = run("align", audio, transcript, "--json", "--quiet", "--check", mode)
    assert result.returncode == code, result.stderr
    if mode == "refuse":
        assert "is it another sentence, or are two sentences swapped?" in result.stderr
        return
    warnings = json.loads(result.stdout)["warnings"]
    found = [w for w in warnings if w.startswith("the transcript may not match the audio")]
    assert len(found) == (1 if mode == "warn" else 0)


def test_check_option_other_values_are_a_usage_error():
    audio, transcript = clip("one_sentence")
    result = run("align", audio, transcript, "--check", "maybe")
    assert result.returncode == 2
    assert "--check" in result.stderr


@pytest.mark.parametrize("name", ["sox_22050.mp3", "phone.m4a", "clip.webm"])
def test_recordings_as_people_have_them_align(name):
    audio = SOURCE_DIR / "tests" / "data" / "audio" / name
    _, transcript = clip("one_sentence")
    result = run("align", audio, transcript, "--json", "--quiet")
    assert result.returncode == 0, result.stderr
    assert len(json.loads(result.stdout)["syllables"]) == 11


def test_a_video_without_sound_exits_1_saying_so():
    audio = SOURCE_DIR / "tests" / "data" / "audio" / "no_sound.mp4"
    _, transcript = clip("one_sentence")
    result = run("align", audio, transcript, "--quiet")
    assert result.returncode == 1
    assert result.stderr.startswith(f"talkface: error: {audio}: a video without a sound track")


def test_a_video_whose_index_is_damaged_is_called_damaged_not_soundless(tmp_path):
    # 100 bytes scratched inside the index (moov, at the end of this file) hide its sound track:
    # it was called "a video without a sound track".
    audio = damaged_copies.scratched_copy(AUDIO_DIR / "clip.mp4", tmp_path / "scratched.mp4", 0.95, count=100)
    _, transcript = clip("one_sentence")
    result = run("align", audio, transcript, "--quiet")
    assert result.returncode == 1
    assert result.stderr.startswith(
        f"talkface: error: {audio}: the file is damaged: its index (the moov box, bytes 10710-12464, which says "
        "where its sound and picture lie) breaks at byte 11834, and no sound track can be found in what is left "
        "of it"), result.stderr


def test_lenient_aligns_a_text_a_word_off_and_reports_the_stretch(tmp_path):
    audio = CLIPS_DIR / "lenient_espeak.flac"  # says 公园, which this transcript lacks
    transcript = tmp_path / "lacks.txt"
    transcript.write_text("小朋友们在里放风筝。\n", encoding="utf-8")
    result = run("align", audio, transcript, "--json", "--quiet", "--lenient")
    assert result.returncode == 0, result.stderr
    document = json.loads(result.stdout)
    assert [(m["first_syllable"], m["syllable_count"], m["expected"]) for m in document["mismatches"]] == [(5, 0, "")]
    assert document["mismatches"][0]["start"] < document["mismatches"][0]["end"]
    assert "mismatches" not in json.loads(run("align", audio, transcript, "--json", "--quiet", "--check", "off").stdout)
    # The commands that align on their way to an animation take it too, and say what they found.
    keyframes = run("keyframes", audio, transcript, "--lenient", "-o", tmp_path / "k.json")
    assert keyframes.returncode == 0, keyframes.stderr
    # Said once (the timeline's warning), not twice.
    assert keyframes.stderr.count("speech the transcript lacks") == 1, keyframes.stderr
    # The stretch's loudness is in the JSON; over it the mouth opens and closes with the voice.
    loudness = document["mismatches"][0]["loudness"]
    assert all(0 <= value <= 1 for value in loudness) and max(loudness) > 0.5


def test_lenient_with_a_timing_file(tmp_path):
    audio = CLIPS_DIR / "lenient_espeak.flac"  # says 公园, which this transcript and its cue lack
    transcript = tmp_path / "lacks.txt"
    transcript.write_text("小朋友们在里放风筝。\n", encoding="utf-8")
    cues = tmp_path / "cues.srt"
    cues.write_text("1\n00:00:00,200 --> 00:00:03,100\n小朋友们在里放风筝。\n", encoding="utf-8")
    # Subtitle cues pin the aligner, which --lenient makes lenient.
    strict = run("keyframes", audio, transcript, "--timing", cues, "-o", tmp_path / "strict.json")
    assert "speech the transcript lacks" not in strict.stderr
    pinned = run("keyframes", audio, transcript, "--timing", cues, "--lenient", "-o", tmp_path / "k.json")
    assert pinned.returncode == 0, pinned.stderr
    assert pinned.stderr.count("speech the transcript lacks") == 1, pinned.stderr
    # A timing that times every syllable aligns nothing: --lenient there is a usage error, named.
    words = tmp_path / "words.json"
    words.write_text('[{"text": "小朋友们在里放风筝", "start": 0.3, "end": 2.9}]', encoding="utf-8")
    out = tmp_path / "words_k.json"
    result = run("keyframes", audio, transcript, "--timing", words, "--lenient", "-o", out)
    assert result.returncode == 2
    assert f"--lenient: {words} (json) times every syllable itself" in result.stderr, result.stderr
    assert not out.exists()


def test_a_damaged_file_aligns_with_a_warning_naming_where_its_sound_was_lost(tmp_path):
    # The scratch costs the AAC decoder 0.64 s of packets: read as silence, the rest keeps its time.
    audio = damaged_copies.scratched_copy(AUDIO_DIR / "phone.m4a", tmp_path / "scratched.m4a", 1 / 3)
    _, transcript = clip("one_sentence")
    result = run("align", audio, transcript, "--json", "--quiet")
    assert result.returncode == 0, result.stderr
    document = json.loads(result.stdout)
    assert len(document["syllables"]) == 11
    damage = [w for w in document["warnings"] if w.startswith(f"{audio}: the file is damaged: ")]
    assert len(damage) == 1 and "s of its sound could not be decoded, at 1." in damage[0], document["warnings"]
    # A WebM of one cluster scratched half way in: the demuxer skips the rest of the cluster, and
    # the sound up to the track's stated 3.098 s is named as lost (it aligned on with silence,
    # nothing said).
    webm = damaged_copies.scratched_copy(AUDIO_DIR / "clip.webm", tmp_path / "scratched.webm", 1 / 2)
    result = run("align", webm, transcript, "--json", "--quiet")
    assert result.returncode == 0, result.stderr
    damage = [w for w in json.loads(result.stdout)["warnings"] if w.startswith(f"{webm}: the file is damaged: ")]
    assert len(damage) == 1 and "s of its sound could not be decoded, at 1.373-3.098 s" in damage[0], result.stdout


def test_a_damaged_file_refused_names_the_damage_before_the_text(tmp_path):
    # 0.7 s of the clip's 3.1 s lost: the refusal says so first, not that the text is wrong.
    audio = damaged_copies.scratched_copy(AUDIO_DIR / "clip.mp4", tmp_path / "scratched.mp4", 1 / 3)
    _, transcript = clip("one_sentence")
    result = run("align", audio, transcript, "--json", "-o", tmp_path / "out.json")
    assert result.returncode == 1
    assert result.stderr.startswith(f"talkface: error: {audio}: the file is damaged: "), result.stderr
    assert "s of its sound could not be decoded, at 0." in result.stderr
    assert "--lenient" in result.stderr and "The aligner found: sentence 1" in result.stderr
    assert_nothing_written(tmp_path, audio)
    # A scratch in an Ogg page's header (its segment table, 40 bytes into the page at byte 1920):
    # the page claims more bytes than the file holds; it was called cut ("truncated: the Ogg
    # stream breaks off inside a page"). The page's second is named as lost.
    opus = damaged_copies.scratched_copy(AUDIO_DIR / "voice.opus", tmp_path / "scratched.opus", 1960.5 / 5869)
    result = run("align", opus, transcript, "--json", "-o", tmp_path / "out.json")
    assert result.returncode == 1
    assert result.stderr.startswith(f"talkface: error: {opus}: the file is damaged: 1 s of its sound could not be "
                                    "decoded, at 1.014-2.014 s"), result.stderr


def test_a_word_silenced_at_a_sentences_end_is_named(tmp_path):
    # 吧, the last syllable of two_sentences.wav, put to exact zeros over its true span (the text
    # kept): no syllable of its sentence follows the zeros, and the rule for zeros inside a sentence
    # passed it by; the aligner lays 吧 on the zeros.
    audio, transcript = clip("two_sentences")
    last = truth("two_sentences")["syllables"][-1]
    with wave.open(str(audio), "rb") as source:
        params = source.getparams()
        frames = bytearray(source.readframes(params.nframes))
    width = params.sampwidth * params.nchannels
    first, end = (int(last[key] * params.framerate) for key in ("start", "end"))
    frames[first * width : end * width] = bytes((end - first) * width)
    edited = tmp_path / "silenced.wav"
    with wave.open(str(edited), "wb") as out:
        out.setparams(params)
        out.writeframes(bytes(frames))
    result = run("align", edited, transcript, "--json", "--quiet")
    assert result.returncode == 0, result.stderr
    silenced = [w for w in json.loads(result.stdout)["warnings"] if "is digital silence (exact zeros)" in w]
    assert len(silenced) == 1, result.stdout
    assert silenced[0].startswith(f"{edited}: sentence 2: 4") and '"吧" 0 ms' in silenced[0], silenced
    assert 'is a word of "去吧" silenced there by an editor, its text kept?' in silenced[0], silenced


def test_a_refusal_names_a_words_digital_silence_inside_its_sentence(tmp_path):
    # 們在公園裡 of one_sentence.wav put to exact zeros over their true spans (the text kept): the
    # text is refused as not the speech, and the refusal said nothing of the silence.
    audio, transcript = clip("one_sentence")
    syllables = truth("one_sentence")["syllables"]
    with wave.open(str(audio), "rb") as source:
        params = source.getparams()
        frames = bytearray(source.readframes(params.nframes))
    width = params.sampwidth * params.nchannels
    first, end = int(syllables[3]["start"] * params.framerate), int(syllables[7]["end"] * params.framerate)
    frames[first * width : end * width] = bytes((end - first) * width)
    edited = tmp_path / "silenced.wav"
    with wave.open(str(edited), "wb") as out:
        out.setparams(params)
        out.writeframes(bytes(frames))
    result = run("align", edited, transcript, "--quiet")
    assert result.returncode == 1, result.stderr
    assert "(the recording: 0.96-1.94 s, inside sentence 1, is digital silence (exact zeros) where its text marks no pause" in result.stderr


def test_a_stale_wav_header_is_read_whole_and_said(tmp_path):
    # A recorder that stopped without bringing its header up to date: the data size states half.
    audio = damaged_copies.stale_wav_copy(CLIPS_DIR / "one_sentence.wav", tmp_path / "stale.wav")
    _, transcript = clip("one_sentence")
    result = run("align", audio, transcript, "--json", "--quiet")
    assert result.returncode == 0, result.stderr
    document = json.loads(result.stdout)
    assert len(document["syllables"]) == 11
    assert abs(document["duration"] - truth("one_sentence")["duration"]) < 0.001
    assert [w for w in document["warnings"] if w.startswith(str(audio))] == [
        f"{audio}: its header states 1.5 s of sound, the file holds 3.1 s (a header not brought up to date when "
        "the recording stopped, as a recorder that crashed or lost power leaves it); read to the end of the file"]
    # The table form says it on stderr.
    table = run("align", audio, transcript, "--quiet")
    assert table.returncode == 0, table.stderr
    assert f"talkface: warning: {audio}: its header states 1.5 s" in table.stderr


@pytest.mark.parametrize("command", ["align", "keyframes", "export", "animate", "video", "syllables"])
def test_every_command_that_reads_a_transcript_can_read_latin_never_as_pinyin(command):
    # TranscriptOptions::read_pinyin, as tf_transcript_options_set_read_pinyin and read_pinyin=False.
    assert "--no-pinyin-input" in run(command, "--help").stdout


def test_no_pinyin_input_aligns_latin_letters_as_letters_or_words(tmp_path):
    audio, _ = clip("one_sentence")
    transcript = tmp_path / "pinyin.txt"
    transcript.write_text("ni3 hao3", encoding="utf-8")
    as_pinyin = run("align", audio, transcript, "--check", "off", "--json", "--quiet")
    as_latin = run("align", audio, transcript, "--check", "off", "--json", "--quiet", "--no-pinyin-input")
    assert as_pinyin.returncode == 0 and as_latin.returncode == 0, as_pinyin.stderr + as_latin.stderr
    assert [s["pinyin"] for s in json.loads(as_pinyin.stdout)["syllables"]] == ["ni3", "hao3"]
    # "ni" is a word no table reads (generic speech), 3 the number 三.
    assert [s["pinyin"] for s in json.loads(as_latin.stdout)["syllables"]][:2] == ["de5", "san1"]

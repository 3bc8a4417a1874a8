"""`talkface export AUDIO TRANSCRIPT -o FILE`: each format from its suffix, each checked by the
program that reads it (praat reads the TextGrid and counts its intervals, ffprobe reads the
subtitles), Rhubarb's cues spanning the audio, the face as Lottie, `--timing` instead of aligning, and refusals that
name the file and leave nothing behind."""
import json
import os
import pathlib
import shutil
import subprocess

import pytest

CLI = os.environ["TALKFACE_CLI"]
SOURCE_DIR = pathlib.Path(os.environ.get("TALKFACE_SOURCE_DIR", pathlib.Path(__file__).parents[2]))
CLIPS_DIR = SOURCE_DIR / "tests" / "data" / "speech"
AUDIO = CLIPS_DIR / "two_sentences.wav"
TRANSCRIPT = CLIPS_DIR / "two_sentences.txt"
DURATION_S = 4.451  # the audio's length as talkface reads it


def run(*args):
    return subprocess.run([CLI, *map(str, args)], capture_output=True, text=True, timeout=120)


def export(tmp_path, name, *args):
    out = tmp_path / name
    result = run("export", AUDIO, TRANSCRIPT, "-o", out, "--quiet", *args)
    assert result.returncode == 0, result.stderr
    assert result.stdout == ""
    return out


@pytest.fixture(scope="module")
def aligned():
    result = run("align", AUDIO, TRANSCRIPT, "--json", "--quiet")
    assert result.returncode == 0, result.stderr
    return json.loads(result.stdout)


def test_rhubarb_tsv_spans_the_audio_with_rubarb_letters(tmp_path):
    lines = export(tmp_path, "cues.tsv").read_text().splitlines()
    times = [float(line.split("\t")[0]) for line in lines]
    letters = [line.split("\t")[1] for line in lines]
    assert lines[0] == "0.00\tX" and lines[-1] == "4.45\tX"
    assert times == sorted(times) and len(set(times)) == len(times)
    assert set(letters) <= set("ABCDEFGHX")
    assert {"A", "D", "X"} <= set(letters)  # 们 and 明 close the lips; 下 and 吧 open wide
    assert all(a != b for a, b in zip(letters[:-2], letters[1:-1]))  # neighbours joined, as Rhubarb does


def test_rhubarb_json_and_xml_carry_the_same_cues(tmp_path):
    tsv = export(tmp_path, "cues.tsv").read_text().splitlines()
    document = json.loads(export(tmp_path, "cues.json", "--format", "rhubarb-json").read_text())
    assert document["metadata"] == {"soundFile": str(AUDIO.resolve()), "duration": 4.45}
    assert [f"{c['start']:.2f}\t{c['value']}" for c in document["mouthCues"]] == tsv[:-1]
    assert document["mouthCues"][-1]["end"] == 4.45
    xml = export(tmp_path, "cues.xml").read_text()
    assert xml.startswith('<?xml version="1.0" encoding="utf-8"?>\n<rhubarbResult>\n  <metadata>\n')
    assert xml.count("<mouthCue ") == len(document["mouthCues"])


def test_moho_switch_data(tmp_path):
    lines = export(tmp_path, "mouth.dat", "--fps", 24).read_text().splitlines()
    assert lines[0] == "MohoSwitch1" and lines[1] == "1 rest"
    assert lines[-1] == f"{1 + int(24 * 4.45)} rest"
    frames = [int(line.split()[0]) for line in lines[1:]]
    assert frames == sorted(frames) and len(set(frames)) == len(frames)
    assert {line.split()[1] for line in lines[1:]} <= {"MBP", "etc", "E", "AI", "O", "U", "FV", "L", "rest"}


def test_live2d_motion_has_its_curves_and_counts(tmp_path):
    motion = json.loads(export(tmp_path, "talk.motion3.json", "--seed", 3).read_text())
    ids = [curve["Id"] for curve in motion["Curves"]]
    assert ids == ["ParamMouthOpenY", "ParamMouthForm", "ParamEyeLOpen", "ParamEyeROpen", "ParamBrowLY",
                   "ParamBrowRY", "ParamAngleX", "ParamAngleY", "ParamAngleZ"]
    meta = motion["Meta"]
    assert meta["CurveCount"] == 9 and abs(meta["Duration"] - DURATION_S) < 1e-3
    points = segments = 0
    for curve in motion["Curves"]:
        values = curve["Segments"]
        assert values[0] == 0  # every curve starts at 0 s
        points += 1 + (len(values) - 2) // 3
        segments += (len(values) - 2) // 3
        assert values[-2] == meta["Duration"]  # and ends at the audio's end
    assert (meta["TotalPointCount"], meta["TotalSegmentCount"]) == (points, segments)
    eyes = motion["Curves"][2]["Segments"]
    assert min(eyes[1::3]) < 0.5  # a blink in 4.45 s at the thesis's rate (seed 3)


@pytest.mark.skipif(shutil.which("praat") is None, reason="praat is not installed")
def test_praat_reads_the_textgrid_and_counts_its_intervals(tmp_path, aligned):
    grid = export(tmp_path, "speech.TextGrid")
    script = tmp_path / "count.praat"
    script.write_text(f'grid = Read from file: "{grid}"\n'
                      'for tier to 2\n    n = Get number of intervals: tier\n    appendInfoLine: n\nendfor\n'
                      'end = Get end time\nappendInfoLine: end\n'
                      'label$ = Get label of interval: 2, 2\nappendInfoLine: label$\n', encoding="utf-8")
    result = subprocess.run(["praat", "--run", str(script)], capture_output=True, text=True, timeout=60)
    assert result.returncode == 0, result.stderr
    sentence_intervals, syllable_intervals, end, label = result.stdout.split()
    syllables = aligned["syllables"]
    gaps = sum(1 for a, b in zip(syllables, syllables[1:]) if b["start"] > a["end"])
    gaps += (syllables[0]["start"] > 0) + (syllables[-1]["end"] < aligned["duration"])
    assert int(syllable_intervals) == len(syllables) + gaps
    assert int(sentence_intervals) == 5  # silence, sentence, pause, sentence, silence
    assert abs(float(end) - aligned["duration"]) < 1e-9
    assert label == syllables[0]["pinyin"]


@pytest.mark.skipif(shutil.which("ffprobe") is None, reason="ffprobe is not installed")
@pytest.mark.parametrize("name", ["speech.srt", "speech.vtt"])
def test_ffprobe_reads_the_subtitles_a_cue_per_sentence(tmp_path, aligned, name):
    subtitles = export(tmp_path, name)
    result = subprocess.run(["ffprobe", "-v", "error", "-show_entries", "packet=pts_time,duration_time", "-of", "json",
                             str(subtitles)], capture_output=True, text=True, timeout=60)
    assert result.returncode == 0, result.stderr
    packets = json.loads(result.stdout)["packets"]
    assert len(packets) == len(aligned["sentences"])
    for packet, sentence in zip(packets, aligned["sentences"]):
        assert abs(float(packet["pts_time"]) - sentence["start"]) < 0.0015
        assert abs(float(packet["pts_time"]) + float(packet["duration_time"]) - sentence["end"]) < 0.0015


def test_vtt_marks_each_later_syllable(tmp_path):
    cues = export(tmp_path, "speech.vtt").read_text(encoding="utf-8").split("\n\n")
    assert cues[0] == "WEBVTT"
    assert cues[1].splitlines()[2].count("<00:00:") == 5  # 今天下午有雨: a timestamp before 天 下 午 有 雨


def test_timing_file_instead_of_aligning(tmp_path, aligned):
    words = [{"text": s["text"], "start": s["start"], "end": s["end"]} for s in aligned["syllables"]]
    timing = tmp_path / "words.json"
    timing.write_text(json.dumps(words, ensure_ascii=False), encoding="utf-8")
    through_timing = export(tmp_path, "timed.srt", "--timing", timing).read_text()
    assert through_timing == export(tmp_path, "aligned.srt").read_text()
    grid = export(tmp_path, "speech.TextGrid")
    again = export(tmp_path, "again.TextGrid", "--timing", grid)
    assert again.read_text() == grid.read_text()


def test_subtitle_cues_pin_the_aligner(tmp_path):
    cues = tmp_path / "cues.srt"
    # The second sentence is spoken 2.57-4.15 s; its cue says 2.80-4.00, the first cue is right.
    cues.write_text("1\n00:00:00,290 --> 00:00:01,690\n今天下午有雨。\n\n"
                    "2\n00:00:02,800 --> 00:00:04,000\n我们明天再去吧。\n", encoding="utf-8")
    pinned = export(tmp_path, "pinned.srt", "--timing", cues).read_text(encoding="utf-8").split("\n\n")
    aligned = export(tmp_path, "aligned.srt").read_text(encoding="utf-8").split("\n\n")[0].splitlines()
    # Pinned to the right cue the sentence is the aligner's; its end within a frame (10 ms), since the
    # search stops at the cue's end where the aligner's last syllable keeps its fade's last frame.
    first = pinned[0].splitlines()
    assert first[0::2] == aligned[0::2] and first[1][:12] == aligned[1][:12]
    seconds = [sum(float(part) * scale for part, scale in zip(cue[-12:].replace(",", ":").split(":"), (3600, 60, 1, 0.001)))
               for cue in (first[1], aligned[1])]
    assert abs(seconds[0] - seconds[1]) <= 0.0105
    times = pinned[1].splitlines()[1]
    assert "00:00:02,800" <= times[:12] and times[-12:] <= "00:00:04,000"
    # Searched only inside its cue, the sentence keeps the syllables the cue does not cut where
    # espeak-ng put them (天 再 去, within 50 ms), instead of squeezing them all in proportion.
    grid = export(tmp_path, "pinned.TextGrid", "--timing", cues).read_text(encoding="utf-8")
    tier = grid[grid.index('name = "syllables"'):]
    starts = [float(line.split("=")[1]) for line in tier.splitlines() if line.strip().startswith("xmin")][1:]
    labels = [line.split("=")[1].strip().strip('"') for line in tier.splitlines() if line.strip().startswith("text")]
    spoken = [start for start, label in zip(starts, labels) if label]
    truth = json.loads((CLIPS_DIR / "two_sentences.json").read_text(encoding="utf-8"))["syllables"]
    for k in (9, 10, 11):
        assert abs(spoken[k] - truth[k]["start"]) < 0.05, (k, spoken[k])
    result = run("keyframes", AUDIO, TRANSCRIPT, "--timing", cues, "-o", "-")
    assert result.returncode == 0, result.stderr
    assert json.loads(result.stdout)["mouth"] != json.loads(run("keyframes", AUDIO, TRANSCRIPT, "-o", "-").stdout)["mouth"]


def test_a_timing_that_parts_from_the_transcript_names_the_place_and_writes_nothing(tmp_path):
    timing = tmp_path / "words.json"
    timing.write_text('[{"text": "今天", "start": 0.3, "end": 0.8},\n{"text": "上午", "start": 0.8, "end": 1.2}]',
                      encoding="utf-8")
    out = tmp_path / "cues.tsv"
    result = run("export", AUDIO, TRANSCRIPT, "-o", out, "--timing", timing)
    assert result.returncode == 1
    assert result.stderr.startswith(f'talkface: error: {timing}:2: "上午": "上" parts from the transcript at sentence 1')
    assert not out.exists()
    late = tmp_path / "late.json"
    late.write_text('[{"text": "今天下午有雨我们明天再去吧", "start": 0.3, "end": 9.0}]', encoding="utf-8")
    result = run("export", AUDIO, TRANSCRIPT, "-o", out, "--timing", late)
    assert result.returncode == 1 and "past the end of the audio (4.451 s)" in result.stderr
    assert sorted(p.name for p in tmp_path.iterdir()) == ["late.json", "words.json"]


def test_a_utf16_timing_of_an_odd_number_of_bytes_is_refused_naming_it(tmp_path, aligned):
    # Saved as Notepad's "Unicode" (UTF-16 with its byte order mark) it reads; a byte more is half a
    # 16-bit unit, refused with the file's name instead of dropped.
    words = [{"text": s["text"], "start": s["start"], "end": s["end"]} for s in aligned["syllables"]]
    timing = tmp_path / "words.json"
    timing.write_bytes(json.dumps(words, ensure_ascii=False).encode("utf-16"))
    out = tmp_path / "cues.tsv"
    assert run("export", AUDIO, TRANSCRIPT, "-o", out, "--timing", timing, "--quiet").returncode == 0
    out.unlink()
    timing.write_bytes(timing.read_bytes() + b"\n")
    result = run("export", AUDIO, TRANSCRIPT, "-o", out, "--timing", timing)
    assert result.returncode == 1
    assert result.stderr.startswith(f"talkface: error: {timing}: not UTF-16: an odd number of bytes")
    assert sorted(p.name for p in tmp_path.iterdir()) == ["words.json"]


def test_lottie_is_the_face_itself_over_the_whole_speech(tmp_path):
    lottie = json.loads(export(tmp_path, "face.json", "--format", "lottie", "--fps", 20, "--seed", 3).read_text())
    assert (lottie["fr"], lottie["ip"]) == (20, 0)
    assert lottie["op"] == int(DURATION_S * 20) + 1  # frame i at i / fps, to the audio's end
    names = [layer["nm"] for layer in lottie["layers"]]
    assert names[-1] == "background" and "hair" in names and "clothes" in names
    masked = sorted(layer["nm"] for layer in lottie["layers"] if layer.get("hasMask"))
    assert masked == ["face eyeball-left", "face eyeball-right", "face mouth-below-upper-teeth",
                      "face mouth-inside-short-of-corners"]
    # --look paints the face: outlined draws strokes, flat none but its upper lids' bands; a timing
    # format refuses it.
    def strokes(document, leaving_out=()):
        groups = [g for layer in document["layers"] for g in layer["shapes"] if g["nm"] not in leaving_out]
        return json.dumps(groups).count('"ty": "st"') + json.dumps(groups).count('"ty": "gs"')
    flat = json.loads(export(tmp_path, "flat.json", "--format", "lottie", "--fps", 20, "--seed", 3,
                             "--look", "flat").read_text())
    assert strokes(lottie) > 10 and strokes(flat, leaving_out=("eye-left-lid", "eye-right-lid")) == 0
    assert strokes(flat) == 2
    assert {"hair", "clothes", "background"} <= {layer["nm"] for layer in flat["layers"]}
    refused = run("export", AUDIO, TRANSCRIPT, "-o", tmp_path / "cues.tsv", "--look", "flat")
    assert refused.returncode == 2 and "--look: only the lottie export draws the face" in refused.stderr
    assert not (tmp_path / "cues.tsv").exists()
    # --tolerance: fewer key frames, a smaller document; the drawing options refuse a timing format too.
    coarse = export(tmp_path, "coarse.json", "--format", "lottie", "--fps", 20, "--seed", 3, "--tolerance", 3)
    assert coarse.stat().st_size < 0.9 * (tmp_path / "face.json").stat().st_size
    for option in (["--stroke-width", "0.05"], ["--no-clothes"], ["--tolerance", "3"]):
        refused = run("export", AUDIO, TRANSCRIPT, "-o", tmp_path / "cues.tsv", *option)
        assert refused.returncode == 2 and f"{option[0]}: only the lottie export" in refused.stderr, refused.stderr
    # --face takes a face file, as animate's does.
    missing = run("export", AUDIO, TRANSCRIPT, "-o", "-", "--format", "lottie", "--quiet", "--face",
                  tmp_path / "missing.xml")
    assert missing.returncode == 2 and "missing.xml" in missing.stderr


def test_format_errors(tmp_path):
    result = run("export", AUDIO, TRANSCRIPT, "-o", tmp_path / "cues.json")
    assert result.returncode == 1 and "name the format" in result.stderr
    result = run("export", AUDIO, TRANSCRIPT, "-o", tmp_path / "cues.xyz")
    assert result.returncode == 1 and 'no export format for suffix ".xyz"' in result.stderr
    assert run("export", AUDIO, TRANSCRIPT, "-o", "-").returncode == 2
    assert run("export", AUDIO, TRANSCRIPT, "-o", "x.tsv", "--format", "flash").returncode == 2
    assert list(tmp_path.iterdir()) == []
    result = run("export", AUDIO, TRANSCRIPT, "-o", "-", "--format", "rhubarb-tsv", "--quiet")
    assert result.returncode == 0 and result.stdout.startswith("0.00\tX\n")

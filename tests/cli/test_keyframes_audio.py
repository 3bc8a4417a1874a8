"""`talkface keyframes AUDIO TRANSCRIPT`: the key frames of a real clip (aligned, then animated) keep
the keyframes JSON contract, are the same bytes for the same seed, and a bad input writes nothing."""
import json
import os
import pathlib
import subprocess

CLI = os.environ["TALKFACE_CLI"]
SOURCE_DIR = pathlib.Path(os.environ.get("TALKFACE_SOURCE_DIR", pathlib.Path(__file__).parents[2]))
CLIPS_DIR = SOURCE_DIR / "tests" / "data" / "speech"
AUDIO = CLIPS_DIR / "two_sentences.wav"
TRANSCRIPT = CLIPS_DIR / "two_sentences.txt"
SHAPES = ["m", "f", "h'", "h", "r", "z", "a", "i", "u", "e", "o", "n"]
KINDS = ["blink", "brows", "tilt", "turn", "nod"]


def run(*args):
    return subprocess.run([CLI, *map(str, args)], capture_output=True, text=True, timeout=120)


def keyframes(*args):
    result = run("keyframes", AUDIO, TRANSCRIPT, *args)
    assert result.returncode == 0, result.stderr
    return result


def test_audio_form_writes_the_keyframes_contract(tmp_path):
    truth = json.loads((CLIPS_DIR / "two_sentences.json").read_text(encoding="utf-8"))
    out = tmp_path / "keys.json"
    result = keyframes("--seed", 7, "-o", out)
    assert result.stdout == ""
    document = json.loads(out.read_text(encoding="utf-8"))
    assert list(document) == ["fps", "duration", "mouth", "events"]
    assert document["fps"] == 25 and abs(document["duration"] - truth["duration"]) < 0.05
    assert document["mouth"][0] == {"time": 0, "shape": "m", "syllable": None}
    for item in document["mouth"]:
        assert list(item) == ["time", "shape", "syllable"]
        assert item["shape"] in SHAPES
        assert 0 <= item["time"] <= truth["duration"] + 0.05
    times = [item["time"] for item in document["mouth"]]
    assert times == sorted(times) and len(set(times)) == len(times)
    # Every syllable of the transcript gets its key frames, in transcript order.
    syllables = [item["syllable"] for item in document["mouth"] if item["syllable"] is not None]
    assert syllables == sorted(syllables)
    assert set(syllables) == set(range(len(truth["syllables"])))
    for event in document["events"]:
        assert list(event) == ["kind", "start", "end", "amount"]
        assert event["kind"] in KINDS
        assert event["start"] <= event["end"]


def test_same_seed_same_bytes_other_seeds_other_events(tmp_path):
    out = tmp_path / "keys.json"
    keyframes("--seed", 7, "-o", out)
    again = keyframes("--seed", 7, "-o", "-").stdout
    assert again == out.read_text(encoding="utf-8")
    others = [json.loads(keyframes("--seed", seed, "-o", "-").stdout) for seed in (8, 9)]
    assert all(other["mouth"] == json.loads(again)["mouth"] for other in others)
    assert any(other["events"] != json.loads(again)["events"] for other in others)


def test_mismatched_transcript_exits_1_and_writes_nothing(tmp_path):
    transcript = tmp_path / "wrong.txt"
    transcript.write_text("今天下午有雨。我们明天再去吧。他们都很好。", encoding="utf-8")
    out = tmp_path / "keys.json"
    result = run("keyframes", AUDIO, transcript, "-o", out)
    assert result.returncode == 1
    assert result.stderr.startswith(f"talkface: error: {AUDIO}: ")
    assert not out.exists()
    assert sorted(p.name for p in tmp_path.iterdir()) == ["wrong.txt"]

"""`talkface keyframes --timeline`: the keyframes JSON contract, determinism, --tsv, the caller's
events (add / replace), and errors that name the event or the place in the file."""
import json
import os
import subprocess

import pytest

CLI = os.environ["TALKFACE_CLI"]

# 媽媽好，你好。 from 0.5 s: ma1 ma1 hao3 (pause) ni3 hao3, 3 s of audio; the `align` JSON.
TIMELINE = {
    "sentences": [{"text": "媽媽好，你好。", "start": 0.5, "end": 2.25}],
    "syllables": [
        {"text": "媽", "pinyin": "ma1", "start": 0.5, "end": 0.75, "sentence": 0},
        {"text": "媽", "pinyin": "ma1", "start": 0.75, "end": 1.0, "sentence": 0},
        {"text": "好", "pinyin": "hao3", "start": 1.0, "end": 1.25, "sentence": 0, "pause_after": True},
        {"text": "你", "pinyin": "ni3", "start": 1.75, "end": 2.0, "sentence": 0},
        {"text": "好", "pinyin": "hao3", "start": 2.0, "end": 2.25, "sentence": 0},
    ],
    "duration": 3.0,
}


def run(*args):
    return subprocess.run([CLI, *map(str, args)], capture_output=True, text=True, timeout=60)


def write_json(tmp_path, name, document):
    path = tmp_path / name
    path.write_text(json.dumps(document, ensure_ascii=False) if not isinstance(document, str) else document,
                    encoding="utf-8")
    return path


@pytest.fixture
def timeline(tmp_path):
    return write_json(tmp_path, "timeline.json", TIMELINE)


def keyframes(*args):
    result = run("keyframes", *args)
    assert result.returncode == 0, result.stderr
    return result


def test_json_has_exactly_the_contract_shape(tmp_path, timeline):
    out = tmp_path / "keys.json"
    result = keyframes("--timeline", timeline, "--seed", 7, "-o", out)
    assert result.stdout == "" and result.stderr == ""
    document = json.loads(out.read_text())
    assert list(document) == ["mouth", "events"]
    assert document["mouth"][0] == {"time": 0, "shape": "m", "syllable": None}
    for item in document["mouth"]:
        assert list(item) == ["time", "shape", "syllable"]
        assert item["shape"] in ["m", "f", "h'", "h", "r", "z", "a", "i", "u", "e", "o", "n"]
    assert [item["shape"] for item in document["mouth"] if item["syllable"] == 0] == ["m", "a"]
    assert {item["syllable"] for item in document["mouth"]} == {None, 0, 1, 2, 3, 4}
    times = [item["time"] for item in document["mouth"]]
    assert times == sorted(times) and len(set(times)) == len(times)
    for event in document["events"]:
        assert list(event) == ["kind", "start", "end", "amount"]
        assert event["kind"] in ["blink", "brows", "tilt", "turn", "nod"]
        assert event["start"] <= event["end"]


def test_same_seed_same_bytes_and_stdout_equals_file(tmp_path, timeline):
    out = tmp_path / "keys.json"
    keyframes("--timeline", timeline, "--seed", 7, "-o", out)
    again = keyframes("--timeline", timeline, "--seed", 7, "-o", "-").stdout
    assert again == out.read_text()
    other = [keyframes("--timeline", timeline, "--seed", seed, "-o", "-").stdout for seed in (8, 9, 10)]
    assert any(json.loads(text)["events"] != json.loads(again)["events"] for text in other)
    announcer = keyframes("--timeline", timeline, "--seed", 7, "--style", "announcer", "-o", "-").stdout
    assert json.loads(announcer)["mouth"] == json.loads(again)["mouth"]


def test_tsv_lists_the_mouth_key_frames(timeline):
    document = json.loads(keyframes("--timeline", timeline, "-o", "-").stdout)
    lines = keyframes("--timeline", timeline, "--tsv", "-o", "-").stdout.splitlines()
    assert lines == [f"{item['time']:g}\t{item['shape']}" for item in document["mouth"]]
    assert lines[0] == "0\tm"


def test_fps_moves_key_frames_onto_frames(timeline):
    document = json.loads(keyframes("--timeline", timeline, "--fps", 10, "-o", "-").stdout)
    assert all(abs(item["time"] * 10 - round(item["time"] * 10)) < 1e-6 for item in document["mouth"])


def events_of(document, kind):
    return [event for event in document["events"] if event["kind"] == kind]


def test_events_add_and_replace(tmp_path, timeline):
    nod = {"kind": "nod", "start": 1.0, "end": 1.4, "amount": 6}
    events = write_json(tmp_path, "events.json", [nod])
    simulated = json.loads(keyframes("--timeline", timeline, "--seed", 3, "-o", "-").stdout)
    added = json.loads(keyframes("--timeline", timeline, "--seed", 3, "--events", events, "-o", "-").stdout)
    replaced = json.loads(keyframes("--timeline", timeline, "--seed", 3, "--events", events,
                                    "--events-mode", "replace", "-o", "-").stdout)
    assert nod in added["events"]
    kept = [e for e in events_of(simulated, "nod") if e["end"] <= 1.0 or e["start"] >= 1.4]
    assert sorted(kept + [nod], key=lambda e: e["start"]) == events_of(added, "nod")
    assert events_of(replaced, "nod") == [nod]
    assert events_of(replaced, "blink") == events_of(simulated, "blink")
    # A keyframes document is an events file too: its "events" list is read.
    again = write_json(tmp_path, "again.json", replaced)
    reread = json.loads(keyframes("--timeline", timeline, "--seed", 3, "--events", again, "--events-mode",
                                  "replace", "-o", "-").stdout)
    assert reread["events"] == replaced["events"]


def test_an_event_out_of_range_exits_1_naming_it(tmp_path, timeline):
    events = write_json(tmp_path, "events.json", [{"kind": "blink", "start": 0.5, "end": 0.7, "amount": 1},
                                                  {"kind": "turn", "start": 2.0, "end": 2.5, "amount": 40}])
    out = tmp_path / "keys.json"
    result = run("keyframes", "--timeline", timeline, "--events", events, "-o", out)
    assert result.returncode == 1
    assert result.stderr.startswith(f"talkface: error: {events}: ")
    assert "event 1 (turn, 2-2.5 s)" in result.stderr
    assert not out.exists()


def test_an_unknown_kind_exits_1_naming_the_item(tmp_path, timeline):
    events = write_json(tmp_path, "events.json", {"events": [{"kind": "wink", "start": 0, "end": 1, "amount": 1}]})
    result = run("keyframes", "--timeline", timeline, "--events", events, "-o", "-")
    assert result.returncode == 1
    assert f"{events}: events[0].kind:" in result.stderr
    assert result.stdout == ""


@pytest.mark.parametrize(
    "text, where",
    [
        ('{"sentences": [}', ":1:16: not JSON"),
        ('{"sentences": []}', ':1:1: document: "syllables" is missing'),
        ('{"sentences":[{"text":"a"}],"syllables":[{"text":"a","pinyin":"a1","sentence":0,"start":"x"}]}',
         ':1:89: syllables[0].start: expected a number of seconds, found "x"'),
        ('{"sentences":[{"text":"a"}],"syllables":[{"text":"a","pinyin":"a1","sentence":3}]}',
         ":1:79: syllables[0].sentence: expected a sentence index 0..0, found 3"),
    ],
)
def test_a_timeline_with_an_error_exits_1_naming_where(tmp_path, text, where):
    path = write_json(tmp_path, "timeline.json", text)
    out = tmp_path / "keys.json"
    out.write_text("keep me")
    result = run("keyframes", "--timeline", path, "-o", out)
    assert result.returncode == 1
    assert result.stderr.startswith(f"talkface: error: {path}{where}"), result.stderr
    assert out.read_text() == "keep me"


def test_a_syllable_that_is_not_mandarin_is_named(tmp_path):
    document = json.loads(json.dumps(TIMELINE))
    document["syllables"][3]["pinyin"] = "xx3"
    result = run("keyframes", "--timeline", write_json(tmp_path, "t.json", document), "-o", "-")
    assert result.returncode == 1
    assert "xx3" in result.stderr


def test_usage_errors_exit_2(timeline):
    assert run("keyframes", "-o", "-").returncode == 2
    assert run("keyframes", "--timeline", timeline, "--style", "shouty", "-o", "-").returncode == 2
    assert run("keyframes", "--timeline", timeline, "--events-mode", "merge", "-o", "-").returncode == 2
    assert run("keyframes", "--timeline", timeline).returncode == 2


def long_timeline(tmp_path, seconds=300.0):
    document = json.loads(json.dumps(TIMELINE))
    document["duration"] = seconds
    return write_json(tmp_path, "long.json", document)


def test_a_style_file_changes_the_simulated_events(tmp_path):
    timeline = long_timeline(tmp_path)
    style = write_json(tmp_path, "style.json", {"blink_duration_s": [0.5, 0.5], "tilt_angle_deg": [9, 10]})
    document = json.loads(keyframes("--timeline", timeline, "--seed", 5, "--style", style, "-o", "-").stdout)
    blinks, tilts = events_of(document, "blink"), events_of(document, "tilt")
    assert len(blinks) > 20 and len(tilts) > 20
    assert all(abs(e["end"] - e["start"] - 0.5) < 0.0015 for e in blinks)
    assert all(9 <= abs(e["amount"]) <= 10 for e in tilts)
    default = json.loads(keyframes("--timeline", timeline, "--seed", 5, "-o", "-").stdout)
    assert events_of(default, "blink") != blinks
    # Kinds the file leaves alone draw from their own streams: unchanged.
    assert events_of(default, "turn") == events_of(document, "turn")


def test_a_style_file_with_a_base_equals_the_named_style(tmp_path):
    timeline = long_timeline(tmp_path, 60.0)
    style = write_json(tmp_path, "style.json", {"base": "announcer"})
    named = keyframes("--timeline", timeline, "--seed", 9, "--style", "announcer", "-o", "-").stdout
    assert keyframes("--timeline", timeline, "--seed", 9, "--style", style, "-o", "-").stdout == named
    assert keyframes("--timeline", timeline, "--seed", 9, "-o", "-").stdout != named


def test_without_switches_kinds_off_and_leaves_the_others_alone(tmp_path):
    timeline = long_timeline(tmp_path, 60.0)
    default = json.loads(keyframes("--timeline", timeline, "--seed", 2, "-o", "-").stdout)
    fewer = json.loads(keyframes("--timeline", timeline, "--seed", 2, "--without", "blink,nod", "-o", "-").stdout)
    assert events_of(default, "blink") and events_of(default, "nod")
    assert not events_of(fewer, "blink") and not events_of(fewer, "nod")
    assert fewer["events"] == [e for e in default["events"] if e["kind"] not in ("blink", "nod")]
    # The file's switches and --without add up; the caller's own events of a kind switched off stay.
    style = write_json(tmp_path, "style.json", {"is_turn_simulated": False})
    blink = {"kind": "blink", "start": 1.0, "end": 1.2, "amount": 1}
    events = write_json(tmp_path, "events.json", [blink])
    both = json.loads(keyframes("--timeline", timeline, "--seed", 2, "--style", style, "--without", "blink",
                                "--events", events, "-o", "-").stdout)
    assert {e["kind"] for e in both["events"]} == {"blink", "brows", "tilt", "nod"}
    assert events_of(both, "blink") == [blink]


@pytest.mark.parametrize(
    "text, where",
    [
        ('{\n  "blink_scale": 2\n}', ':2:3: key "blink_scale": unknown key; the keys are base, name, '),
        ('{"tilt_angle_deg": [2, 20]}', ':1:20: key "tilt_angle_deg": expected a range with 0 <= min <= max <= 15'),
        ('{"is_nod_simulated": "no"}', ':1:22: key "is_nod_simulated": expected true or false, found "no"'),
        ('{"base": "loud"}', ':1:10: key "base": expression style "loud"'),
        ('{"nod_up_s": [0.3, 0.5],}', ":1:25: expected a key in quotes"),
    ],
)
def test_a_bad_style_file_exits_1_naming_the_file_line_and_key(tmp_path, timeline, text, where):
    style = write_json(tmp_path, "style.json", text)
    out = tmp_path / "keys.json"
    result = run("keyframes", "--timeline", timeline, "--style", style, "-o", out)
    assert result.returncode == 1
    assert result.stderr.startswith(f"talkface: error: {style}{where}"), result.stderr
    assert not out.exists()


def test_style_usage_errors_exit_2(tmp_path, timeline):
    assert run("keyframes", "--timeline", timeline, "--style", tmp_path / "missing.json", "-o", "-").returncode == 2
    assert run("keyframes", "--timeline", timeline, "--without", "wink", "-o", "-").returncode == 2
    assert run("keyframes", "--timeline", timeline, "--without", "blink,wink", "-o", "-").returncode == 2

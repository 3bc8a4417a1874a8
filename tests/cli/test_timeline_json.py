"""The timeline JSON through the command (issue #14): `align --json` then `keyframes --timeline` gives
the same key-frame bytes as `keyframes AUDIO TRANSCRIPT` (no pause, nod or rest lost between them),
and `align --json` of a clip matches its golden file (tests/golden/README.md: TALKFACE_UPDATE_GOLDEN=1
rewrites it after a human has looked at the change)."""
import json
import os
import pathlib
import subprocess

import pytest

CLI = os.environ["TALKFACE_CLI"]
SOURCE_DIR = pathlib.Path(os.environ.get("TALKFACE_SOURCE_DIR", pathlib.Path(__file__).parents[2]))
CLIPS_DIR = SOURCE_DIR / "tests" / "data" / "speech"
GOLDEN_DIR = SOURCE_DIR / "tests" / "golden"
# comma_pause has a transcript comma (pause_after, the nod and the rest it brings); two_sentences two
# sentences and a sentence pause.
CLIPS = {"comma_pause": "flac", "two_sentences": "wav"}


def run(*args):
    result = subprocess.run([CLI, *map(str, args)], capture_output=True, text=True, timeout=120)
    assert result.returncode == 0, result.stderr
    return result.stdout


def clip(name):
    return CLIPS_DIR / f"{name}.{CLIPS[name]}", CLIPS_DIR / f"{name}.txt"


@pytest.mark.parametrize("name", list(CLIPS))
@pytest.mark.parametrize("form", [[], ["--tsv"], ["--fps", "30", "--style", "announcer"]])
def test_keyframes_of_the_align_json_are_the_bytes_of_keyframes_of_the_audio(tmp_path, name, form):
    audio, transcript = clip(name)
    timeline = tmp_path / "aligned.json"
    run("align", audio, transcript, "--json", "--quiet", "-o", timeline)
    direct = run("keyframes", audio, transcript, "--seed", 11, *form, "-o", "-")
    through_the_file = run("keyframes", "--timeline", timeline, "--seed", 11, *form, "-o", "-")
    assert through_the_file == direct


def test_align_json_prints_times_as_the_frames_they_are():
    """Aligned times are whole 10 ms frames: the document prints 3.57, not 3.5700000000000003 (a
    frame count times 0.01), while still keeping every digit a time has (shortest exact form)."""
    audio, transcript = clip("comma_pause")
    document = json.loads(run("align", audio, transcript, "--json", "--quiet"))
    times = [item[key] for part in ("sentences", "syllables") for item in document[part]
             for key in ("start", "end", "final_start") if key in item]
    assert times
    for time in times:
        assert len(repr(time).partition(".")[2]) <= 2, time


def test_align_json_matches_its_golden_file():
    audio, transcript = clip("two_sentences")
    document = run("align", audio, transcript, "--json", "--quiet")
    golden = GOLDEN_DIR / "align_two_sentences.json"
    if os.environ.get("TALKFACE_UPDATE_GOLDEN") == "1":
        golden.write_text(document, encoding="utf-8")
    assert document == golden.read_text(encoding="utf-8"), (
        f"`talkface align --json` differs from {golden}; if the change is right, rerun with "
        "TALKFACE_UPDATE_GOLDEN=1 and review the diff")

"""Golden files for what users keep (tests/golden/README.md): the keyframes SVG animation, the
key-frame JSON and TSV, and `talkface --help`, each compared byte for byte with the command's output
for a fixed clip and seed. TALKFACE_UPDATE_GOLDEN=1 rewrites them instead, after which a person
looks at the diff (and the SVG, rasterised) before committing."""
import os
import pathlib
import subprocess

import pytest

CLI = os.environ["TALKFACE_CLI"]
SOURCE_DIR = pathlib.Path(os.environ["TALKFACE_SOURCE_DIR"])
GOLDEN_DIR = SOURCE_DIR / "tests" / "golden"
CLIP = SOURCE_DIR / "tests" / "data" / "speech" / "two_sentences"
UPDATE = os.environ.get("TALKFACE_UPDATE_GOLDEN") == "1"
# The command without the photo stage (TALKFACE_WITH_PHOTO=OFF) has no face-from-photo line.
HAS_PHOTO = os.environ.get("TALKFACE_HAS_PHOTO", "1") == "1"


def run(*args):
    result = subprocess.run([CLI, *map(str, args)], capture_output=True, timeout=120)
    assert result.returncode == 0, result.stderr.decode()
    return result


def check_golden(name, produced, expected_filter=None):
    golden = GOLDEN_DIR / name
    if UPDATE:
        golden.write_bytes(produced)
        return
    expected = golden.read_bytes()
    if expected_filter:
        expected = expected_filter(expected)
    if produced != expected:
        produced_lines, expected_lines = produced.splitlines(), expected.splitlines()
        first = next((k for k, (a, b) in enumerate(zip(produced_lines, expected_lines)) if a != b),
                     min(len(produced_lines), len(expected_lines)))
        pytest.fail(f"{golden.relative_to(SOURCE_DIR)} differs from the command's output, first at line "
                    f"{first + 1} ({len(expected)} bytes expected, {len(produced)} produced). If the change "
                    f"is intended, rerun with TALKFACE_UPDATE_GOLDEN=1, look at `git diff tests/golden/` "
                    f"(and the SVG, rasterised) and commit it with the change.", pytrace=False)


def test_keyframes_json():
    check_golden("keyframes_two_sentences.json",
                 run("keyframes", f"{CLIP}.wav", f"{CLIP}.txt", "--seed", 7, "-o", "-").stdout)


def test_keyframes_tsv():
    check_golden("keyframes_two_sentences.tsv",
                 run("keyframes", f"{CLIP}.wav", f"{CLIP}.txt", "--seed", 7, "--tsv", "-o", "-").stdout)


def test_keyframes_svg_animation(tmp_path):
    svg = tmp_path / "talk.svg"
    run("animate", f"{CLIP}.wav", f"{CLIP}.txt", "--seed", 7, "--encoding", "keyframes", "--quiet", "-o", svg)
    check_golden("animation_two_sentences.svg", svg.read_bytes())


def without_photo_lines(text):
    return b"".join(line for line in text.splitlines(keepends=True) if b"face-from-photo" not in line)


def test_help():
    check_golden("help.txt", run("--help").stdout, None if HAS_PHOTO else without_photo_lines)

"""`talkface face-from-photo`: a face file and an overlay from a photo, errors with exit code 1."""
import os
import subprocess
import xml.etree.ElementTree as ET

import pytest

CLI = os.environ["TALKFACE_CLI"]
ASTRONAUT = "/usr/lib/python3/dist-packages/skimage/data/astronaut.png"


def run(*args):
    return subprocess.run([CLI, *map(str, args)], capture_output=True, text=True, timeout=120)


@pytest.mark.skipif(not os.path.exists(ASTRONAUT), reason="install Debian's python3-skimage")
def test_writes_the_face_and_the_overlay_and_lists_the_features(tmp_path):
    face, overlay = tmp_path / "face.xml", tmp_path / "points.png"
    result = run("face-from-photo", ASTRONAUT, "-o", face, "--debug", overlay, "--locator", "thesis")
    assert result.returncode == 0, result.stderr
    assert result.stdout == ""
    points = ET.parse(face).getroot().find("points")
    assert len(points) == 72
    assert overlay.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert "eye_pair" in result.stderr and "locator: thesis" in result.stderr


def test_a_photo_without_a_face_fails_with_exit_1_and_leaves_no_output(tmp_path):
    blank = tmp_path / "blank.pgm"
    blank.write_bytes(b"P5 64 64 255\n" + bytes([180]) * (64 * 64))
    face = tmp_path / "face.xml"
    result = run("face-from-photo", blank, "-o", face)
    assert result.returncode == 1
    assert "no face found" in result.stderr
    assert str(blank) in result.stderr
    assert not face.exists()


def test_an_unknown_locator_is_a_usage_error(tmp_path):
    result = run("face-from-photo", ASTRONAUT, "-o", tmp_path / "f.xml", "--locator", "haar")
    assert result.returncode == 2

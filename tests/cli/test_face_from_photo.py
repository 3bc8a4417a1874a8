"""`talkface face-from-photo`: a face file and an overlay from a photo, errors with exit code 1."""
import os
import struct
import subprocess
import xml.etree.ElementTree as ET
import zlib

import numpy
import pytest

CLI = os.environ["TALKFACE_CLI"]
ASTRONAUT = "/usr/lib/python3/dist-packages/skimage/data/astronaut.png"


def run(*args):
    return subprocess.run([CLI, *map(str, args)], capture_output=True, text=True, timeout=120)


def write_grey_png(path, width, height, level):
    """A uniform 8-bit grey PNG, written with the standard library only."""
    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))
    rows = (b"\0" + bytes([level]) * width) * height
    path.write_bytes(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 0, 0, 0, 0))
                     + chunk(b"IDAT", zlib.compress(rows)) + chunk(b"IEND", b""))


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
    blank = tmp_path / "blank.png"
    write_grey_png(blank, 64, 64, 180)
    face = tmp_path / "face.xml"
    result = run("face-from-photo", blank, "-o", face)
    assert result.returncode == 1
    assert "no face found" in result.stderr
    assert str(blank) in result.stderr
    assert not face.exists()


def test_a_black_photo_is_too_dark(tmp_path):
    black = tmp_path / "black.png"
    write_grey_png(black, 64, 64, 0)
    result = run("face-from-photo", black, "-o", tmp_path / "face.xml")
    assert result.returncode == 1
    assert f"{black}: too dark" in result.stderr


@pytest.mark.skipif(not os.path.exists(ASTRONAUT), reason="install Debian's python3-skimage")
def test_two_faces_are_refused_until_face_index_picks_one(tmp_path):
    from skimage import io
    two = tmp_path / "two.png"
    pixels = io.imread(ASTRONAUT)[:, :, :3]
    io.imsave(two, numpy.hstack([pixels, pixels]), check_contrast=False)
    result = run("face-from-photo", two, "-o", tmp_path / "face.xml", "--locator", "thesis")
    assert result.returncode == 1
    assert "2 faces found" in result.stderr
    result = run("face-from-photo", two, "-o", tmp_path / "face.xml", "--locator", "thesis", "--face-index", "1")
    assert result.returncode == 0, result.stderr


@pytest.mark.skipif(not os.path.exists(ASTRONAUT), reason="install Debian's python3-skimage")
def test_a_truncated_photo_is_named_with_exit_1(tmp_path):
    truncated = tmp_path / "half.png"
    data = open(ASTRONAUT, "rb").read()
    truncated.write_bytes(data[:len(data) // 2])
    result = run("face-from-photo", truncated, "-o", tmp_path / "face.xml")
    assert result.returncode == 1
    assert f"{truncated}: broken PNG: the file ends before the image does (truncated)" in result.stderr


def test_an_unknown_locator_is_a_usage_error(tmp_path):
    result = run("face-from-photo", ASTRONAUT, "-o", tmp_path / "f.xml", "--locator", "haar")
    assert result.returncode == 2

"""`talkface face-from-photo`: a face file and an overlay from a photo, errors with exit code 1."""
import os
import pathlib
import shutil
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


@pytest.mark.skipif(not os.path.exists(ASTRONAUT), reason="install Debian's python3-skimage")
def test_the_smallest_face_accepted_can_be_set(tmp_path):
    face = tmp_path / "face.xml"
    result = run("face-from-photo", ASTRONAUT, "-o", face, "--locator", "thesis", "--min-face-width", "400")
    assert result.returncode == 1
    assert "at least 400" in result.stderr
    assert not face.exists()
    assert run("face-from-photo", ASTRONAUT, "-o", face, "--min-face-width", "0").returncode == 2


def test_an_unknown_locator_is_a_usage_error(tmp_path):
    result = run("face-from-photo", ASTRONAUT, "-o", tmp_path / "f.xml", "--locator", "haar")
    assert result.returncode == 2


def test_the_command_opens_the_photo_stage_only_for_this_command():
    # No OpenCV, dlib or libtalkface_photo among what the command needs to start (a `talkface
    # syllables` would pay some 50 M instructions to load them): face-from-photo's module links them.
    needed = subprocess.run(["readelf", "-d", CLI], capture_output=True, text=True, check=True).stdout
    assert "talkface_photo" not in needed and "opencv" not in needed and "dlib" not in needed


def test_without_its_module_the_command_names_it_and_the_packages(tmp_path):
    # The command copied away from the lib/talkface/ beside it finds libtalkface (its build run path)
    # but not the module: every other command still runs, face-from-photo is refused with exit 1.
    copy = tmp_path / "bin" / "talkface"
    copy.parent.mkdir()
    shutil.copy(CLI, copy)
    assert subprocess.run([copy, "render", "-o", tmp_path / "face.svg"]).returncode == 0
    blank = tmp_path / "blank.png"
    write_grey_png(blank, 64, 64, 180)
    result = subprocess.run([copy, "face-from-photo", blank, "-o", tmp_path / "face.xml"], capture_output=True,
                            text=True, timeout=60)
    assert result.returncode == 1
    assert result.stderr.startswith(f"talkface: error: {tmp_path}/")  # LIBDIR/talkface/ beside bin/
    assert "/talkface/talkface_face_from_photo.so: face-from-photo's module is missing" in result.stderr
    assert not (tmp_path / "face.xml").exists()
    # A module there that cannot be loaded (as when a library it links is missing): the loader's
    # reason, and the Debian packages of what it links.
    module = pathlib.Path(result.stderr[len("talkface: error: "):].split(": ")[0])
    module.parent.mkdir(parents=True)
    module.write_bytes(b"not a shared object\n")
    result = subprocess.run([copy, "face-from-photo", blank, "-o", tmp_path / "face.xml"], capture_output=True,
                            text=True, timeout=60)
    assert result.returncode == 1
    assert result.stderr.startswith(f"talkface: error: {module}: face-from-photo needs the photo stage, which could "
                                    f"not be loaded ({module}: ")
    assert "libopencv-objdetect406" in result.stderr
    assert not (tmp_path / "face.xml").exists()

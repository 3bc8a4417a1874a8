"""Face from a photo in Python: paths and numpy arrays, feature confidences, every refusal as
ValueError, broken photo files as OSError."""
import os

import numpy
import pytest

import talkface

# The photo stage is a library of its own (TALKFACE_WITH_PHOTO); a build without it has no module.
pytest.importorskip("talkface._talkface_photo")

ASTRONAUT = "/usr/lib/python3/dist-packages/skimage/data/astronaut.png"
HOPPER = "/usr/share/matplotlib/mpl-data/sample_data/grace_hopper.jpg"
needs_photo = pytest.mark.skipif(not os.path.exists(ASTRONAUT),
                                 reason="install Debian's python3-skimage for astronaut.png")
needs_jpeg = pytest.mark.skipif(not os.path.exists(HOPPER),
                                reason="install Debian's python-matplotlib-data for grace_hopper.jpg")


def astronaut_pixels():
    from skimage import io
    return io.imread(ASTRONAUT)[:, :, :3]


@needs_photo
def test_from_photo_is_a_static_method_giving_a_face_in_photo_pixels():
    face = talkface.FaceModel.from_photo(ASTRONAUT, locator="thesis")
    # Hand-marked iris centres (204, 100) and (246, 102); 0.1 d is about 4 px.
    numpy.testing.assert_allclose(face.point("EyeballLeft"), (204, 100), atol=4.2)
    numpy.testing.assert_allclose(face.point("EyeballRight"), (246, 102), atol=4.2)


@needs_photo
def test_face_from_photo_reports_every_feature(tmp_path):
    result = talkface.face_from_photo(ASTRONAUT, locator="thesis")
    assert result.locator == "thesis"
    assert result.faces_found == 1
    names = {feature.name for feature in result.features}
    assert {"eye_pair", "mouth", "nose", "hair", "skin_colour"} <= names
    assert all(0.0 <= feature.confidence <= 1.0 for feature in result.features)
    assert result.confidence("mouth") > 0.5
    result.write_overlay(ASTRONAUT, tmp_path / "overlay.png")
    assert (tmp_path / "overlay.png").stat().st_size > 1000
    result.face.save(tmp_path / "face.xml")
    assert talkface.FaceModel.load(tmp_path / "face.xml") == result.face


@needs_photo
def test_a_numpy_rgb_array_gives_the_same_face_as_the_file():
    pixels = astronaut_pixels()
    assert talkface.FaceModel.from_photo(pixels, locator="thesis") == \
        talkface.FaceModel.from_photo(ASTRONAUT, locator="thesis")


def test_a_blank_array_has_no_face():
    with pytest.raises(talkface.InvalidArgument, match="no face found"):
        talkface.face_from_photo(numpy.full((200, 200, 3), 180, numpy.uint8))


@needs_photo
def test_a_dark_photo_is_refused_as_too_dark():
    dark = (astronaut_pixels() * 0.12).astype(numpy.uint8)
    with pytest.raises(talkface.InvalidArgument, match="too dark"):
        talkface.face_from_photo(dark)


@needs_photo
def test_a_tiny_face_is_refused_as_too_small():
    from skimage.transform import rescale
    small = (rescale(astronaut_pixels(), 0.45, channel_axis=2, anti_aliasing=True) * 255).astype(numpy.uint8)
    with pytest.raises(talkface.InvalidArgument, match="face too small"):
        talkface.face_from_photo(small, locator="thesis")


@needs_photo
def test_the_smallest_face_accepted_can_be_set():
    # PhotoOptions::min_face_width_px, as tf_photo_options_set_min_face_width_px and --min-face-width.
    with pytest.raises(talkface.InvalidArgument, match="at least 400"):
        talkface.face_from_photo(ASTRONAUT, locator="thesis", min_face_width_px=400)
    with pytest.raises(talkface.InvalidArgument, match="min_face_width_px"):
        talkface.FaceModel.from_photo(ASTRONAUT, min_face_width_px=8)
    assert talkface.face_from_photo(ASTRONAUT, locator="thesis", min_face_width_px=16).face.name == "photo"


@needs_photo
def test_two_faces_are_refused_until_face_index_picks_one():
    two = numpy.ascontiguousarray(numpy.hstack([astronaut_pixels(), astronaut_pixels()]))
    with pytest.raises(talkface.InvalidArgument, match=r"2 faces found.*pass face_index 0\.\.1"):
        talkface.face_from_photo(two, locator="thesis")
    right = talkface.face_from_photo(two, locator="thesis", face_index=1)
    assert right.faces_found == 2
    assert right.face.point("EyeballLeft")[0] == pytest.approx(512 + 204, abs=4.2)


@needs_jpeg
def test_a_jpeg_file_is_read_and_a_truncated_one_is_an_oserror_naming_it(tmp_path):
    result = talkface.face_from_photo(HOPPER, locator="thesis")
    # Hand-marked iris centres (222, 190) and (305, 187); 0.1 d is about 8 px.
    numpy.testing.assert_allclose(result.face.point("EyeballLeft"), (222, 190), atol=8.3)
    truncated = tmp_path / "hopper.jpg"
    data = open(HOPPER, "rb").read()
    truncated.write_bytes(data[:len(data) // 2])
    with pytest.raises(OSError, match=r"hopper\.jpg: broken JPEG: the file ends before the image does"):
        talkface.face_from_photo(truncated)


@needs_jpeg
def test_a_cmyk_jpeg_is_refused_with_what_to_do(tmp_path):
    image = pytest.importorskip("PIL.Image")
    cmyk = tmp_path / "print.jpg"
    image.open(HOPPER).convert("CMYK").save(cmyk)
    with pytest.raises(talkface.FileError, match="print.jpg: a CMYK JPEG .*save the photo as RGB"):
        talkface.face_from_photo(cmyk)


def test_a_file_in_another_format_is_named(tmp_path):
    gif = tmp_path / "me.gif"
    gif.write_bytes(b"GIF89a" + bytes(32))
    with pytest.raises(talkface.FileError, match="a GIF image; talkface reads PNG and JPEG"):
        talkface.face_from_photo(gif)


def test_a_wrong_array_shape_is_named():
    with pytest.raises(ValueError, match=r"\(H, W, 3\)"):
        talkface.face_from_photo(numpy.zeros((20, 20, 2), numpy.uint8))


def test_a_missing_photo_is_a_file_error_naming_it():
    with pytest.raises(talkface.FileError, match="me.jpg"):
        talkface.face_from_photo("/nonexistent/me.jpg")


def test_an_unknown_locator_is_refused():
    with pytest.raises(ValueError, match="thesis, dlib or automatic"):
        talkface.face_from_photo("/nonexistent/me.jpg", locator="haar")

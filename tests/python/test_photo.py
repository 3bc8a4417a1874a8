"""Face from a photo in Python: paths and numpy arrays, feature confidences, errors as ValueError."""
import os

import numpy
import pytest

import talkface

ASTRONAUT = "/usr/lib/python3/dist-packages/skimage/data/astronaut.png"
needs_photo = pytest.mark.skipif(not os.path.exists(ASTRONAUT),
                                 reason="install Debian's python3-skimage for astronaut.png")


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
    from skimage import io
    pixels = io.imread(ASTRONAUT)[:, :, :3]
    assert talkface.FaceModel.from_photo(pixels, locator="thesis") == \
        talkface.FaceModel.from_photo(ASTRONAUT, locator="thesis")


def test_a_blank_array_has_no_face():
    with pytest.raises(talkface.InvalidArgument, match="no face found"):
        talkface.face_from_photo(numpy.full((200, 200, 3), 180, numpy.uint8))


def test_a_wrong_array_shape_is_named():
    with pytest.raises(ValueError, match=r"\(H, W, 3\)"):
        talkface.face_from_photo(numpy.zeros((20, 20, 2), numpy.uint8))


def test_a_missing_photo_is_a_file_error_naming_it():
    with pytest.raises(talkface.FileError, match="me.jpg"):
        talkface.face_from_photo("/nonexistent/me.jpg")


def test_an_unknown_locator_is_refused():
    with pytest.raises(ValueError, match="thesis, dlib or automatic"):
        talkface.face_from_photo("/nonexistent/me.jpg", locator="haar")

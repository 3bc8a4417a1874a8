import copy
import pickle

import numpy
import numpy.testing
import pytest

import talkface


def test_default_face_has_72_points_and_12_fapus(face):
    assert len(talkface.FaceModel.point_ids()) == 72
    assert talkface.FaceModel.fapu_names()[0] == "d"
    assert face.points().shape == (72, 2)
    assert face.points().dtype == numpy.float64
    assert set(face.fapus()) == set(talkface.FaceModel.fapu_names())
    assert face.fapu("d") > 0
    assert talkface.default_face() == talkface.FaceModel.default_face() == face


def test_point_is_an_xy_tuple_matching_points_array(face):
    x, y = face.point("3.2")
    row = talkface.FaceModel.point_ids().index("3.2")
    assert (x, y) == tuple(face.points()[row])


def test_set_point_and_set_fapu_are_read_back(face):
    face.set_point("8.3", (140.25, 212.5))
    assert face.point("8.3") == (140.25, 212.5)
    face.set_fapu("MW0", 33.5)
    assert face.fapu("MW0") == 33.5
    face.name = "announcer"
    assert face.name == "announcer"


def test_set_points_round_trips_and_checks_the_shape(face):
    moved = face.points() + numpy.array([10.0, -5.0])
    face.set_points(moved)
    numpy.testing.assert_allclose(face.points(), moved, rtol=0, atol=0)
    with pytest.raises(talkface.InvalidArgument, match=r"points: expected shape \(72, 2\), got \(70, 2\)"):
        face.set_points(numpy.zeros((70, 2)))
    with pytest.raises(ValueError, match=r"got \(144,\)"):
        face.set_points(numpy.zeros(144))


def test_set_points_is_all_or_nothing(face):
    before = face.points()
    bad = before.copy()
    bad[40, 0] = numpy.nan
    with pytest.raises(talkface.InvalidArgument, match="finite"):
        face.set_points(bad)
    numpy.testing.assert_array_equal(face.points(), before)


def test_points_returns_a_copy(face):
    xy = face.points()
    xy[:] = 0.0
    assert face.point("3.2") != (0.0, 0.0)


def test_saved_face_loads_back_equal(face, tmp_path):
    face.set_point("8.3", (101.0 / 3.0, 1e-7))
    path = tmp_path / "face.xml"
    face.save(path)
    loaded = talkface.FaceModel.load(path)
    assert loaded == face
    numpy.testing.assert_array_equal(loaded.points(), face.points())
    assert loaded.fapus() == face.fapus()
    assert talkface.FaceModel.load(str(path)) == face


def test_xml_text_round_trips(face):
    assert talkface.FaceModel.from_xml(face.to_xml(), "face.xml") == face


def test_a_face_file_of_a_future_version_is_refused_naming_the_version_read(face):
    future = face.to_xml().replace('version="1"', 'version="999"', 1)
    assert 'version="999"' in future
    with pytest.raises(talkface.ParseError, match=r"face\.xml:\d+:\d+: .*version 999 is newer than this library "
                                                  r"reads \(up to 1\); update talkface"):
        talkface.FaceModel.from_xml(future, "face.xml")


def test_copy_and_pickle_are_independent_equal_faces(face):
    for other in (copy.copy(face), copy.deepcopy(face), pickle.loads(pickle.dumps(face))):
        assert other == face
        other.set_point("3.2", (0.0, 0.0))
        assert other != face


def test_colors_are_hex_strings_assigned_back(face):
    colors = face.colors
    assert colors.skin.startswith("#") and len(colors.skin) == 7
    colors.hair = "#602010"
    assert face.colors.hair != "#602010"  # a copy until assigned back
    face.colors = colors
    assert face.colors.hair == "#602010"
    with pytest.raises(talkface.InvalidArgument, match="colour"):
        colors.hair = "brown"


def test_lift_face_gives_89_local_points(face):
    lifted = talkface.lift_face(face)
    assert len(lifted.ids) == 89
    assert lifted.ids[72:] == talkface.additional_point_ids()
    assert lifted.local_xyz.shape == (89, 3)
    assert lifted.d == face.fapu("d")
    x, y, z = lifted.local("3.2")
    # The local frame: x towards the image left, y up, from O; back to the image exactly.
    origin_x, origin_y = lifted.origin
    assert (origin_x - x, origin_y - y) == face.point("3.2")
    assert talkface.rotation_origin(face) == lifted.origin


def test_place_face_moves_and_scales(face):
    placed = talkface.place_face(face, (300.0, 400.0), 2.0 * face.fapu("d"))
    numpy.testing.assert_allclose(talkface.rotation_origin(placed), (300.0, 400.0), atol=1e-9)
    numpy.testing.assert_allclose(placed.fapu("MW0"), 2.0 * face.fapu("MW0"), rtol=1e-12)
    with pytest.raises(talkface.InvalidArgument, match="d_px"):
        talkface.place_face(face, (0.0, 0.0), -1.0)

import numpy
import numpy.testing
import pytest

import talkface


def test_mouth_shape_names_round_trip():
    shapes = talkface.all_mouth_shapes()
    assert len(shapes) == 12
    names = [talkface.mouth_shape_name(shape) for shape in shapes]
    assert names == ["m", "f", "h'", "h", "r", "z", "a", "i", "u", "e", "o", "n"]
    for shape, name in zip(shapes, names):
        assert talkface.mouth_shape_from_name(name) == shape
    assert talkface.mouth_shape_from_name("h_prime") == talkface.MouthShape.h_prime
    assert int(talkface.MouthShape.n) == 11  # equal to the C ABI's TF_MOUTH_N
    with pytest.raises(talkface.InvalidArgument, match='"q"'):
        talkface.mouth_shape_from_name("q")


@pytest.mark.parametrize("shape", talkface.all_mouth_shapes(), ids=talkface.mouth_shape_name)
def test_every_shape_keeps_corners_apart_and_lips_ordered(face, shape):
    controls = talkface.mouth_controls(face, shape)
    assert controls.left[0] < controls.right[0]
    assert controls.up[1] <= controls.down[1]
    shaped = talkface.apply_mouth(face, controls)
    assert shaped.point("8.2") == controls.down
    assert shaped.point("2.2")[1] <= shaped.point("2.3")[1]


def test_shape_a_opens_widest_and_m_is_neutral(face):
    def opening(shape):
        controls = talkface.mouth_controls(face, shape)
        return controls.down[1] - controls.up[1]

    openings = {shape: opening(shape) for shape in talkface.all_mouth_shapes()}
    assert max(openings, key=openings.get) == talkface.MouthShape.a
    assert talkface.mouth_controls(face, talkface.MouthShape.m) == talkface.neutral_mouth_controls(face)


def test_apply_expression_closes_the_eye_and_checks_amounts(face):
    closed = talkface.apply_expression(face, talkface.Expression(blink_left=1.0))
    assert closed.point("3.2")[1] > face.point("3.2")[1]
    assert closed.point("3.1") == face.point("3.1")
    with pytest.raises(talkface.InvalidArgument, match="smile"):
        talkface.apply_expression(face, talkface.Expression(smile=1.5))


def test_face_state_fields_are_the_states_own():
    state = talkface.FaceState()
    assert state.mouth is None
    state.pose.beta_deg = 10.0
    state.expression.smile = 0.5
    assert state.pose == talkface.Pose(beta_deg=10.0)
    assert state.expression == talkface.Expression(smile=0.5)


def test_frontal_neutral_projection_keeps_the_model_points(face):
    projected = talkface.project_face(face, talkface.FaceState())
    assert projected.ids[:72] == talkface.FaceModel.point_ids()
    assert projected.image_xy.shape == (89, 2)
    assert projected.hair_polygon().shape == (23, 2)
    assert list(projected.left_contour) == ["11.2", "10.10", "2.14"]
    assert projected.nose_bridge in (talkface.NoseBridgeSide.left, talkface.NoseBridgeSide.right)
    for id in talkface.FaceModel.point_ids():
        if id.startswith("Eyeball"):
            continue  # pupils follow the gaze
        numpy.testing.assert_allclose(projected.point(id), face.point(id), atol=1e-9, err_msg=id)


def test_projection_uses_the_mouth_controls(face):
    controls = talkface.mouth_controls(face, talkface.MouthShape.a)
    projected = talkface.project_face(face, talkface.FaceState(mouth=controls))
    numpy.testing.assert_allclose(projected.point("8.2"), controls.down, atol=1e-9)
    assert projected.face.point("8.2") == controls.down


def test_turned_head_moves_the_nose_tip(face):
    frontal = talkface.project_face(face, talkface.FaceState())
    turned = talkface.project_face(face, talkface.FaceState(pose=talkface.Pose(beta_deg=15.0)))
    assert turned.point("9.15") != frontal.point("9.15")


def test_out_of_range_pose_names_the_angle(face):
    with pytest.raises(talkface.InvalidArgument, match="beta_deg") as raised:
        talkface.project_face(face, talkface.FaceState(pose=talkface.Pose(beta_deg=20.0)))
    assert "beta_deg" in raised.value.parameter
    assert talkface.kMaxPoseAngleDeg == 15.0

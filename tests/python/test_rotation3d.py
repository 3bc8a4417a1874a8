import itertools

import numpy
import numpy.testing
import pytest

import talkface

ANGLES_DEG = (-15.0, -7.5, 0.0, 7.5, 15.0)


@pytest.mark.parametrize("alpha_deg,beta_deg,gamma_deg", itertools.product(ANGLES_DEG, repeat=3))
def test_matrix_is_a_proper_rotation(alpha_deg, beta_deg, gamma_deg):
    matrix = talkface.Rotation3D(alpha_deg, beta_deg, gamma_deg).matrix()
    assert matrix.shape == (3, 3)
    numpy.testing.assert_allclose(matrix @ matrix.T, numpy.eye(3), atol=1e-12)
    numpy.testing.assert_allclose(numpy.linalg.det(matrix), 1.0, atol=1e-12)


def test_rotation_order_is_y_then_x_then_z():
    rotation = talkface.Rotation3D(alpha_deg=5.0, beta_deg=10.0, gamma_deg=-3.0)
    # Each single-axis matrix is the library's own; the product checks the documented order.
    rx = talkface.Rotation3D(alpha_deg=5.0).matrix()
    ry = talkface.Rotation3D(beta_deg=10.0).matrix()
    rz = talkface.Rotation3D(gamma_deg=-3.0).matrix()
    numpy.testing.assert_allclose(rotation.matrix(), rz @ rx @ ry, atol=1e-12)


def test_rotate_accepts_a_point_or_rows_and_unrotate_inverts_it():
    rotation = talkface.Rotation3D(5.0, 10.0, 15.0)
    point = rotation.rotate([1.0, 2.0, 3.0])
    assert point.shape == (3,)
    numpy.testing.assert_allclose(point, rotation.matrix() @ [1.0, 2.0, 3.0], atol=1e-12)
    rows = numpy.random.default_rng(7).uniform(-100, 100, size=(20, 3))
    rotated = rotation.rotate(rows)
    assert rotated.shape == (20, 3)
    numpy.testing.assert_allclose(rotation.unrotate(rotated), rows, atol=1e-9)


def test_wrong_shape_and_non_finite_angle_are_named():
    with pytest.raises(talkface.InvalidArgument, match=r"local_xyz: expected shape \(3,\) or \(N, 3\), got \(4, 2\)"):
        talkface.Rotation3D().rotate(numpy.zeros((4, 2)))
    with pytest.raises(talkface.InvalidArgument, match="beta"):
        talkface.Rotation3D(0.0, float("nan"), 0.0)


def test_angles_are_kept_and_compared():
    rotation = talkface.Rotation3D(alpha_deg=1.0, beta_deg=2.0, gamma_deg=3.0)
    assert (rotation.alpha_deg, rotation.beta_deg, rotation.gamma_deg) == (1.0, 2.0, 3.0)
    assert rotation == talkface.Rotation3D(1.0, 2.0, 3.0)
    assert rotation != talkface.Rotation3D()

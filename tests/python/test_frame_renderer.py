import threading

import numpy
import pytest

import talkface


def test_a_frame_is_an_rgba_array_of_the_frame_size(face):
    renderer = talkface.FrameRenderer(face, talkface.FrameOptions(width_px=320, height_px=180))
    frame = renderer.render_frame_rgba(talkface.FaceState())
    assert frame.shape == (180, 320, 4)
    assert frame.dtype == numpy.uint8
    assert tuple(frame[0, 0]) == (0x1D, 0x3B, 0x5C, 255)  # the announcer stage's colour
    assert (renderer.width_px, renderer.height_px) == (320, 180)
    assert renderer.options.layout == talkface.FrameLayout.announcer


def test_the_flat_look_draws_the_same_face_without_outlines(face):
    outlined = talkface.FrameRenderer(face, talkface.FrameOptions(width_px=320, height_px=180))
    flat = talkface.FrameRenderer(face, talkface.FrameOptions(width_px=320, height_px=180,
                                                               look=talkface.FaceLook.flat))
    assert flat.options.look == talkface.FaceLook.flat
    a = outlined.render_frame_rgba(talkface.FaceState()).astype(int)
    b = flat.render_frame_rgba(talkface.FaceState()).astype(int)
    assert tuple(b[0, 0]) == tuple(a[0, 0])
    assert numpy.abs(a - b).max(axis=2).astype(bool).sum() > 200


def test_the_mouth_region_changes_with_the_mouth_shape(face):
    renderer = talkface.FrameRenderer(face, talkface.FrameOptions(width_px=640, height_px=360))
    open_mouth = talkface.FaceState()
    open_mouth.mouth = talkface.mouth_controls(face, talkface.MouthShape.a)
    closed = talkface.FaceState()
    closed.mouth = talkface.mouth_controls(face, talkface.MouthShape.m)
    a = renderer.render_frame_rgba(open_mouth).astype(int)
    m = renderer.render_frame_rgba(closed).astype(int)
    changed = numpy.argwhere(numpy.abs(a - m).max(axis=2) > 64)
    assert len(changed) > 100
    # Only around the mouth: the lower middle of the face.
    assert changed[:, 1].min() > 640 * 0.35 and changed[:, 1].max() < 640 * 0.65


def test_a_transparent_frame_in_the_face_layout(face):
    options = talkface.FrameOptions(width_px=200, height_px=240, layout=talkface.FrameLayout.face, background=None)
    frame = talkface.FrameRenderer(face, options).render_frame_rgba(talkface.FaceState())
    assert frame[0, 0, 3] == 0
    assert frame[120, 100, 3] == 255


def test_a_background_picture_covers_the_frame(face):
    renderer = talkface.FrameRenderer(face, talkface.FrameOptions(width_px=100, height_px=60))
    picture = numpy.zeros((3, 4, 4), numpy.uint8)
    picture[..., 1] = 240
    picture[..., 3] = 255
    renderer.set_background_image(picture)
    assert tuple(renderer.render_frame_rgba(talkface.FaceState())[0, 0]) == (0, 240, 0, 255)
    with pytest.raises(talkface.InvalidArgument, match=r"\(H, W, 4\)"):
        renderer.set_background_image(numpy.zeros((3, 4, 3), numpy.uint8))
    with pytest.raises(talkface.InvalidArgument, match="uint8"):
        renderer.set_background_image(numpy.zeros((3, 4, 4), numpy.float32))


def test_out_of_range_options_are_named(face):
    with pytest.raises(talkface.InvalidArgument, match="width_px"):
        talkface.FrameRenderer(face, talkface.FrameOptions(width_px=0))
    with pytest.raises(talkface.InvalidArgument, match="height_px"):
        talkface.FrameRenderer(face, talkface.FrameOptions(height_px=5000))
    with pytest.raises(talkface.InvalidArgument, match="face_d_px"):
        talkface.FrameRenderer(face, talkface.FrameOptions(face_d_px=-2.0))


def test_threads_share_a_renderer_and_get_whole_frames(face):
    renderer = talkface.FrameRenderer(face, talkface.FrameOptions(width_px=160, height_px=90))
    states = []
    for beta in (-12.0, 0.0, 12.0):
        state = talkface.FaceState()
        state.pose = talkface.Pose(0.0, beta, 0.0)
        states.append(state)
    expected = [talkface.FrameRenderer(face, renderer.options).render_frame_rgba(s) for s in states]
    results = {}

    def draw(index):
        for _ in range(20):
            results.setdefault(index, []).append(renderer.render_frame_rgba(states[index]))

    threads = [threading.Thread(target=draw, args=(i,)) for i in range(3)]
    for thread in threads:
        thread.start()
    for thread in threads:
        thread.join()
    for index, frames in results.items():
        for frame in frames:
            numpy.testing.assert_array_equal(frame, expected[index])


def test_the_stub_lists_the_options():
    stub = open(talkface.__file__.replace("__init__.py", "_talkface.pyi"), encoding="utf-8").read()
    for name in ("width_px", "layout", "background", "face_origin_px", "face_d_px", "alpha"):
        assert f"    {name}: " in stub, name
    assert "class FrameRenderer:" in stub

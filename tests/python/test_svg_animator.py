import concurrent.futures
import xml.dom.minidom

import pytest

import talkface


def test_render_svg_is_a_standalone_svg_document(face):
    svg = talkface.SvgAnimator(face).render_svg(talkface.FaceState())
    assert svg.startswith("<?xml")
    assert xml.dom.minidom.parseString(svg).documentElement.tagName == "svg"


def test_options_are_kept_and_change_the_drawing(face):
    options = talkface.SvgOptions(background=None, draw_clothes=False, width_px=400, height_px=500)
    animator = talkface.SvgAnimator(face, options)
    assert animator.options.background is None
    assert animator.options.width_px == 400
    assert animator.face == face
    plain = talkface.SvgAnimator(face).render_svg(talkface.FaceState())
    assert animator.render_svg(talkface.FaceState()) != plain


def test_out_of_range_option_is_named(face):
    with pytest.raises(talkface.InvalidArgument, match="decimals"):
        talkface.SvgAnimator(face, talkface.SvgOptions(decimals=99))


def test_write_svg_writes_the_rendered_document(face, tmp_path):
    animator = talkface.SvgAnimator(face)
    state = talkface.FaceState(pose=talkface.Pose(beta_deg=10.0))
    path = tmp_path / "face.svg"
    animator.write_svg(path, state)
    assert path.read_text(encoding="utf-8") == animator.render_svg(state)


def test_write_svg_to_a_missing_folder_is_a_file_error(face, tmp_path):
    path = tmp_path / "missing" / "face.svg"
    with pytest.raises(talkface.FileError) as raised:
        talkface.SvgAnimator(face).write_svg(path, talkface.FaceState())
    assert raised.value.filename == str(path)
    assert not path.exists()


def test_two_threads_render_at_once(face):
    animator = talkface.SvgAnimator(face)
    states = [talkface.FaceState(pose=talkface.Pose(beta_deg=beta)) for beta in (-15.0, -5.0, 5.0, 15.0)] * 4
    expected = [animator.render_svg(state) for state in states]
    with concurrent.futures.ThreadPoolExecutor(max_workers=2) as pool:
        rendered = list(pool.map(animator.render_svg, states))
    assert rendered == expected

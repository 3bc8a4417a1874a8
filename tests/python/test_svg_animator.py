import concurrent.futures
import json
import re
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


def test_the_flat_look_draws_no_outline_but_the_upper_lids(face):
    options = talkface.SvgOptions(look=talkface.FaceLook.flat)
    assert options.look == talkface.FaceLook.flat
    assert "look=FaceLook.flat" in repr(options)
    flat = talkface.SvgAnimator(face, options).render_svg(talkface.FaceState())
    stroked = re.findall(r'<[^>]* stroke-width="[^"]*"', flat)
    assert len(stroked) == 2 and all('class="eye-left-lid"' in e or 'class="eye-right-lid"' in e for e in stroked)
    assert flat.count("stroke-width") == 2
    assert "stroke-width" in talkface.SvgAnimator(face).render_svg(talkface.FaceState())


def test_out_of_range_option_is_named(face):
    talkface.SvgAnimator(face, talkface.SvgOptions(decimals=talkface.kMaxSvgDecimals))
    with pytest.raises(talkface.InvalidArgument, match=f"decimals: expected 0..{talkface.kMaxSvgDecimals}"):
        talkface.SvgAnimator(face, talkface.SvgOptions(decimals=talkface.kMaxSvgDecimals + 1))
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


def test_the_animation_as_lottie_moves_the_mouth_and_writes_atomically(face, tmp_path):
    timeline = talkface.read_transcript("你好。")
    syllables = timeline.syllables
    for index, syllable in enumerate(syllables):
        syllable.start_s, syllable.end_s = 0.3 + 0.3 * index, 0.6 + 0.3 * index
    timeline.syllables = syllables
    timeline.duration_s = 1.2
    animation = talkface.animate(face, timeline, talkface.ExpressionSimulator(timeline, 3))
    animator = talkface.SvgAnimator(face)
    lottie = json.loads(animator.render_animation_lottie(animation))
    assert (lottie["fr"], lottie["ip"], lottie["op"]) == (animation.fps, 0, len(animation.frames))
    lips = [group for layer in lottie["layers"] for group in layer["shapes"] if group["nm"] == "lips"]
    assert len(lips) == 1 and lips[0]["it"][0]["ks"]["a"] == 1
    # A coarser tolerance needs fewer key frames.
    coarse = json.loads(animator.render_animation_lottie(animation, tolerance_px=3.0))
    coarse_lips = [group for layer in coarse["layers"] for group in layer["shapes"] if group["nm"] == "lips"]
    assert len(coarse_lips[0]["it"][0]["ks"]["k"]) < len(lips[0]["it"][0]["ks"]["k"])
    with pytest.raises(talkface.InvalidArgument, match="tolerance_px"):
        animator.render_animation_lottie(animation, tolerance_px=-1.0)
    path = tmp_path / "face.json"
    animator.write_animation_lottie(path, animation)
    assert json.loads(path.read_text()) == lottie
    with pytest.raises(talkface.FileError):
        animator.write_animation_lottie(tmp_path / "missing" / "face.json", animation)

"""talkface.render_video: the face as a video from Python; progress, cancel, refusals, and the GIL
released while frames are drawn and encoded."""
import base64
import gzip
import pathlib
import shutil
import subprocess
import threading
import time

import numpy
import pytest
from PIL import Image

import talkface


def animation_of(face, seconds, fps=10):
    timeline = talkface.Timeline()
    timeline.duration_s = seconds
    return talkface.animate(face, timeline, talkface.ExpressionSimulator(timeline, 1), talkface.LipSyncOptions(fps=fps))


def small(width=160, height=90, fps=10, layout=talkface.FrameLayout.face):
    return talkface.FaceVideoOptions(video=talkface.VideoOptions(width_px=width, height_px=height, fps=fps),
                                     layout=layout, background="#ffffff")


def test_progress_runs_from_zero_to_one_in_order(face, tmp_path):
    animation = animation_of(face, 1.0)
    seen = []
    talkface.render_video(str(tmp_path / "face.png"), face, animation, "", small(),
                          progress=lambda fraction, stage: seen.append((fraction, stage)))
    frames = sorted(p.name for p in tmp_path.iterdir())
    assert frames[0] == "face-000000.png" and len(frames) == len(animation.frames)
    fractions = [fraction for fraction, _ in seen]
    assert fractions[0] == 0.0 and fractions[-1] == 1.0
    assert fractions == sorted(fractions)
    assert {stage for _, stage in seen} == {"video"}


def test_cancel_leaves_no_file(face, tmp_path):
    animation = animation_of(face, 1.0)
    calls = []

    def stop_half_way(fraction, stage):
        calls.append(fraction)
        return fraction < 0.5

    with pytest.raises(talkface.Cancelled, match="video cancelled at frame"):
        talkface.render_video(str(tmp_path / "cancelled.mp4"), face, animation, "", small(), progress=stop_half_way)
    assert 0.5 <= calls[-1] < 1.0
    assert list(tmp_path.iterdir()) == []


def test_an_exception_in_progress_cancels_and_comes_through(face, tmp_path):
    def fail(fraction, stage):
        raise KeyError("from the callback")

    with pytest.raises(KeyError, match="from the callback"):
        talkface.render_video(str(tmp_path / "a.webm"), face, animation_of(face, 0.5), "", small(), progress=fail)
    assert list(tmp_path.iterdir()) == []


def test_refusals_name_what_is_wrong_and_leave_no_file(face, tmp_path):
    animation = animation_of(face, 0.5)
    with pytest.raises(talkface.InvalidArgument, match=r'unknown extension "\.avi"'):
        talkface.render_video(str(tmp_path / "a.avi"), face, animation, "", small())
    with pytest.raises(talkface.InvalidArgument, match="width_px.*even width and height"):
        talkface.render_video(str(tmp_path / "a.mp4"), face, animation, "", small(width=161))
    with pytest.raises(talkface.InvalidArgument, match="7680x4320"):
        talkface.render_video(str(tmp_path / "a.mp4"), face, animation, "", small(width=7682))
    with pytest.raises(talkface.InvalidArgument, match="fps.*1..120"):
        talkface.render_video(str(tmp_path / "a.mp4"), face, animation, "", small(fps=121))
    with pytest.raises(talkface.FileError, match="missing.wav"):
        talkface.render_video(str(tmp_path / "a.mp4"), face, animation, str(tmp_path / "missing.wav"), small())
    with pytest.raises(talkface.FileError, match="missing.png"):
        options = small()
        options.background_image_path = str(tmp_path / "missing.png")
        talkface.render_video(str(tmp_path / "a.mp4"), face, animation, "", options)
    with pytest.raises(TypeError):
        talkface.FaceVideoOptions(layout="face")
    assert list(tmp_path.iterdir()) == []


def test_another_python_thread_runs_while_a_video_is_made(face, tmp_path):
    animation = animation_of(face, 3.0, fps=30)
    options = small(width=640, height=360, fps=30, layout=talkface.FrameLayout.announcer)
    ticks = []
    done = threading.Event()

    def tick():
        while not done.is_set():
            ticks.append(time.perf_counter())
            time.sleep(0.001)

    ticker = threading.Thread(target=tick)
    ticker.start()
    try:
        started = time.perf_counter()
        talkface.render_video(str(tmp_path / "a.mp4"), face, animation, "", options)
        finished = time.perf_counter()
    finally:
        done.set()
        ticker.join()
    during = [t for t in ticks if started < t < finished]
    # With the GIL held the ticker would stand still for the whole call; released, it wakes about
    # every millisecond (a loaded machine gives it fewer turns, never none).
    assert finished - started > 0.05
    assert len(during) >= 10
    assert max(b - a for a, b in zip([started] + during, during + [finished])) < 0.5 * (finished - started)


def test_options_keep_what_they_are_given():
    options = talkface.FaceVideoOptions(layout=talkface.FrameLayout.face, background=None, face_origin_px=(320, 500),
                                        face_d_px=80)
    assert options.layout == talkface.FrameLayout.face
    assert options.background is None
    assert options.face_origin_px == (320, 500) and options.face_d_px == 80
    options.layout = talkface.FrameLayout.announcer
    assert options.layout == talkface.FrameLayout.announcer
    assert talkface.FaceVideoOptions().layout == talkface.FrameLayout.announcer
    assert talkface.FaceVideoOptions().look == talkface.FaceLook.outlined
    assert talkface.FaceVideoOptions(look=talkface.FaceLook.flat).look == talkface.FaceLook.flat


def test_the_flat_look_reaches_the_frames(face, tmp_path):
    animation = animation_of(face, 0.1)
    frames = {}
    for look in (talkface.FaceLook.outlined, talkface.FaceLook.flat):
        options = small(width=320, height=180)
        options.look = look
        folder = tmp_path / look.name
        folder.mkdir()
        talkface.render_video(str(folder / "face.png"), face, animation, "", options)
        frames[look] = numpy.asarray(Image.open(folder / "face-000000.png").convert("RGB")).astype(int)
    outlined, flat = frames[talkface.FaceLook.outlined], frames[talkface.FaceLook.flat]
    assert tuple(flat[0, 0]) == tuple(outlined[0, 0])
    assert numpy.abs(outlined - flat).max(axis=2).astype(bool).sum() > 200


def test_the_clothes_and_the_outline_width_reach_the_frames(face, tmp_path):
    # FrameOptions' clothes and outline, as tf_video_look_set_clothes and _set_stroke_width_in_d set them.
    options = talkface.FaceVideoOptions(draw_clothes=False, clothes="#c82828", stroke_width_in_d=0.05)
    assert not options.draw_clothes and options.clothes == "#c82828" and options.stroke_width_in_d == 0.05
    defaults = talkface.FaceVideoOptions()
    assert defaults.draw_clothes and defaults.clothes == "#2f4f7f" and defaults.stroke_width_in_d == 0.025
    animation = animation_of(face, 0.1)
    frames = {}
    for draw_clothes in (True, False):
        options = small(width=320, height=180)
        options.draw_clothes = draw_clothes
        folder = tmp_path / str(draw_clothes)
        folder.mkdir()
        talkface.render_video(str(folder / "face.png"), face, animation, "", options)
        frames[draw_clothes] = numpy.asarray(Image.open(folder / "face-000000.png").convert("RGB")).astype(int)
    assert numpy.abs(frames[True] - frames[False]).max(axis=2).astype(bool).sum() > 200
    options = small()
    options.stroke_width_in_d = -1.0
    with pytest.raises(talkface.InvalidArgument, match="stroke_width_in_d"):
        talkface.render_video(str(tmp_path / "bad.png"), face, animation, "", options)


RSVG_CONVERT = shutil.which("rsvg-convert")
SPEECH = pathlib.Path(__file__).resolve().parents[2] / "samples" / "speech" / "demo.ogg"
STAGE = "#1d3b5c"


def drawn_box(png_path):
    """The smallest box holding every pixel that is not the stage's colour: the face and its clothes."""
    pixels = numpy.asarray(Image.open(png_path).convert("RGB")).astype(int)
    stage = numpy.array([int(STAGE[k:k + 2], 16) for k in (1, 3, 5)])
    rows, columns = numpy.nonzero(numpy.abs(pixels - stage).sum(axis=2) > 30)
    return columns.min(), rows.min(), columns.max(), rows.max()


@pytest.mark.skipif(RSVG_CONVERT is None, reason="rsvg-convert is not installed")
@pytest.mark.parametrize("width, height", [(640, 360), (360, 640)])
def test_the_video_shows_the_face_where_the_announcer_page_does(face, tmp_path, width, height):
    timeline = talkface.read_transcript("媽媽好。")
    for k, syllable in enumerate(timeline.syllables):
        syllable.start_s, syllable.end_s = 0.5 + 0.25 * k, 0.75 + 0.25 * k
    timeline.syllables = list(timeline.syllables)
    timeline.duration_s = 2.0
    animation = talkface.animate(face, timeline, talkface.ExpressionSimulator(timeline, 3),
                                 talkface.LipSyncOptions(fps=10))
    page = talkface.build_web_page(talkface.SvgAnimator(face), animation, timeline, SPEECH,
                                   talkface.WebPageOptions(app=talkface.WebPageApp.announcer, stage_width_px=width,
                                                           stage_height_px=height, stage_colour=STAGE))
    # The stage's own SVG (background and placed face) as a browser draws it before the clock runs:
    # the animation's first frame, which the page's script unpacks into the stage's empty face.
    stage = page[page.index('<svg class="tf-stage-art"'):page.index('<div class="tf-lower-third')]
    stage = stage[:stage.rindex("</svg>") + len("</svg>")]
    packed = page.split('<script type="application/gzip" id="tf-animation-data">')[1].split("</script>")[0]
    face_tag = stage.index(">", stage.index('class="tf-animation"')) + 1
    assert stage[face_tag:].startswith("</svg>")
    # The face as animated (after a form feed comes the face with its head held still).
    content = gzip.decompress(base64.b64decode(packed)).decode().split("\f")[0]
    stage = stage[:face_tag] + content + stage[face_tag:]
    (tmp_path / "stage.svg").write_text(stage)
    subprocess.run([RSVG_CONVERT, "-w", str(width), "-h", str(height), str(tmp_path / "stage.svg"), "-o",
                    str(tmp_path / "page.png")], check=True)
    talkface.render_video(str(tmp_path / "video.png"), face, animation, "",
                          talkface.FaceVideoOptions(video=talkface.VideoOptions(width_px=width, height_px=height, fps=10),
                                                    background=STAGE))
    page_box = drawn_box(tmp_path / "page.png")
    video_box = drawn_box(tmp_path / "video-000000.png")
    assert all(abs(a - b) <= 1 for a, b in zip(page_box, video_box)), (page_box, video_box)
    assert page_box[3] >= height - 2  # the clothes reach the stage's bottom: something is drawn

"""`talkface video` and `talkface demo -o OUT.mp4`, run as a user runs them: the files are read back
with ffprobe and ffmpeg (frames decoded at an open vowel and in a pause), the refusals checked by
their messages, and Ctrl-C checked to leave nothing behind.

The bundled speech (samples/speech/demo.ogg, 12.95 s) is aligned once with `talkface align --json`;
the same audio and transcript give the video's times.
"""
import json
import os
import pathlib
import re
import shutil
import signal
import subprocess
import sys
import time

import pytest
from PIL import Image

sys.path.insert(0, str(pathlib.Path(__file__).parents[1] / "common"))
from mouth_pixels import mouth_inside_pixels  # noqa: E402

CLI = os.environ["TALKFACE_CLI"]
SPEECH_DIR = pathlib.Path(os.environ["TALKFACE_SOURCE_DIR"]) / "samples" / "speech"
SPEECH, TRANSCRIPT = SPEECH_DIR / "demo.ogg", SPEECH_DIR / "demo.txt"
SPEECH_S = 12.95
# 12 keeps the dark lip outline out of the mouth's inside after H.264.
MOUTH_TOLERANCE = 12
FFMPEG, FFPROBE = shutil.which("ffmpeg"), shutil.which("ffprobe")

pytestmark = pytest.mark.skipif(FFPROBE is None or FFMPEG is None, reason="ffmpeg is not installed")


def run(*args, check=True):
    return subprocess.run([CLI, *map(str, args)], capture_output=True, text=True, timeout=600, check=check)


def probe(path):
    out = subprocess.run([FFPROBE, "-v", "error", "-show_streams", "-show_format", "-of", "json", str(path)],
                         capture_output=True, text=True, check=True).stdout
    return json.loads(out)


def frame_at(video, time_s, png):
    subprocess.run([FFMPEG, "-v", "error", "-y", "-ss", f"{time_s:.3f}", "-i", str(video), "-frames:v", "1",
                    str(png)], check=True)
    return Image.open(png).convert("RGB")


@pytest.fixture(scope="module")
def alignment():
    return json.loads(run("align", SPEECH, TRANSCRIPT, "--json", "-q").stdout)


@pytest.fixture(scope="module")
def mp4(tmp_path_factory):
    # The default size, 1280x720: at 640x360 the open mouth's inside colour, between the teeth and
    # the tongue, is a band 3 pixels tall, and 4:2:0 chroma (one colour per 2x2 pixels) blends it
    # with its neighbours in any encoder: the lossless frame's 93 inside pixels become 57 after an
    # exact, uncompressed BT.709 4:2:0 round trip, so a count there measured the subsampling, not
    # the sync.
    path = tmp_path_factory.mktemp("video") / "talk.mp4"
    run("video", SPEECH, TRANSCRIPT, "-o", path, "-q")
    return path


def test_mp4_plays_in_browsers_and_lasts_as_long_as_the_speech(mp4):
    info = probe(mp4)
    video = next(s for s in info["streams"] if s["codec_type"] == "video")
    audio = next(s for s in info["streams"] if s["codec_type"] == "audio")
    assert (video["codec_name"], video["pix_fmt"], video["width"], video["height"]) == ("h264", "yuv420p", 1280, 720)
    # Tagged as converted, so that players convert back with the same matrix and range.
    assert (video["color_space"], video["color_range"], video["color_primaries"], video["color_transfer"]) == \
        ("bt709", "tv", "bt709", "bt709")
    assert audio["codec_name"] == "aac"
    assert float(video["start_time"]) == pytest.approx(0.0, abs=1e-6)
    assert float(audio["start_time"]) == pytest.approx(0.0, abs=1e-6)
    assert float(info["format"]["duration"]) == pytest.approx(SPEECH_S, abs=1 / 30)
    assert float(video["duration"]) == pytest.approx(SPEECH_S, abs=1 / 30)
    assert eval(video["r_frame_rate"]) == 30  # noqa: S307 - "30/1" from ffprobe
    head = mp4.read_bytes()
    assert head.find(b"moov") < head.find(b"mdat")  # faststart


def open_vowel_time(alignment):
    """The middle of the vowel of the longest syllable whose final is a / ai / ao / an / ang."""
    open_finals = [s for s in alignment["syllables"] if re.fullmatch(r"[a-z]*?[^iuv]?a[oin]?g?\d", s["pinyin"])]
    syllable = max(open_finals, key=lambda s: s["end"] - s.get("final_start", s["start"]))
    vowel_start = syllable.get("final_start", syllable["start"])
    return vowel_start + 0.6 * (syllable["end"] - vowel_start)


def test_mouth_is_open_in_a_vowel_and_closed_in_a_pause(mp4, alignment, tmp_path):
    vowel_s = open_vowel_time(alignment)
    pause_s = alignment["syllables"][0]["start"] / 2
    open_pixels = mouth_inside_pixels(frame_at(mp4, vowel_s, tmp_path / "vowel.png"), MOUTH_TOLERANCE)
    closed_pixels = mouth_inside_pixels(frame_at(mp4, pause_s, tmp_path / "pause.png"), MOUTH_TOLERANCE)
    assert open_pixels > 60, f"mouth at {vowel_s:.3f} s shows {open_pixels} inside pixels"
    assert closed_pixels < 10, f"mouth at {pause_s:.3f} s shows {closed_pixels} inside pixels"


def test_transparent_webm_keeps_alpha(tmp_path):
    path = tmp_path / "alpha.webm"
    run("video", SPEECH, TRANSCRIPT, "-o", path, "-q", "--size", "320x180", "--fps", "10", "--transparent")
    info = probe(path)
    codecs = sorted(s["codec_name"] for s in info["streams"])
    assert codecs == ["opus", "vp9"]
    video = next(s for s in info["streams"] if s["codec_type"] == "video")
    assert video.get("tags", {}).get("alpha_mode") == "1"


def test_png_sequence_and_webp(tmp_path):
    run("video", SPEECH, TRANSCRIPT, "-o", tmp_path / "f.png", "-q", "--size", "161x91", "--fps", "2")
    frames = sorted(p.name for p in tmp_path.glob("f-*.png"))
    assert len(frames) == 26 and frames[0] == "f-000000.png"  # ceil(12.95 * 2)
    assert Image.open(tmp_path / frames[0]).size == (161, 91)
    run("video", SPEECH, TRANSCRIPT, "-o", tmp_path / "chat.webp", "-q", "--size", "160x90", "--fps", "5")
    assert (tmp_path / "chat.webp").read_bytes()[8:12] == b"WEBP"


def test_gif_has_a_frame_per_step_and_lasts_as_long_as_the_speech(tmp_path):
    path = tmp_path / "chat.gif"
    run("video", SPEECH, TRANSCRIPT, "-o", path, "-q", "--size", "161x91", "--fps", "5")
    assert path.read_bytes()[:6] == b"GIF89a"
    out = subprocess.run([FFPROBE, "-v", "error", "-count_frames", "-show_streams", "-show_format", "-of", "json",
                          str(path)], capture_output=True, text=True, check=True).stdout
    info = json.loads(out)
    assert [(s["codec_name"], s["width"], s["height"]) for s in info["streams"]] == [("gif", 161, 91)]
    assert int(info["streams"][0]["nb_read_frames"]) == 65  # ceil(12.95 * 5)
    assert float(info["format"]["duration"]) == pytest.approx(SPEECH_S, abs=1 / 5)
    assert list(tmp_path.iterdir()) == [path]


@pytest.mark.parametrize("args,message", [
    (["-o", "talk.avi"], 'unknown extension ".avi"'),
    (["-o", "talk.mp4", "--size", "641x360"], "needs an even width and height"),
    (["-o", "talk.mp4", "--size", "8000x4000"], "over the largest, 7680x4320"),
    (["-o", "talk.mp4", "--size", "big"], "expected WIDTHxHEIGHT"),
    (["-o", "talk.mp4", "--fps", "0"], "--fps"),
    (["-o", "talk.mp4", "--fps", "121"], "--fps"),
    (["-o", "talk.gif", "--fps", "60"], "expected 1..50 frames per second for .gif"),
    (["-o", "talk.gif", "--size", "8000x4000"], "over the largest, 7680x4320"),
    (["-o", "talk.mp4", "--transparent"], "no alpha channel"),
    (["-o", "talk.mp4", "--crf", "60"], "crf: expected 0..51"),
])
def test_bad_input_is_refused_by_name_and_leaves_no_file(tmp_path, args, message):
    args = [str(tmp_path / a) if a.startswith("talk.") else a for a in args]
    result = run("video", SPEECH, TRANSCRIPT, "-q", *args, check=False)
    assert result.returncode == 2, result.stderr
    assert message in result.stderr
    assert list(tmp_path.iterdir()) == []


def test_ctrl_c_leaves_no_file(tmp_path):
    path = tmp_path / "long.mp4"
    process = subprocess.Popen([CLI, "video", str(SPEECH), str(TRANSCRIPT), "-o", str(path), "-q",
                                "--size", "1920x1080", "--fps", "60"], stderr=subprocess.PIPE, text=True)
    deadline = time.monotonic() + 60
    while time.monotonic() < deadline and not any(p.name.startswith("long.mp4.tmp") for p in tmp_path.iterdir()):
        time.sleep(0.05)
    process.send_signal(signal.SIGINT)
    _, stderr = process.communicate(timeout=120)
    assert process.returncode == 130, stderr
    assert "interrupted" in stderr
    assert list(tmp_path.iterdir()) == []


def test_demo_makes_an_mp4_of_the_built_in_face(tmp_path):
    path = tmp_path / "demo.mp4"
    run("demo", "-o", path, "-q")
    info = probe(path)
    video = next(s for s in info["streams"] if s["codec_type"] == "video")
    assert (video["width"], video["height"], eval(video["r_frame_rate"])) == (1280, 720, 30)  # noqa: S307
    assert float(info["format"]["duration"]) == pytest.approx(SPEECH_S, abs=1 / 30)


def test_clothes_outline_and_face_placement_change_the_frames(tmp_path):
    def frame(name, *args):
        run("video", SPEECH, TRANSCRIPT, "-o", tmp_path / f"{name}.png", "-q", "--size", "160x90", "--fps", "1",
            *args)
        return Image.open(tmp_path / f"{name}-000005.png").convert("RGB")
    plain = frame("plain")
    for name, args in [("bare", ["--no-clothes"]), ("wide", ["--stroke-width", "0.08"]),
                       ("placed", ["--face-origin", "40,80", "--face-d", "20"])]:
        assert frame(name, *args).tobytes() != plain.tobytes(), name
    # Placed left and small on the announcer's stage, the face leaves the frame's right part as the background.
    placed = frame("placed", "--face-origin", "40,80", "--face-d", "20")
    assert len(set(placed.crop((100, 0, 160, 90)).getdata())) == 1


def test_a_bad_face_placement_is_refused_by_name(tmp_path):
    for args, name in [(["--face-d", "0"], "--face-d"), (["--face-origin", "40"], "--face-origin")]:
        result = run("video", SPEECH, TRANSCRIPT, "-q", "-o", tmp_path / "talk.mp4", *args, check=False)
        assert result.returncode == 2 and f"{name}:" in result.stderr, result.stderr
    assert list(tmp_path.iterdir()) == []

"""talkface.VideoWriter: frames from numpy, sound from numpy or a file, read back with ffprobe."""
import json
import shutil
import subprocess
import threading

import numpy
import pytest

import talkface

FFPROBE = shutil.which("ffprobe")


def pattern(index, width=160, height=120):
    frame = numpy.zeros((height, width, 4), numpy.uint8)
    frame[..., 0], frame[..., 1], frame[..., 2], frame[..., 3] = 40, 90, 160, 255
    left = 8 + 4 * index
    frame[50:70, left:left + 20] = (220, 30, 40, 255)
    return frame


def probe(path):
    out = subprocess.run([FFPROBE, "-v", "error", "-show_streams", "-show_format", "-of", "json", str(path)],
                         capture_output=True, text=True, check=True).stdout
    return json.loads(out)


@pytest.mark.skipif(FFPROBE is None, reason="ffprobe is not installed")
def test_mp4_of_numpy_frames_and_sound(tmp_path):
    path = tmp_path / "talk.mp4"
    options = talkface.VideoOptions(width_px=160, height_px=120, fps=25)
    sound = (0.3 * numpy.sin(numpy.arange(16000) * 2 * numpy.pi * 200 / 16000)).astype(numpy.float32)
    with talkface.VideoWriter(str(path), options) as video:
        video.add_audio(sound, 16000)
        assert video.format == talkface.VideoFormat.mp4
        for k in range(25):
            video.write_frame(pattern(k))
        assert video.frame_count == 25
        assert not path.exists()
    info = probe(path)
    codecs = sorted(stream["codec_name"] for stream in info["streams"])
    assert codecs == ["aac", "h264"]
    assert abs(float(info["format"]["duration"]) - 1.0) < 1 / 25


def test_an_exception_in_the_block_leaves_no_file(tmp_path):
    path = tmp_path / "talk.webm"
    with pytest.raises(RuntimeError):
        with talkface.VideoWriter(str(path), talkface.VideoOptions(width_px=160, height_px=120)) as video:
            video.write_frame(pattern(0))
            raise RuntimeError("stop")
    assert list(tmp_path.iterdir()) == []
    with pytest.raises(talkface.InvalidArgument, match="abandoned"):
        video.write_frame(pattern(1))


def test_png_sequence(tmp_path):
    with talkface.VideoWriter(str(tmp_path / "f.png"), talkface.VideoOptions(width_px=33, height_px=21)) as video:
        for k in range(2):
            video.write_frame(pattern(k, 33, 21))
    assert sorted(p.name for p in tmp_path.iterdir()) == ["f-000000.png", "f-000001.png"]


@pytest.mark.skipif(FFPROBE is None, reason="ffprobe is not installed")
def test_gif_of_numpy_frames(tmp_path):
    path = tmp_path / "chat.gif"
    with talkface.VideoWriter(str(path), talkface.VideoOptions(width_px=160, height_px=120, fps=20)) as video:
        assert video.format == talkface.VideoFormat.gif
        for k in range(10):
            video.write_frame(pattern(k))
    out = subprocess.run([FFPROBE, "-v", "error", "-count_frames", "-show_streams", "-show_format", "-of", "json",
                          str(path)], capture_output=True, text=True, check=True).stdout
    info = json.loads(out)
    assert [s["codec_name"] for s in info["streams"]] == ["gif"]
    assert int(info["streams"][0]["nb_read_frames"]) == 10
    assert abs(float(info["format"]["duration"]) - 0.5) <= 1 / 20


def test_bad_input_is_named(tmp_path):
    with pytest.raises(talkface.InvalidArgument, match=r'unknown extension "\.avi"'):
        talkface.VideoWriter(str(tmp_path / "a.avi"))
    with pytest.raises(talkface.InvalidArgument, match="even width and height"):
        talkface.check_video_options("a.mp4", talkface.VideoOptions(width_px=1281))
    with pytest.raises(talkface.InvalidArgument, match="fps"):
        talkface.VideoWriter(str(tmp_path / "a.mp4"), talkface.VideoOptions(fps=0.5))
    with pytest.raises(talkface.InvalidArgument, match=r"fps: expected 1\.\.50 frames per second for \.gif"):
        talkface.VideoWriter(str(tmp_path / "a.gif"), talkface.VideoOptions(fps=60))
    video = talkface.VideoWriter(str(tmp_path / "a.mp4"), talkface.VideoOptions(width_px=160, height_px=120))
    with pytest.raises(talkface.InvalidArgument, match=r"expected shape \(120, 160, 4\) uint8, got \(120, 160, 3\)"):
        video.write_frame(numpy.zeros((120, 160, 3), numpy.uint8))
    with pytest.raises(talkface.FileError):
        video.add_audio_file(str(tmp_path / "missing.wav"))
    del video
    assert list(tmp_path.iterdir()) == []
    assert talkface.video_format_from_path("X.WEBP") == talkface.VideoFormat.webp


def test_two_writers_on_two_threads(tmp_path):
    def write(name):
        with talkface.VideoWriter(str(tmp_path / name), talkface.VideoOptions(width_px=160, height_px=120)) as video:
            for k in range(20):
                video.write_frame(pattern(k))
    threads = [threading.Thread(target=write, args=(name,)) for name in ("a.mp4", "b.mp4")]
    for thread in threads:
        thread.start()
    for thread in threads:
        thread.join()
    assert (tmp_path / "a.mp4").read_bytes() == (tmp_path / "b.mp4").read_bytes()

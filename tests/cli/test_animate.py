"""`talkface animate` and `talkface demo`: pages and bare animations from a speech, the audio
embedded or linked, usage errors, and failures that leave no file behind."""
import base64
import gzip
import os
import pathlib
import re
import shutil
import subprocess
import xml.dom.minidom

import pytest

CLI = os.environ["TALKFACE_CLI"]
SPEECH = pathlib.Path(os.environ["TALKFACE_SOURCE_DIR"]) / "samples" / "speech"


def run(*args):
    return subprocess.run([CLI, *map(str, args)], capture_output=True, text=True, timeout=120)


def test_demo_makes_a_self_contained_page(tmp_path):
    page = tmp_path / "demo.html"
    result = run("demo", "-o", page)
    assert result.returncode == 0, result.stderr
    html = page.read_text(encoding="utf-8")
    assert html.startswith("<!DOCTYPE html>")
    assert "data:audio/webm;base64," in html
    packed = html.split('<script type="application/gzip" id="tf-animation-data">')[1].split("</script>")[0]
    assert "<animate " in gzip.decompress(base64.b64decode(packed)).decode()
    assert "大家好" in html
    # No bar when stderr is not a terminal; one line saying what was written, how long and how large.
    assert re.fullmatch(r"talkface: wrote \S+demo\.html: plain web page, audio compressed and embedded, \d+\.\d\d s, "
                        r"\d+\.\d [kM]B\n", result.stderr), result.stderr
    number, unit = result.stderr.split(", ")[-1].split()
    scale = {"kB": 1e3, "MB": 1e6}[unit]
    assert abs(float(number) * scale - page.stat().st_size) <= 0.05 * scale


def test_quiet_says_nothing_and_the_svg_report_names_its_encoding(tmp_path):
    svg = tmp_path / "talk.svg"
    quiet = run("demo", "--quiet", "-o", tmp_path / "quiet.html")
    assert quiet.returncode == 0 and quiet.stderr == "", quiet.stderr
    result = run("demo", "-o", svg)
    assert result.returncode == 0, result.stderr
    assert result.stderr.startswith(f"talkface: wrote {svg}: SVG animation (keyframes), "), result.stderr
    seconds = float(result.stderr.split(", ")[1].split()[0])
    assert 3.0 < seconds < 30.0


@pytest.mark.skipif(shutil.which("ffmpeg") is None, reason="ffmpeg is not installed")
def test_a_page_takes_under_200_kib_a_minute_of_speech(tmp_path):
    # The demo speech five times over (65 s) and its transcript as often: the face's packed
    # animation and the compressed speech grow with the speech, the script and style do not.
    # 200 KiB is issue 17's aim, with the head held still for a reader who asks for reduced motion
    # (WCAG 2.3.3): the face is drawn at rest and the pose carried apart in additive animations the
    # page takes out (178.0 KiB a minute here; 217.2 when the still face was a second animation).
    (tmp_path / "list.txt").write_text(f"file '{SPEECH / 'demo.ogg'}'\n" * 5)
    subprocess.run(["ffmpeg", "-v", "error", "-f", "concat", "-safe", "0", "-i", tmp_path / "list.txt", "-ac", "1",
                    "-ar", "16000", tmp_path / "long.wav"], check=True, timeout=60)
    (tmp_path / "long.txt").write_text(((SPEECH / "demo.txt").read_text(encoding="utf-8") + "\n") * 5, encoding="utf-8")
    page = tmp_path / "long.html"
    result = run("animate", tmp_path / "long.wav", tmp_path / "long.txt", "-o", page)
    assert result.returncode == 0, result.stderr
    seconds = float(re.search(r", (\d+\.\d\d) s, ", result.stderr).group(1))
    assert seconds > 60
    kib_per_minute = page.stat().st_size / 1024 / (seconds / 60)
    assert kib_per_minute < 200, f"{kib_per_minute:.1f} KiB a minute"


def test_demo_links_its_audio_beside_the_page(tmp_path):
    page = tmp_path / "linked.html"
    result = run("demo", "--link-audio", "-o", page)
    assert result.returncode == 0, result.stderr
    assert result.stderr.startswith(f"talkface: wrote {tmp_path / 'linked.ogg'}: the demo speech (Ogg Vorbis), ")
    assert f"talkface: wrote {page}: plain web page, audio linked, " in result.stderr
    assert 'src="linked.ogg"' in page.read_text(encoding="utf-8")
    assert (tmp_path / "linked.ogg").read_bytes() == (SPEECH / "demo.ogg").read_bytes()


def test_animate_embeds_the_audio_as_it_is_when_asked(tmp_path):
    page = tmp_path / "original.html"
    result = run("animate", SPEECH / "demo.ogg", SPEECH / "demo.txt", "--audio-embed", "original", "-o", page)
    assert result.returncode == 0, result.stderr
    assert "audio embedded as it is" in result.stderr
    assert "data:audio/ogg;base64," in page.read_text(encoding="utf-8")
    refused = run("animate", SPEECH / "demo.ogg", SPEECH / "demo.txt", "--audio-bitrate", "1000", "-o", page)
    assert refused.returncode == 2 and "--audio-bitrate" in refused.stderr


@pytest.mark.parametrize("embed", ["original", "link"])
def test_a_recording_browsers_do_not_play_is_refused_as_it_is_with_advice(tmp_path, embed):
    # A voice mail's GSM 06.10 WAV: the page was written and Chromium said, on it, that it could
    # not play the speech. Refused, naming the file, the codec and what to do; no page written.
    gsm = tmp_path / "voicemail.wav"
    subprocess.run(["ffmpeg", "-nostdin", "-loglevel", "error", "-i", SPEECH / "demo.ogg", "-ar", "8000", "-ac", "1",
                    "-c:a", "libgsm_ms", gsm], check=True)
    page = tmp_path / "voicemail.html"
    result = run("animate", gsm, SPEECH / "demo.txt", "--audio-embed", embed, "-o", page)
    assert result.returncode == 1
    assert result.stderr.startswith(f"talkface: error: {gsm}: cannot be "), result.stderr
    assert "GSM 6.10" in result.stderr and "embed it compressed" in result.stderr
    assert not page.exists()
    # The default, compressed, plays it.
    assert run("animate", gsm, SPEECH / "demo.txt", "-o", page).returncode == 0


def test_a_format_no_browser_plays_is_refused_by_its_file_name(tmp_path):
    # A recording talkface reads and no browser plays (a phone's AMR memo took this path too; Debian's
    # FFmpeg has no AMR encoder to make one here): the message named the library's parameter
    # ("audio_path"), not the file.
    memo = tmp_path / "memo.aiff"
    subprocess.run(["ffmpeg", "-nostdin", "-loglevel", "error", "-i", SPEECH / "demo.ogg", memo], check=True)
    page = tmp_path / "memo.html"
    result = run("animate", memo, SPEECH / "demo.txt", "--audio-embed", "original", "-o", page)
    assert result.returncode == 1
    assert result.stderr.startswith(f"talkface: error: {memo}: cannot be embedded as it is"), result.stderr
    assert "embed it compressed" in result.stderr and "audio_path" not in result.stderr
    assert not page.exists()


def test_animate_writes_the_bare_animation_as_svg(tmp_path):
    svg = tmp_path / "talk.svg"
    result = run("animate", SPEECH / "demo.ogg", SPEECH / "demo.txt", "--encoding", "frames", "-o", svg)
    assert result.returncode == 0, result.stderr
    root = xml.dom.minidom.parse(str(svg)).documentElement
    assert root.getAttribute("class") == "tf-animation"
    assert "<set " in svg.read_text()


def test_animate_links_the_audio_by_a_relative_path(tmp_path):
    page = tmp_path / "sub" / "page.html"
    page.parent.mkdir()
    assert run("animate", SPEECH / "demo.ogg", SPEECH / "demo.txt", "--link-audio", "-o", page).returncode == 0
    html = page.read_text(encoding="utf-8")
    src = html.split('<audio id="tf-audio"')[1].split(' src="')[1].split('"')[0]
    assert (page.parent / src).resolve() == (SPEECH / "demo.ogg").resolve()


def test_an_svg_output_refuses_page_options(tmp_path):
    result = run("demo", "--app", "audiobook", "-o", tmp_path / "x.svg")
    assert result.returncode == 2
    assert "--app" in result.stderr


def test_a_script_link_fails_and_keeps_the_old_page(tmp_path):
    page = tmp_path / "book.html"
    page.write_text("old")
    result = run("demo", "--app", "audiobook", "--link", "x=javascript:alert(1)", "-o", page)
    assert result.returncode == 1
    assert "links[0].url" in result.stderr
    assert page.read_text() == "old"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["book.html"]


def test_a_bad_background_image_is_named(tmp_path):
    image = tmp_path / "back.txt"
    image.write_text("not an image")
    result = run("demo", "--app", "announcer", "--background", image, "-o", tmp_path / "news.html")
    assert result.returncode == 1
    assert "background_image_path" in result.stderr
    assert not (tmp_path / "news.html").exists()


def test_demo_takes_a_style_file_and_kinds_switched_off(tmp_path):
    style = tmp_path / "calm.json"
    style.write_text('{"base": "announcer", "blink_interval_scale_s": 3.0}', encoding="utf-8")
    page = tmp_path / "calm.html"
    result = run("demo", "--style", style, "--without", "tilt,turn,nod", "-o", page)
    assert result.returncode == 0, result.stderr
    assert page.read_text(encoding="utf-8").startswith("<!DOCTYPE html>")


def test_a_bad_style_file_fails_before_the_alignment_and_writes_nothing(tmp_path):
    style = tmp_path / "loud.json"
    style.write_text('{\n  "turn_angle_deg": [5, 25]\n}', encoding="utf-8")
    page = tmp_path / "page.html"
    for command in (["demo"], ["animate", SPEECH / "demo.ogg", SPEECH / "demo.txt"]):
        result = run(*command, "--style", style, "-o", page)
        assert result.returncode == 1
        assert result.stderr.startswith(f'talkface: error: {style}:2:21: key "turn_angle_deg": expected a range'), \
            result.stderr
        assert not page.exists()
    assert run("demo", "--without", "wink", "-o", page).returncode == 2


@pytest.fixture(scope="module")
def default_svg(tmp_path_factory):
    svg = tmp_path_factory.mktemp("default") / "talk.svg"
    assert run("demo", "-q", "-o", svg).returncode == 0
    return svg.read_text(encoding="utf-8")


@pytest.mark.parametrize("args", [["--max-mouth-speed", "2"], ["--mouth-interpolation", "smooth"],
                                  ["--rest-min-pause", "1"], ["--rest-transition", "0.2"]])
def test_the_lip_sync_options_move_the_mouth_otherwise(tmp_path, default_svg, args):
    svg = tmp_path / "talk.svg"
    assert run("demo", "-q", *args, "-o", svg).returncode == 0
    assert svg.read_text(encoding="utf-8") != default_svg


def test_outline_width_clothes_and_tolerance_change_the_drawing(tmp_path, default_svg):
    # The built-in face's d is 65 px: 0.025 d is 1.62 px, 0.05 d 3.25 px.
    assert 'stroke-width="3.25"' not in default_svg and '<path class="shirt"' in default_svg
    wide = tmp_path / "wide.svg"
    assert run("demo", "-q", "--stroke-width", "0.05", "-o", wide).returncode == 0
    assert 'stroke-width="3.25"' in wide.read_text(encoding="utf-8")
    bare = tmp_path / "bare.svg"
    assert run("demo", "-q", "--no-clothes", "-o", bare).returncode == 0
    assert '<path class="shirt"' not in bare.read_text(encoding="utf-8")
    coarse = tmp_path / "coarse.svg"
    assert run("demo", "-q", "--tolerance", "3", "-o", coarse).returncode == 0
    assert coarse.stat().st_size < 0.8 * len(default_svg.encode())


@pytest.mark.parametrize("args,name", [
    (["--max-mouth-speed", "0"], "--max-mouth-speed"), (["--mouth-interpolation", "cubic"], "--mouth-interpolation"),
    (["--rest-min-pause", "-1"], "--rest-min-pause"), (["--rest-transition", "-0.1"], "--rest-transition"),
    (["--stroke-width", "0"], "--stroke-width"), (["--tolerance", "0"], "--tolerance")])
def test_a_bad_drawing_or_lip_sync_value_is_refused_by_name(tmp_path, args, name):
    page = tmp_path / "talk.html"
    result = run("demo", *args, "-o", page)
    assert result.returncode == 2 and f"{name}:" in result.stderr, result.stderr
    assert not page.exists()

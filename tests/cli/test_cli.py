"""The talkface command: exit codes, messages, and outputs that are whole or absent."""
import os
import pathlib
import re
import subprocess
import xml.etree.ElementTree as ET

import pytest

CLI = os.environ["TALKFACE_CLI"]
SOURCE_DIR = pathlib.Path(os.environ.get("TALKFACE_SOURCE_DIR", pathlib.Path(__file__).parents[2]))
MALE_FACE = SOURCE_DIR / "samples" / "faces" / "male.xml"
SVG_NS = "{http://www.w3.org/2000/svg}"


def run(*args):
    return subprocess.run([CLI, *map(str, args)], capture_output=True, text=True, timeout=60)


def layer_ids(svg_text):
    root = ET.fromstring(svg_text.encode())
    return [g.get("id") for g in root.findall(SVG_NS + "g")]


def test_render_writes_a_valid_svg(tmp_path):
    out = tmp_path / "face.svg"
    result = run("render", "--pose", "5,-10,3", "--mouth", "a", "--blink", "0.5", "--smile", "0.3",
                 "-o", out)
    assert result.returncode == 0, result.stderr
    assert result.stdout == ""
    assert layer_ids(out.read_text()) == ["background", "hair", "clothes", "face"]


def test_render_to_stdout_prints_the_document_only():
    result = run("render", "-o", "-")
    assert result.returncode == 0, result.stderr
    assert result.stdout.startswith("<?xml")
    assert layer_ids(result.stdout) == ["background", "hair", "clothes", "face"]


def test_background_none_and_no_clothes_empty_those_layers():
    result = run("render", "--background", "none", "--no-clothes", "-o", "-")
    assert result.returncode == 0, result.stderr
    root = ET.fromstring(result.stdout.encode())
    groups = {g.get("id"): g for g in root.findall(SVG_NS + "g")}
    assert len(groups["background"]) == 0
    assert len(groups["clothes"]) == 0


def test_look_flat_draws_without_outlines_and_an_unknown_look_is_a_usage_error():
    result = run("render", "--look", "flat", "-o", "-")
    assert result.returncode == 0, result.stderr
    # No outline but the upper lids' bands.
    stroked = [e for e in ET.fromstring(result.stdout.encode()).iter() if e.get("stroke-width") is not None]
    assert sorted(e.get("class") for e in stroked) == ["eye-left-lid", "eye-right-lid"]
    assert "stroke-width" in run("render", "-o", "-").stdout
    refused = run("render", "--look", "sketch", "-o", "-")
    assert refused.returncode == 2
    assert '--look: expected outlined or flat, found "sketch"' in refused.stderr


def test_an_unknown_audio_embedding_is_a_usage_error_listing_the_choices(tmp_path):
    refused = run("demo", "--audio-embed", "wav", "-o", tmp_path / "page.html")
    assert refused.returncode == 2
    assert '--audio-embed: expected compressed, original or link, found "wav"' in refused.stderr
    assert not (tmp_path / "page.html").exists()
    assert "--audio-embed TEXT:{compressed,original,link}=compressed" in run("demo", "--help").stdout


def test_help_exits_0_and_lists_exit_codes():
    result = run("--help")
    assert result.returncode == 0
    for line in ("0    success", "1    the work failed", "2    usage error", "3    internal error",
                 "130  interrupted"):
        assert line in result.stdout
    assert "render" in result.stdout


def test_every_command_that_reads_a_speech_lists_the_same_formats():
    # export listed "WAV, FLAC, OGG" while it read MP3, M4A, Opus and AMR as align does.
    helps = {command: run(command, "--help").stdout for command in ("align", "animate", "video", "export", "keyframes")}
    for command, text in helps.items():
        audio = next(line for line in text.splitlines() if line.strip().startswith("AUDIO"))
        for name in ("WAV", "FLAC", "Ogg", "MP3", "M4A", "Opus", "AMR", "MP4", "MOV", "MKV", "WebM"):
            assert name in audio, f"{command}: {audio}"


def test_version_prints_the_version():
    result = run("--version")
    assert result.returncode == 0
    assert result.stdout.strip().count(".") == 2


@pytest.mark.parametrize("args", [
    ["render"],                                        # -o is required
    ["render", "--no-such-option", "-o", "-"],
    ["render", "--pose", "1,2", "-o", "-"],
    ["render", "--pose", "a,b,c", "-o", "-"],
    ["render", "--mouth", "x", "-o", "-"],
    ["render", "--blink", "1.5", "-o", "-"],
    ["render", "--background", "blue", "-o", "-"],
    [],                                                # a subcommand is required
])
def test_usage_errors_exit_2(args):
    result = run(*args)
    assert result.returncode == 2, result.stderr
    assert result.stdout == ""
    assert result.stderr


def test_malformed_pose_is_explained():
    result = run("render", "--pose", "1;2;3", "-o", "-")
    assert result.returncode == 2
    assert "--pose" in result.stderr
    assert "ALPHA,BETA,GAMMA" in result.stderr


def test_missing_face_file_is_named(tmp_path):
    missing = tmp_path / "no-such-face.xml"
    result = run("render", "--face", missing, "-o", tmp_path / "out.svg")
    assert result.returncode in (1, 2)
    assert str(missing) in result.stderr
    assert not (tmp_path / "out.svg").exists()


def assert_failed_without_output(result, out, *names):
    assert result.returncode == 1, result.stderr
    assert result.stderr.startswith("talkface: error: ")
    for name in names:
        assert name in result.stderr
    assert result.stdout == ""
    assert not out.exists()
    assert list(out.parent.glob(out.name + "*")) == []


@pytest.mark.skipif(not MALE_FACE.exists(), reason="samples/faces/male.xml is not there")
def test_face_file_missing_a_point_exits_1_naming_file_and_line(tmp_path):
    lines = MALE_FACE.read_text().splitlines(keepends=True)
    dropped = next(i for i, line in enumerate(lines) if 'id="8.3"' in line)
    broken = tmp_path / "broken.xml"
    broken.write_text("".join(lines[:dropped] + lines[dropped + 1:]))
    out = tmp_path / "out.svg"
    result = run("render", "--face", broken, "-o", out)
    assert_failed_without_output(result, out, str(broken) + ":", "8.3")


def test_face_file_that_is_not_xml_exits_1_naming_file_and_line(tmp_path):
    broken = tmp_path / "not-xml.xml"
    broken.write_text("<talkface-face version=\"1\">\n  <points>\n    <point id=\"11.1\" x=\"1\"\n")
    out = tmp_path / "out.svg"
    result = run("render", "--face", broken, "-o", out)
    assert_failed_without_output(result, out, str(broken) + ":")
    assert any(ch.isdigit() for ch in result.stderr.split(str(broken) + ":")[1][:3])


def test_existing_output_survives_a_failure(tmp_path):
    out = tmp_path / "out.svg"
    out.write_text("keep me")
    result = run("render", "--pose", "0,20,0", "-o", out)
    assert result.returncode == 1
    assert out.read_text() == "keep me"


@pytest.mark.parametrize("pose, angle", [("20,0,0", "alpha"), ("0,-16,0", "beta"), ("0,0,15.5", "gamma")])
def test_pose_out_of_range_names_the_angle_and_writes_nothing(tmp_path, pose, angle):
    out = tmp_path / "out.svg"
    result = run("render", "--pose", pose, "-o", out)
    assert result.returncode in (1, 2)
    assert result.stderr.startswith("talkface: error: ")
    assert angle in result.stderr
    assert not out.exists()


def path_numbers(svg_text):
    return re.findall(r"-?\d+(?:\.\d+)?", " ".join(re.findall(r' d="([^"]*)"', svg_text)))


def test_render_takes_the_outline_width_and_the_decimals(tmp_path):
    default = run("render", "-o", "-").stdout
    assert any("." in number for number in path_numbers(default))
    result = run("render", "--decimals", "0", "--stroke-width", "0.05", "-o", "-")
    assert result.returncode == 0, result.stderr
    # The built-in face's d is 65 px: 0.05 d is 3.25 px, where the default 0.025 d is 1.62.
    assert 'stroke-width="3.25"' in result.stdout and 'stroke-width="3.25"' not in default
    assert path_numbers(result.stdout) and not any("." in number for number in path_numbers(result.stdout))
    page = tmp_path / "talk.svg"
    assert run("demo", "-q", "--decimals", "1", "-o", page).returncode == 0
    assert all(len(number.partition(".")[2]) <= 1 for number in path_numbers(page.read_text()))
    for args in (["render", "--decimals", "7"], ["render", "--stroke-width", "-1"], ["demo", "--decimals", "-1"]):
        refused = run(*args, "-o", tmp_path / "refused.svg")
        assert refused.returncode == 2 and f"{args[1]}:" in refused.stderr, refused.stderr
    assert not (tmp_path / "refused.svg").exists()


def test_the_decimals_range_is_the_librarys(tmp_path):
    # The command checks --decimals itself (a usage error before anything is drawn); its range must
    # be SvgOptions' (kMaxSvgDecimals, svg_animator.hpp), or a value between the two is refused by one only.
    header = (SOURCE_DIR / "include" / "talkface" / "svg_animator.hpp").read_text()
    most = int(re.search(r"kMaxSvgDecimals = (\d+);", header).group(1))
    assert f"0..{most}" in run("render", "--help").stdout
    drawn = run("render", "--decimals", most, "-o", "-")
    assert drawn.returncode == 0, drawn.stderr
    assert max(len(number.partition(".")[2]) for number in path_numbers(drawn.stdout)) == most
    refused = run("render", "--decimals", most + 1, "-o", tmp_path / "refused.svg")
    assert refused.returncode == 2 and "--decimals:" in refused.stderr, refused.stderr
    assert not (tmp_path / "refused.svg").exists()

"""FFmpeg's libraries are libtalkface's module (LIBDIR/talkface/talkface_ffmpeg.so), opened on first use:
a command that reads no MP3, M4A or video and writes no video or page loads none of them."""
import json
import os
import pathlib
import re
import shutil
import subprocess

CLI = os.environ["TALKFACE_CLI"]
SOURCE_DIR = pathlib.Path(os.environ["TALKFACE_SOURCE_DIR"])
MP3 = SOURCE_DIR / "tests" / "data" / "audio" / "sox_22050.mp3"
TRANSCRIPT = SOURCE_DIR / "tests" / "data" / "speech" / "one_sentence.txt"


def libtalkface():
    """The libtalkface the command loads (its build tree's)."""
    ldd = subprocess.run(["ldd", CLI], capture_output=True, text=True, check=True).stdout
    return pathlib.Path(re.search(r"libtalkface\.so\S* => (\S+)", ldd).group(1))


def loaded_objects(*args, env=None):
    """The shared objects the command opens (the loader's LD_DEBUG=files), and its result."""
    result = subprocess.run([CLI, *map(str, args)], capture_output=True, text=True, timeout=120,
                            env={**(env or os.environ), "LD_DEBUG": "files"})
    return re.findall(r"file=(\S+) \[0\];  (?:needed|dynamically loaded)", result.stderr), result


def test_libtalkface_links_no_ffmpeg_library():
    needed = subprocess.run(["readelf", "-d", libtalkface()], capture_output=True, text=True, check=True).stdout
    assert "NEEDED" in needed
    assert not re.search(r"NEEDED.*\[lib(av|sw)", needed), needed


def test_syllables_loads_none_of_ffmpeg_and_an_mp3_loads_the_module(tmp_path):
    transcript = tmp_path / "t.txt"
    transcript.write_text("你好。\n", encoding="utf-8")
    objects, result = loaded_objects("syllables", transcript)
    assert result.returncode == 0, result.stderr
    assert any(name.startswith("libsndfile") for name in objects), objects  # the loader's report was read
    assert not [name for name in objects if re.search(r"libav|libsw|talkface_ffmpeg", name)], objects
    # Reading an MP3 opens the module, which links FFmpeg (whatever the alignment's outcome).
    objects, result = loaded_objects("align", MP3, TRANSCRIPT)
    assert any(name.endswith("/talkface/talkface_ffmpeg.so") for name in objects), result.stderr[-2000:]
    assert any("libavcodec" in name for name in objects), objects


def test_without_its_module_the_library_names_it(tmp_path):
    # The library alone in a folder (found first through LD_LIBRARY_PATH): what needs no FFmpeg runs,
    # an MP3 is refused with exit 1 naming the module's path beside that library.
    lib = tmp_path / "lib"
    lib.mkdir()
    shutil.copy(libtalkface(), lib / libtalkface().name)
    env = {**os.environ, "LD_LIBRARY_PATH": str(lib)}
    transcript = tmp_path / "t.txt"
    transcript.write_text("你好。\n", encoding="utf-8")
    assert subprocess.run([CLI, "syllables", transcript], env=env, capture_output=True).returncode == 0
    module = lib / "talkface" / "talkface_ffmpeg.so"
    result = subprocess.run([CLI, "align", MP3, TRANSCRIPT], env=env, capture_output=True, text=True, timeout=120)
    assert result.returncode == 1
    assert result.stderr.startswith(f"talkface: error: {module}: FFmpeg's module is missing"), result.stderr
    # A module there that cannot be loaded (as when a library it links is missing): the loader's reason.
    module.parent.mkdir()
    module.write_bytes(b"not a shared object\n")
    result = subprocess.run([CLI, "align", MP3, TRANSCRIPT], env=env, capture_output=True, text=True, timeout=120)
    assert result.returncode == 1
    assert result.stderr.startswith(f"talkface: error: {module}: FFmpeg's module could not be loaded ({module}: "), \
        result.stderr


def test_without_its_module_ogg_opus_is_read_by_libsndfile(tmp_path):
    # Ogg Opus is FFmpeg's where the module loads (it decodes faster), but libsndfile reads it too:
    # without the module it is aligned, not refused for a module it does not need.
    lib = tmp_path / "lib"
    lib.mkdir()
    shutil.copy(libtalkface(), lib / libtalkface().name)
    env = {**os.environ, "LD_LIBRARY_PATH": str(lib)}
    opus = SOURCE_DIR / "tests" / "data" / "audio" / "voice.opus"
    result = subprocess.run([CLI, "align", "-q", "--json", opus, TRANSCRIPT], env=env, capture_output=True, text=True,
                            timeout=120)
    assert result.returncode == 0, result.stderr
    assert len(json.loads(result.stdout)["syllables"]) == 11

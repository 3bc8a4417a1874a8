"""Broken files of the kinds users have (issue 13, "Bad input"; bad_inputs.py makes them) through the
command (align, animate, export, syllables, render), the C ABI and the Python module: each gives an
error naming the file and the reason, or a result; never a crash, an internal error or a hang."""
import json
import os
import pathlib
import shutil
import subprocess
import sys

import pytest

sys.path.insert(0, str(pathlib.Path(__file__).parent))
import bad_inputs  # noqa: E402

CLI = os.environ["TALKFACE_CLI"]
PROBE = pathlib.Path(__file__).parent / "bad_input_probe.py"
SPEECH = pathlib.Path(bad_inputs.SPEECH)
TRANSCRIPT = str(SPEECH / "one_sentence.txt")
VOICE = str(SPEECH / "one_sentence.wav")
TIMEOUT_S = 120

OK = None
# Audio: the reason each file is refused for (a part of the message after its path), or OK.
AUDIO = {
    "zero_bytes.wav": "empty file",
    "zero_bytes.mp3": "empty file",
    "text.wav": 'a text file (its first line "小朋友們在公園裡放風箏。"), not audio',
    "text.mp3": 'a text file (its first line "this is a text file, not an mp3"), not audio',
    "cut_in_header.wav": "truncated: the file ends after 30 bytes, inside its header",
    "cut_in_data.wav": "truncated",
    "data_past_end.wav": "truncated",
    "data_size_stream.wav": OK,
    "zero_channels.wav": "unsupported header: 0 channels at 16000 Hz",
    "rate_zero.wav": "unsupported header: 1 channels at 0 Hz",
    "rate_1e9.wav": "1 channels at 1000000000 Hz",
    "channels_64.wav": OK,
    "pcm8.wav": OK,
    "pcm24.wav": OK,
    "float32.wav": OK,
    "alaw.wav": OK,
    "mulaw.wav": OK,
    "float32_nan_inf.wav": OK,
    "id3_only.mp3": "ID3 tag (the title, artist and picture at its start) states 266 bytes, and no sound",
    "cut_mid_frame.mp3": OK,
    "huge_id3.mp3": "states 268435465 bytes, more than the file's",
    "moov_cut.m4a": "index",
    "no_sound.mp4": "a video without a sound track",
    "bad_crc.ogg": "the file is damaged: its Ogg pages break at byte 0",
    "total_too_long.flac": "truncated",
    "total_too_short.flac": OK,
    # Session 28's kinds.
    "data_size_zero.wav": OK,
    "sizes_zero.wav": OK,
    "data_size_ffffffff.wav": OK,
    "extensible_pcm16.wav": OK,
    "extensible_pcm24.wav": OK,
    "extensible_float32_nan_inf.wav": OK,
    "float64_nan_inf.wav": OK,
    "float32_huge.wav": "where a recording's samples lie within -1..1",
    "list_8mb.wav": OK,
    "list_past_end.wav": "truncated: the file ends after 98952 bytes, inside its header",
    "cut_mid_frame_tagged.mp3": "truncated: its header says the sound lasts",
    "stated_twice.mp3": "truncated: its header says the sound lasts",
    "stated_half.mp3": OK,
    "moov_at_end_cut.m4a": "truncated: an MP4/M4A/MOV file without its index",
    "stated_twice.m4a": OK,
    "stated_half.m4a": OK,
    "two_tracks.mkv": OK,
    "subtitle_only.mkv": "subtitles without a sound track",
    "voice.3gp": OK,
    "cut.3gp": "truncated: an MP4/M4A/MOV file without its index",
    "noise_nb.amr": OK,
    "noise_wb.amr": OK,
    "cut_mid_frame.amr": OK,
    # Session 29's kinds.
    "bad_header.opus": "its Opus header (OpusHead, the stream's first packet) states 0 channels",
    "bad_header.webm": OK,
    "two_data_chunks.wav": "its sound is in 2 data chunks (a second at byte 49492), where a WAV holds one",
    "fmt_after_data.wav": OK,
    "voice.aiff": OK,
    "voice.caf": OK,
    "streaminfo_length.flac": "the file is damaged: its FLAC header (STREAMINFO) states 100 bytes, where FLAC's is 34",
    # Session 30's kinds.
    "float32_nan_inf.caf": OK,
    "float32_all_nan.wav": "samples is a number (each is NaN or infinite)",
    # Session 33's kinds (bench/broken_files_sweep.py): each called "not audio", an MP4 without its
    # index, or FFmpeg's "Invalid data" on main.
    "four_bytes.wav": "truncated: the file holds only 4 bytes, fewer than any recording's header",
    "cut_in_data_header.wav": "truncated: the file ends after 43 bytes, inside its header",
    "header_only.flac": "truncated: its header says the sound lasts 3.",
    "cut_in_first_frame.flac": "truncated: its header says the sound lasts 3.",
    "index_only.m4a": "truncated: its header says the sound lasts 3.",
    "cut_in_first_frames.mp3": "bytes, inside its header, before any sound",
    "cut_in_header.mkv": "truncated: the file ends after 12 bytes, inside its header",
    "damaged_header_page.ogg": "the file is damaged: its Ogg pages break at byte",
    "error_page.m4a": 'a web page (HTML, titled "404 Not Found"), not audio',
    # Session 34's kinds: a few words called truncated, the others aligned without a word on main.
    "nine_bytes.wav": 'a text file (its first line "not audio"), not audio',
    "joined.wav": OK,
    "joined.m4a": OK,
    # Read on through the second copy, then refused as not the text: the join said in the refusal.
    "joined.flac": "(the file: its first 32 bytes (its header) recur at byte 56194: a second copy of the recording",
    "joined.mkv": "(the file: its first 32 bytes (its header) recur at byte 7322, where the first recording ends "
    "(3.091 s): a second copy of the recording",
    "huge_length.mp4": OK,
    "huge_length.mkv": OK,
    "zeroed_block.wav": OK,
    "flipped_bytes.wav": OK,
}
# Audio aligned with a warning that names the file: a part of the warning after the path.
WARNED = {
    "cut_mid_frame.mp3": "its last MP3 frame is cut short: its header states 105 bytes, the file ends after 59 of them, at 1.543 s",
    "stated_half.mp3": "its header states 1.584 s of sound, the file holds 3.091 s",
    "stated_half.m4a": "its header states 1.556 s of sound, the file holds 3.093 s",
    "stated_twice.m4a": "its header states 6.182 s for the file, but its sound track's own index holds 3.093 s",
    "two_tracks.mkv": "it has 2 sound tracks: the second was read, for the first is silent",
    "float32_nan_inf.wav": "300 of its 49448 samples are not numbers (NaN or infinite), the first at 0.773 s",
    "extensible_float32_nan_inf.wav": "300 of its 49448 samples are not numbers (NaN or infinite), the first at 0.773 s",
    "float64_nan_inf.wav": "300 of its 49448 samples are not numbers (NaN or infinite), the first at 0.773 s",
    "float32_nan_inf.caf": "300 of its 49448 samples are not numbers (NaN or infinite), the first at 0.773 s",
    "joined.wav": "the file goes on for 98940 bytes past the end its header states (byte 98940), about 3.1 s of "
    "sound at this file's rate, which no reader reads: a second WAV file begins there",
    "joined.m4a": "the file goes on past its end: a second MP4 file (its own ftyp box) begins at byte 11982",
    "huge_length.mp4": "its header states 3500 s for the file, but its 2 tracks' own lengths reach only 3.5 s (its "
    "sound track 3.136 s, all of which was read)",
    "huge_length.mkv": "its header states 1000000000000 s for the file, but its 2 tracks' own lengths reach only 3.507 s",
    "zeroed_block.wav": "its sound is cut off mid-wave to exact digital zeros at 1.5-1.628 s",
    # The flip at 1.25 s lies in a loud vowel, whose own ringing is nearly as far off: not told.
    "flipped_bytes.wav": "single samples jump far off the wave around them at 0.188 s, 0.8 s, 2.25 s (and 1 more)",
}
# Transcripts aligned with one_sentence.wav with a warning, and the warning.
ALIGN_WARNED = {
    "latin_only.txt": "the transcript cannot be checked against the audio: none of its 18 syllables has a Mandarin reading",
}
# Transcripts: (what loading it gives, what aligning one_sentence.wav with it gives).
TRANSCRIPTS = {
    "empty.txt": (OK, "no text to align"),
    "whitespace.txt": (OK, "no text to align"),
    "punctuation.txt": (OK, "no text to align"),
    "unknown_encoding.txt": ("it reads as big5", "it reads as big5"),
    "binary.txt": ("not UTF-8", "not UTF-8"),
    "one_line_1mb.txt": (OK, "352000 syllables"),
    "digits_40.txt": (OK, "40 syllables"),
    "latin_only.txt": (OK, OK),
    "emoji_only.txt": (OK, "no text to align"),
    "utf16le_bom.txt": (OK, OK),
    "utf16be_bom.txt": (OK, OK),
    "utf8_bom.txt": (OK, OK),
    "gb18030.txt": ("it reads as gb18030", "it reads as gb18030"),
    "crlf.txt": (OK, OK),
    "cr_only.txt": (OK, OK),
    "bom_in_middle.txt": (OK, OK),
    "nul_bytes.txt": (OK, OK),
    "punctuation_emoji.txt": (OK, "no text to align"),
    "wav_as_transcript.txt": ("not UTF-8", "not UTF-8"),
    "png_as_transcript.txt": ("not UTF-8", "not UTF-8"),
}
# Transcripts `syllables` lists nothing of: it says so.
NO_SENTENCE = {"empty.txt", "whitespace.txt", "punctuation.txt", "emoji_only.txt", "punctuation_emoji.txt"}
FACES = {
    "point_missing.xml": "missing 1 point",
    "point_duplicated.xml": "defined twice",
    "nan.xml": "expected a finite number",
    "inf.xml": "expected a finite number",
    "huge.xml": "beyond",
    "all_equal.xml": "the eyeball centres must be apart",
}


@pytest.fixture(scope="module")
def files(tmp_path_factory):
    folder = tmp_path_factory.mktemp("bad_input")
    made = {}
    for maker in (bad_inputs.audio_files, bad_inputs.transcript_files, bad_inputs.face_files):
        for name, data in maker().items():
            made[name] = bad_inputs.write(str(folder), name, data)
    return made


def command(*args):
    return subprocess.run([CLI, *args], capture_output=True, text=True, errors="replace", timeout=TIMEOUT_S)


def check_command(result, path, reason, warning=None):
    """A result (exit 0) where `reason` is OK, with `warning` among its JSON's warnings as "PATH: WARNING"
    where given; else exit 1 with `talkface: error: PATH...REASON`."""
    assert result.returncode in (0, 1), result.stderr  # not 3 (internal error) nor a signal
    if reason is OK:
        assert result.returncode == 0, result.stderr
        if warning is not None:
            warnings = json.loads(result.stdout)["warnings"]
            assert any(w.startswith(path + ": " + warning) for w in warnings), warnings
        return
    assert result.returncode == 1
    assert "talkface: error: " + path in result.stderr
    assert reason in result.stderr


def probe(interface, kind, path, transcript=None):
    args = [sys.executable, str(PROBE), interface, kind, path] + ([transcript] if transcript else [])
    result = subprocess.run(args, capture_output=True, text=True, timeout=TIMEOUT_S)
    assert result.returncode == 0, result.stderr  # no crash, no exception but talkface's own
    return json.loads(result.stdout)


def check_probe(outcome, path, reason, warning=None):
    if reason is OK:
        assert outcome["status"] == "ok", outcome
        if warning is not None:
            assert any(w.startswith(path + ": " + warning) for w in outcome["warnings"]), outcome
        return
    assert outcome["status"] == "error"
    assert "internal error" not in outcome["message"]
    assert path in outcome["message"] and reason in outcome["message"], outcome


# The interfaces the build offers beside the command (ctest's environment, tests/cli/CMakeLists.txt).
INTERFACES = [name for name, variable in (("c", "TALKFACE_C_LIBRARY"), ("python", "TALKFACE_PYTHON_MODULE")) if os.environ.get(variable)]


@pytest.mark.parametrize("name", sorted(AUDIO))
def test_audio_through_align(files, name):
    result = command("align", "-q", "--json", files[name], bad_inputs.transcript_of(name))
    check_command(result, files[name], AUDIO[name], WARNED.get(name))


def peak_of_command(*args):
    """The command's exit code, peak memory in kB (as its parent sees it: a process of its own, so no
    other child counts), stdout and stderr."""
    measure = (
        "import resource, subprocess, sys; r = subprocess.run(sys.argv[1:], capture_output=True, text=True); "
        "print(r.returncode, resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss); "
        "sys.stderr.write(r.stderr); sys.stderr.write(chr(0)); sys.stderr.write(r.stdout)"
    )
    result = subprocess.run([sys.executable, "-c", measure, CLI, *args], capture_output=True, text=True, timeout=TIMEOUT_S)
    returncode, peak_kb = map(int, result.stdout.split())
    stderr, stdout = result.stderr.split(chr(0), 1)
    return returncode, peak_kb, stdout, stderr


def test_long_silence_refused_early_in_bounded_memory(tmp_path):
    """A 10-hour silent WAV (1.15 GB, sparse) is refused when its samples are read, before any
    features: main took 302 s and 496 MB (bench/README.md, Session 27), past this test's timeout."""
    path = bad_inputs.ten_hour_silence(str(tmp_path))
    returncode, peak_kb, _, stderr = peak_of_command("align", "-q", path, TRANSCRIPT)
    assert returncode == 1, stderr
    assert "talkface: error: " + path + ": silent: the loudest sample of its 36000 s is all zero" in stderr
    assert peak_kb < 200 * 1024, peak_kb


def test_a_second_mp3s_tag_and_header_frame_are_the_join_not_damage(tmp_path):
    """An MP3 of FFmpeg's LAME joined to itself: the second copy's ID3 tag and Info tag frame were also
    called "the file is damaged: 0.075 s of its sound could not be decoded", beside the join's warning."""
    mp3 = (pathlib.Path(bad_inputs.AUDIO) / "ffmpeg_16000.mp3").read_bytes()
    path = tmp_path / "joined_tagged.mp3"
    path.write_bytes(mp3 + mp3)
    result = command("align", "-q", "--json", "--check", "warn", str(path), TRANSCRIPT)
    assert result.returncode == 0, result.stderr
    warnings = json.loads(result.stdout)["warnings"]
    assert any("recur at byte %d: a second copy of the recording" % len(mp3) in w for w in warnings), warnings
    assert not any("could not be decoded" in w for w in warnings), warnings


@pytest.mark.skipif(shutil.which("ffmpeg") is None, reason="ffmpeg is not installed")
def test_a_chained_ogg_files_second_stream_is_read_and_named(tmp_path):
    """`cat a.ogg b.ogg` of two Vorbis recordings: libsndfile read the first stream alone, and the
    second recording (here one_sentence.wav played backwards) was lost without a word."""
    streams = []
    for name, effect, serial in (("one.ogg", "anull", "0"), ("backwards.ogg", "areverse", "7")):
        streams.append(tmp_path / name)
        subprocess.run(["ffmpeg", "-nostdin", "-loglevel", "error", "-i", VOICE, "-af", effect, "-c:a", "libvorbis",
                        "-fflags", "+bitexact", "-flags:a", "+bitexact", "-serial_offset", serial, streams[-1]],
                       check=True)
    path = tmp_path / "chained.ogg"
    path.write_bytes(streams[0].read_bytes() + streams[1].read_bytes())
    result = command("align", "-q", "--json", "--check", "warn", str(path), TRANSCRIPT)
    assert result.returncode == 0, result.stderr
    timeline = json.loads(result.stdout)
    assert timeline["duration"] > 6.0, timeline["duration"]
    joins = [w for w in timeline["warnings"] if w.startswith(str(path) + ": ")]
    assert len(joins) == 1, timeline["warnings"]
    assert "a second Ogg stream (its own header pages, which open a recording) starts at byte %d" % (
        streams[0].stat().st_size) in joins[0]


# Main's peak on the three hours: 340 MB; the last minute's and the speech's: 20 MB, 104 MB under
# the sanitizers (their shadow memory and freed-block quarantine), which CI runs this test under too.
PEAK_AFTER_SILENCE_KB = 200 * 1024


def test_long_silence_before_the_voice_left_out(tmp_path):
    """Three hours of digital silence, then the voice: all of the silence but its last minute is
    left out of the analysis, the times counted on the recording's clock. Main analysed it whole,
    its features growing with the silence (340 MB here; 10 hours then a click: 875 MB, bench/README.md
    Session 29)."""
    hours = 3
    path = bad_inputs.silence_then_voice(str(tmp_path), hours)
    returncode, peak_kb, stdout, stderr = peak_of_command("align", "-q", "--json", path, TRANSCRIPT)
    assert returncode == 0, stderr
    alone = json.loads(command("align", "-q", "--json", VOICE, TRANSCRIPT).stdout)["syllables"]
    found = json.loads(stdout)["syllables"]
    assert [s["text"] for s in found] == [s["text"] for s in alone]
    for syllable, own in zip(found, alone):
        assert abs(syllable["start"] - hours * 3600 - own["start"]) < 0.05, (syllable, own)
    assert peak_kb < PEAK_AFTER_SILENCE_KB, peak_kb


@pytest.mark.parametrize("name", sorted(name for name, reason in AUDIO.items() if reason is not OK))
@pytest.mark.parametrize("subcommand", ["animate", "export"])
def test_refused_audio_through_animate_and_export(files, tmp_path, name, subcommand):
    out = tmp_path / ("page.html" if subcommand == "animate" else "cues.tsv")
    check_command(command(subcommand, "-q", files[name], bad_inputs.transcript_of(name), "-o", str(out)), files[name], AUDIO[name])
    assert not out.exists()


@pytest.mark.parametrize("interface", INTERFACES)
@pytest.mark.parametrize("name", sorted(AUDIO))
def test_audio_through_c_and_python(files, interface, name):
    outcome = probe(interface, "audio", files[name], bad_inputs.transcript_of(name))
    check_probe(outcome, files[name], AUDIO[name], WARNED.get(name))


@pytest.mark.parametrize("name", sorted(TRANSCRIPTS))
def test_transcripts_through_syllables_and_align(files, name):
    loaded, aligned = TRANSCRIPTS[name]
    listed = command("syllables", files[name])
    check_command(listed, files[name], loaded)
    if name in NO_SENTENCE:
        assert "talkface: warning: " + files[name] + ": no sentence to show" in listed.stderr
    result = command("align", "-q", "--json", VOICE, files[name])
    # A refusal by the aligner names the audio and the sentence; one of the transcript names it.
    assert result.returncode in (0, 1), result.stderr
    if aligned is OK:
        assert result.returncode == 0, result.stderr
        if name in ALIGN_WARNED:
            assert any(ALIGN_WARNED[name] in warning for warning in json.loads(result.stdout)["warnings"])
    else:
        assert result.returncode == 1 and aligned in result.stderr


@pytest.mark.parametrize("interface", INTERFACES)
@pytest.mark.parametrize("name", sorted(TRANSCRIPTS))
def test_transcripts_through_c_and_python(files, interface, name):
    check_probe(probe(interface, "transcript", files[name]), files[name], TRANSCRIPTS[name][0])


@pytest.mark.parametrize("name", sorted(FACES))
def test_faces_through_render_and_animate(files, tmp_path, name):
    check_command(command("render", "--face", files[name], "-o", str(tmp_path / "face.svg")), files[name], FACES[name])
    check_command(
        command("animate", "-q", "--face", files[name], VOICE, TRANSCRIPT, "-o", str(tmp_path / "page.html")),
        files[name],
        FACES[name],
    )


@pytest.mark.parametrize("interface", INTERFACES)
@pytest.mark.parametrize("name", sorted(FACES))
def test_faces_through_c_and_python(files, interface, name):
    check_probe(probe(interface, "face", files[name]), files[name], FACES[name])


# Paths that are no file, or a file with a name or a mode of its own (session 29): each is read, or
# refused naming the path and what it is.
PIPE_WAIT_S = 10  # read_file's wait for a pipe's first byte (common/atomic_file.cpp)


@pytest.fixture(scope="module")
def odd_paths(tmp_path_factory):
    folder = tmp_path_factory.mktemp("odd_paths")
    spaced = folder / "空 格 目錄"
    spaced.mkdir()
    paths = {
        "directory": str(folder / "a_directory"),
        "fifo": str(folder / "fifo"),
        "spaced_audio": str(spaced / "語音 檔.wav"),
        "spaced_transcript": str(spaced / "文字 稿.txt"),
        "spaced_cut": str(spaced / "剪 斷.wav"),
        "no_permission_audio": str(folder / "no_permission.wav"),
        "no_permission_transcript": str(folder / "no_permission.txt"),
    }
    os.mkdir(paths["directory"])
    os.mkfifo(paths["fifo"])
    bad_inputs.write(str(spaced), "語音 檔.wav", bad_inputs.read(VOICE))
    bad_inputs.write(str(spaced), "文字 稿.txt", bad_inputs.read(TRANSCRIPT))
    bad_inputs.write(str(spaced), "剪 斷.wav", bad_inputs.read(VOICE)[:30])
    for name in ("no_permission_audio", "no_permission_transcript"):
        source = VOICE if name.endswith("audio") else TRANSCRIPT
        bad_inputs.write(str(folder), os.path.basename(paths[name]), bad_inputs.read(source))
        os.chmod(paths[name], 0)
    return paths


# What the command and the library say of a path that is no file. The command's own check (CLI11's)
# refuses a directory before the library sees it, as a usage error (exit 2).
NO_FILE_AUDIO = {"directory": "directory", "fifo": "a named pipe (FIFO), not a file"}
NO_FILE_TEXT = {"directory": "a directory", "fifo": "a named pipe (FIFO) that nothing wrote to in %d s" % PIPE_WAIT_S}


def check_refused(result, path, reason):
    assert result.returncode in (1, 2), result.stderr
    assert path in result.stderr and reason in result.stderr, result.stderr


@pytest.mark.parametrize("kind", sorted(NO_FILE_AUDIO))
def test_no_file_as_audio(odd_paths, kind):
    """A directory or a named pipe given as the recording: on main a pipe nothing wrote to blocked
    the command, the C ABI and Python for ever."""
    path = odd_paths[kind]
    check_refused(command("align", "-q", path, TRANSCRIPT), path, NO_FILE_AUDIO[kind])
    for interface in INTERFACES:
        check_probe(probe(interface, "audio", path, TRANSCRIPT), path, NO_FILE_AUDIO[kind])


@pytest.mark.parametrize("kind", sorted(NO_FILE_TEXT))
def test_no_file_as_transcript_or_face(odd_paths, kind):
    """A directory given as the transcript loaded as an empty one through C and Python on main, and
    as a face said "the file is empty"; a named pipe nothing wrote to blocked."""
    path = odd_paths[kind]
    check_refused(command("syllables", path), path, NO_FILE_TEXT[kind])
    for interface in INTERFACES:
        check_probe(probe(interface, "transcript", path), path, NO_FILE_TEXT[kind])
        check_probe(probe(interface, "face", path), path, NO_FILE_TEXT[kind])


def test_pipe_with_a_writer_is_read_as_a_transcript():
    """A process substitution's pipe (talkface align a.wav <(cat t.txt)) is read to its end."""
    read_end, write_end = os.pipe()
    with open(write_end, "wb") as writer:
        writer.write(bad_inputs.read(TRANSCRIPT))
    result = subprocess.run(
        [CLI, "align", "-q", "--json", VOICE, "/dev/fd/%d" % read_end], capture_output=True, text=True, timeout=TIMEOUT_S,
        pass_fds=(read_end,),
    )
    os.close(read_end)
    assert result.returncode == 0, result.stderr
    assert len(json.loads(result.stdout)["syllables"]) == 11


def test_paths_with_spaces_and_chinese(odd_paths):
    audio, transcript, cut = odd_paths["spaced_audio"], odd_paths["spaced_transcript"], odd_paths["spaced_cut"]
    check_command(command("align", "-q", "--json", audio, transcript), audio, OK)
    check_command(command("align", "-q", "--json", cut, transcript), cut, "truncated")
    for interface in INTERFACES:
        check_probe(probe(interface, "audio", audio, transcript), audio, OK)
        check_probe(probe(interface, "audio", cut, transcript), cut, "truncated")


def test_unreadable_files(odd_paths):
    """chmod 000: refused as such, or read where the tests run as root (who reads it all the same)."""
    audio, transcript = odd_paths["no_permission_audio"], odd_paths["no_permission_transcript"]
    reason = OK if os.geteuid() == 0 else "Permission denied"
    check_command(command("align", "-q", "--json", audio, TRANSCRIPT), audio, reason)
    check_command(command("syllables", transcript), transcript, reason)
    for interface in INTERFACES:
        check_probe(probe(interface, "audio", audio, TRANSCRIPT), audio, reason)
        check_probe(probe(interface, "transcript", transcript), transcript, reason)

#!/usr/bin/env python3
"""Broken files of every kind users have (issue 13, "Bad input"), made from one good recording, each
run through `talkface align` (and the C ABI and the Python module where asked) under a timeout, and
tallied: a crash, a hang, an exit code other than 0 or 1, a refusal whose message lacks the file's
name or a reason, a file aligned with no word of its damage.

    broken_files_sweep.py SOURCE.wav TRANSCRIPT.txt OUT_DIR --cli BUILD/bin/talkface
        [--c-library BUILD/lib/libtalkface.so] [--python-module-dir DIR] [--timeout 60] [--make-only]

SOURCE is a short good recording (a few seconds, its TRANSCRIPT the words said): sox and ffmpeg
encode it as WAV, FLAC, Ogg Vorbis, Ogg Opus, MP3 at 22.05 and 44.1 kHz, M4A (AAC), MP4, MOV, MKV
and WebM videos with its sound, and a video without sound; each is then damaged the ways files are
(cut at ten points, from inside the header to mid-file; empty; its header alone; bytes flipped at
random; a block of zeros mid-file; a wrong extension; two copies joined; a huge stated length), or
joined to another recording (the source played backwards, encoded alike),
beside a WAV stating 0 channels or rate 0, a text file named .mp3 and an HTML error page named .m4a.
Deterministic: the damage is seeded by the file's name; the encoders run with -bitexact.
Writes OUT_DIR/files/ (the inputs), OUT_DIR/sweep.tsv (one row a run) and prints the tally.
"""

import argparse
import json
import os
import random
import re
import struct
import subprocess
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "tests", "common"))
from container_layout import (MP4_DURATION_FIELDS, after_id3, flac_frames_start, mp3_frame_count_at,  # noqa: E402
                              mp4_boxes, ogg_pages, set_ogg_page_crc, with_flac_total_samples,
                              with_matroska_duration, without_mdat)

FF = ["ffmpeg", "-nostdin", "-loglevel", "error", "-y"]
# After the inputs: output options (the muxers' serial numbers and UIDs fixed, the encoders' versions unsaid).
BITEXACT = ["-fflags", "+bitexact", "-flags:a", "+bitexact", "-flags:v", "+bitexact"]
VIDEO = ["-f", "lavfi", "-i", "color=c=gray:s=16x16:r=2"]


def encode_goods(source, folder):
    """The good recordings: name -> path."""
    goods = {
        "good.wav": ["sox", source, "-b", "16", "{out}"],
        "good.flac": ["sox", source, "{out}"],
        "vorbis.ogg": FF + ["-i", source, "-c:a", "libvorbis", "-q:a", "2", "{out}"],
        "opus.ogg": FF + ["-i", source, "-c:a", "libopus", "-b:a", "24k", "{out}"],
        "sox_22050.mp3": ["sox", source, "-C", "32", "-r", "22050", "{out}"],
        "lame_44100.mp3": FF + ["-i", source, "-ar", "44100", "-b:a", "48k", "{out}"],
        "phone.m4a": FF + ["-i", source, "-ar", "48000", "-c:a", "aac", "-b:a", "32k", "{out}"],
        "clip.mp4": FF + VIDEO + ["-i", source, "-shortest", "-c:v", "libx264", "-crf", "40", "-c:a", "aac",
                                  "-b:a", "32k", "{out}"],
        "clip.mov": FF + VIDEO + ["-i", source, "-shortest", "-c:v", "libx264", "-crf", "40", "-c:a", "aac",
                                  "-b:a", "32k", "{out}"],
        "clip.mkv": FF + VIDEO + ["-i", source, "-shortest", "-c:v", "libvpx", "-b:v", "8k", "-c:a", "libopus",
                                  "-b:a", "24k", "{out}"],
        "clip.webm": FF + VIDEO + ["-i", source, "-shortest", "-c:v", "libvpx", "-b:v", "8k", "-c:a",
                                   "libopus", "-b:a", "24k", "{out}"],
        "silent_video.mp4": FF + ["-f", "lavfi", "-i", "color=c=gray:s=16x16:r=2:d=3", "-c:v", "libx264", "-crf",
                                  "40", "{out}"],
    }
    made = {}
    for name, command in goods.items():
        out = os.path.join(folder, name)
        if command[0] == "ffmpeg":
            command = command[:-1] + BITEXACT + command[-1:]
        subprocess.run([out if part == "{out}" else part for part in command], check=True)
        made[name] = out
    return made


def mp3_first_frame_end(data):
    """The end of the first MPEG audio frame (after an ID3v2 tag)."""
    at = after_id3(data)
    while not (data[at] == 0xFF and data[at + 1] & 0xE0 == 0xE0):
        at += 1
    version = (data[at + 1] >> 3) & 3  # 3: MPEG-1, 2: MPEG-2, 0: MPEG-2.5
    rates = {3: (44100, 48000, 32000), 2: (22050, 24000, 16000), 0: (11025, 12000, 8000)}[version]
    kbps = ((0, 32, 40, 48, 56, 64, 80, 96, 112, 128, 160, 192, 224, 256, 320) if version == 3 else
            (0, 8, 16, 24, 32, 40, 48, 56, 64, 80, 96, 112, 128, 144, 160))[data[at + 2] >> 4]
    rate = rates[(data[at + 2] >> 2) & 3]
    padding = (data[at + 2] >> 1) & 1
    return at + (144 if version == 3 else 72) * kbps * 1000 // rate + padding


def header_end(name, data):
    """Where the first sound starts: the bytes before it are the file's header."""
    if name.endswith(".wav"):
        return data.index(b"data") + 8
    if name.endswith(".flac"):
        return flac_frames_start(data)
    if name.endswith(".ogg"):
        return next(start for start, _, granule in ogg_pages(data) if granule > 0)
    if name.endswith(".mp3"):
        return mp3_first_frame_end(data)
    if name.endswith((".m4a", ".mp4", ".mov")):
        return next(start for kind, start, _ in mp4_boxes(data) if kind == b"mdat") + 8
    return data.index(b"\x1f\x43\xb6\x75")  # Matroska's first Cluster


def header_only(name, data):
    if name.endswith((".m4a", ".mp4", ".mov")):  # the index with no sound: every box but mdat
        return without_mdat(data)
    return data[:header_end(name, data)]


def huge_length(name, data):
    """The file stating a length far past what it holds, or None where its format states none."""
    data = bytearray(data)
    if name.endswith(".wav"):
        at = data.index(b"data") + 4
        struct.pack_into("<I", data, at, 0x7FFFFF00)
        struct.pack_into("<I", data, 4, 0x7FFFFF00 + at)
    elif name.endswith(".flac"):
        data = with_flac_total_samples(data, 0xFFFFFFFF0)
    elif name.endswith(".mp3"):
        at = mp3_frame_count_at(data)
        if at is None:
            return None
        struct.pack_into(">I", data, at, 0x7FFFFFF0)
    elif name.endswith((".m4a", ".mp4", ".mov")):
        for box, offset in MP4_DURATION_FIELDS:
            at = 0
            while (at := data.find(box, at)) >= 0:
                struct.pack_into(">I", data, at + offset, 0x7FFFFFF0)
                at += 4
    elif name.endswith(".ogg"):
        start, end, _ = ogg_pages(bytes(data))[-1]
        struct.pack_into("<q", data, start + 6, 1 << 40)
        set_ogg_page_crc(data, start, end)
    else:
        return with_matroska_duration(bytes(data), 1e12)
    return bytes(data)


WRONG_EXTENSION = {".wav": ".mp3", ".flac": ".wav", ".ogg": ".m4a", ".mp3": ".wav", ".m4a": ".mp3",
                   ".mp4": ".wav", ".mov": ".mp4", ".mkv": ".mp4", ".webm": ".ogg"}


def damaged(name, data):
    """kind -> (file name, bytes) of every damage of the good file `name`."""
    stem, ext = os.path.splitext(name)
    start = header_end(name, data)
    rng = random.Random(name)
    out = {}
    points = sorted({1, 4, 12, start // 2, start - 1, start + 1, start + 100, start + 400, len(data) // 2,
                     len(data) * 9 // 10})
    for point in points:
        if 0 < point < len(data):
            out["cut_%d" % point] = data[:point]
    out["empty"] = b""
    out["header_only"] = header_only(name, data)
    flipped = bytearray(data)
    for at in rng.sample(range(len(data)), 16):
        flipped[at] ^= rng.randrange(1, 256)
    out["flipped"] = bytes(flipped)
    middle = len(data) // 2
    out["zeros_mid"] = data[:middle] + bytes(min(4096, len(data) // 8)) + data[middle + min(4096, len(data) // 8):]
    out["joined"] = data + data
    huge = huge_length(name, data)
    if huge is not None:
        out["huge_length"] = huge
    files = {kind: ("%s.%s%s" % (stem, kind, ext), payload) for kind, payload in out.items()}
    files["wrong_extension"] = ("%s.%s%s" % (stem, ext[1:], WRONG_EXTENSION[ext]), data)
    if name == "good.wav":
        for kind, offset, value in (("zero_channels", 22, b"\0\0"), ("rate_zero", 24, b"\0\0\0\0")):
            at = data.index(b"fmt ") + 8 + offset - 20
            files[kind] = ("good.%s.wav" % kind, data[:at] + value + data[at + len(value):])
    return files


def joined_to_another(source, folder, goods):
    """name -> (file name, bytes): each good file followed by the same encoding of another recording (the
    source played backwards: another sound of the same voice, rate and length)."""
    other_folder = os.path.join(folder, "..", "another")
    os.makedirs(other_folder, exist_ok=True)
    backwards = os.path.join(other_folder, "backwards.wav")
    subprocess.run(["sox", source, backwards, "reverse"], check=True)
    others = encode_goods(backwards, other_folder)
    out = {}
    for name, path in goods.items():
        if name == "silent_video.mp4":
            continue
        stem, ext = os.path.splitext(name)
        out[name] = ("%s.joined_another%s" % (stem, ext), open(path, "rb").read() + open(others[name], "rb").read())
    return out


def standalone():
    html = (b"<!DOCTYPE html>\n<html><head><title>404 Not Found</title></head>\n<body><h1>Not Found</h1>\n"
            b"<p>The requested URL /recordings/lesson3.m4a was not found on this server.</p>\n</body></html>\n")
    text = "这是一个文本文件，不是录音。\nThis is a text file, not a recording.\n".encode() * 20
    return {"text_renamed": ("notes.mp3", text), "html_error_page": ("download.m4a", html)}


# FFmpeg's own words, which name no reason a user can act on.
GENERIC = re.compile(r"Invalid data found when processing input$|Invalid argument$|Unknown error|error code -?\d+|"
                     r"End of file$")
MP4_FAMILY = (".m4a", ".mp4", ".mov")


def classify(good, kind, returncode, message, warnings, path):
    """The sweep's verdict on one run."""
    if returncode is None:
        return "hang"
    if returncode < 0:
        return "crash"
    if returncode not in (0, 1):
        return "exit code wrong"
    if returncode == 1:
        if path not in message:
            return "message without the file's name"
        after = message.split(path, 1)[1].strip(": \n")
        is_audio = good != "-"
        if is_audio and ("not audio talkface can read" in after or
                         ("MP4/M4A/MOV" in after and not good.endswith(MP4_FAMILY))):
            return "reason wrong"
        if len(after) < 10 or GENERIC.search(after):
            return "message without a reason"
        # A join read on as one recording is refused as not its text: the refusal should say why.
        if kind.startswith("joined") and "sound track" not in after and not re.search(r"joined|recur", after):
            return "refused, the join unnamed"
        return "refused, named"
    # Two copies joined are read as the first (a warning must say the rest was not read).
    if kind not in ("good", "wrong_extension") and not any(path in w for w in warnings):
        return "aligned despite damage"
    return "aligned"


def run_cli(cli, path, transcript, timeout):
    try:
        result = subprocess.run([cli, "align", "-q", "--json", path, transcript], capture_output=True, text=True,
                                errors="replace", timeout=timeout)
    except subprocess.TimeoutExpired:
        return None, "", []
    warnings = []
    if result.returncode == 0:
        warnings = json.loads(result.stdout).get("warnings", [])
    return result.returncode, result.stderr.strip(), warnings


def run_probe(interface, env, path, transcript, timeout):
    probe = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "tests", "cli", "bad_input_probe.py")
    try:
        result = subprocess.run([sys.executable, probe, interface, "audio", path, transcript], capture_output=True,
                                text=True, errors="replace", timeout=timeout, env=env)
    except subprocess.TimeoutExpired:
        return None, "", []
    if result.returncode != 0:  # a crash of the process, or an exception other than talkface's
        return (result.returncode if result.returncode < 0 else 3), result.stderr.strip()[-300:], []
    outcome = json.loads(result.stdout)
    if outcome["status"] == "ok":
        return 0, "", outcome["warnings"]
    return 1, outcome["message"], []


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("source")
    parser.add_argument("transcript")
    parser.add_argument("out")
    parser.add_argument("--cli")
    parser.add_argument("--c-library")
    parser.add_argument("--python-module-dir")
    parser.add_argument("--timeout", type=float, default=60)
    parser.add_argument("--make-only", action="store_true")
    args = parser.parse_args()
    folder = os.path.join(args.out, "files")
    os.makedirs(folder, exist_ok=True)
    cases = []  # (good, kind, path)
    goods = encode_goods(os.path.abspath(args.source), folder)
    for good, path in goods.items():
        data = open(path, "rb").read()
        cases.append((good, "good", path))
        for kind, (name, payload) in sorted(damaged(good, data).items()):
            with open(os.path.join(folder, name), "wb") as out:
                out.write(payload)
            cases.append((good, kind, os.path.join(folder, name)))
    for good, (name, payload) in joined_to_another(os.path.abspath(args.source), folder, goods).items():
        with open(os.path.join(folder, name), "wb") as out:
            out.write(payload)
        cases.append((good, "joined_another", os.path.join(folder, name)))
    for kind, (name, payload) in standalone().items():
        with open(os.path.join(folder, name), "wb") as out:
            out.write(payload)
        cases.append(("-", kind, os.path.join(folder, name)))
    if args.make_only:
        print(len(cases), "files in", folder)
        return
    runners = [("cli", lambda path: run_cli(args.cli, path, args.transcript, args.timeout))]
    if args.c_library:
        c_env = {**os.environ, "TALKFACE_C_LIBRARY": args.c_library}
        runners.append(("c", lambda path: run_probe("c", c_env, path, args.transcript, args.timeout)))
    if args.python_module_dir:
        python_env = {**os.environ, "PYTHONPATH": args.python_module_dir}
        runners.append(("python", lambda path: run_probe("python", python_env, path, args.transcript, args.timeout)))
    tally = {}
    with open(os.path.join(args.out, "sweep.tsv"), "w", encoding="utf-8") as table:
        table.write("interface\tgood\tkind\tfile\texit\tverdict\tmessage\n")
        for interface, run in runners:
            for good, kind, path in cases:
                returncode, message, warnings = run(path)
                verdict = classify(good, kind, returncode, message, warnings, path)
                tally.setdefault(interface, {}).setdefault(verdict, 0)
                tally[interface][verdict] += 1
                said = message if returncode != 0 else " | ".join(warnings)
                table.write("\t".join([interface, good, kind, os.path.basename(path), str(returncode), verdict,
                                       said.replace("\n", " ")[:400]]) + "\n")
    for interface, verdicts in tally.items():
        print(interface, len(cases), "files:", ", ".join("%s %d" % item for item in sorted(verdicts.items())))


if __name__ == "__main__":
    main()

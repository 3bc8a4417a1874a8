#!/usr/bin/env python3
"""Recordings as people have them, and broken files (issue 13): the sweep, made reproducible.

    bench/sweep_bench.py make OUT [--source DIR/NAME ...]   # the cases, from corpus passages
    bench/sweep_bench.py run OUT TALKFACE [--case SUBSTRING] # % of onsets within 50 ms per case

`make` builds each case from a corpus passage (a WAV, its transcript .txt and its truth .json, as
make_corpus and make_human_corpus write them; by default gcin-voice speaker 3's r-clean tuning-001
and espeak-ng's clean tuning-001) with sox and ffmpeg, as a phone, a recorder, an editor or a bad
copy leaves them: narrowband telephone, A-law, GSM, AMR, MP3, Opus, AAC, video sound tracks,
compression, clipping, dropouts, a notification beep, DC offsets, long silences, more channels,
sample formats, WAV chunks, RF64; and files broken by a scratch or cut to their header. OUT/cases.tsv
lists every case: its file, its transcript, its truth and how far the case moved the truth
(and by what it scaled its times).

`run` aligns every case with `TALKFACE align FILE TRANSCRIPT --json` and prints, per case, the % of
syllable onsets within 50 and 100 ms of the truth, or the error (first line) for a refused case; an
aligned case's warnings about its file (damage, a stale header) follow its figures, after "warns:".
A case is right when it aligns as well as the reference, or is refused with a message naming the
file and the reason.
"""
import argparse
import json
import math
import os
import random
import shutil
import struct
import subprocess
import sys

DEFAULT_SOURCES = [
    ("person", "/work/corpus/human/r-clean/tuning-001"),
    ("espeak", "/work/corpus/espeak/clean/tuning-001"),
]


def run(command):
    subprocess.run(command, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)


def sox(*arguments):
    run(["sox", "-R", "-V1", *arguments])


def ffmpeg(*arguments):
    run(["ffmpeg", "-nostdin", "-loglevel", "error", "-y", *arguments])


def duration_s(path):
    out = subprocess.run(["soxi", "-D", path], check=True, capture_output=True, text=True).stdout
    return float(out)


def scratched(source, target, share=1 / 3, count=2000, seed=3):
    """`count` random bytes a `share` of the way into the file: a bad sector, a broken download."""
    data = bytearray(open(source, "rb").read())
    at = int(len(data) * share)
    generator = random.Random(seed)
    data[at:at + count] = bytes(generator.randrange(256) for _ in range(count))
    open(target, "wb").write(bytes(data))


def wav_with_chunks(source, target):
    """A 16-bit WAV with a LIST/INFO chunk before its data and a cue chunk and a LIST/adtl label
    after it, as editors (Audacity's labels, Sound Forge's markers) write them."""
    data = open(source, "rb").read()
    assert data[:4] == b"RIFF" and data[8:12] == b"WAVE"
    chunks = []
    at = 12
    while at + 8 <= len(data):
        kind, size = data[at:at + 4], struct.unpack("<I", data[at + 4:at + 8])[0]
        chunks.append((kind, data[at + 8:at + 8 + size]))
        at += 8 + size + (size & 1)

    def chunk(kind, body):
        return kind + struct.pack("<I", len(body)) + body + (b"\0" if len(body) & 1 else b"")

    info = b"INFO" + chunk(b"INAM", b"phone memo\0") + chunk(b"ISFT", b"recorder 1.0\0")
    cue = struct.pack("<I", 1) + struct.pack("<II4sIII", 1, 0, b"data", 0, 0, 8000)
    adtl = b"adtl" + chunk(b"labl", struct.pack("<I", 1) + b"start\0")
    body = b"WAVE"
    for kind, content in chunks:
        if kind == b"data":
            body += chunk(b"LIST", info)
        body += chunk(kind, content)
    body += chunk(b"cue ", cue) + chunk(b"LIST", adtl)
    open(target, "wb").write(b"RIFF" + struct.pack("<I", len(body)) + body)


def with_wav_sizes(source, target, riff_size=None, data_size=None):
    """A copy of a WAV with its RIFF and data sizes overwritten, as writers leave them: 0xFFFFFFFF
    from a writer that streams to a pipe and cannot seek back, 0 from a recorder stopped before it
    closed the file, a smaller size from a recorder that updates its header only now and then."""
    data = bytearray(open(source, "rb").read())
    assert data[:4] == b"RIFF"
    at = 12
    while data[at:at + 4] != b"data":
        at += 8 + struct.unpack("<I", data[at + 4:at + 8])[0]
    real = struct.unpack("<I", data[at + 4:at + 8])[0]
    if riff_size is not None:
        data[4:8] = struct.pack("<I", riff_size)
    if data_size is not None:
        data[at + 4:at + 8] = struct.pack("<I", data_size(real) if callable(data_size) else data_size)
    open(target, "wb").write(bytes(data))


def with_wav_rate(source, target, factor):
    """A copy of a 16-bit WAV whose header states `factor` times its sample rate (and byte rate)."""
    data = bytearray(open(source, "rb").read())
    assert data[12:16] == b"fmt "
    rate = round(struct.unpack("<I", data[24:28])[0] * factor)
    block = struct.unpack("<H", data[32:34])[0]
    data[24:28] = struct.pack("<I", rate)
    data[28:32] = struct.pack("<I", rate * block)
    open(target, "wb").write(bytes(data))


def with_xing_frames(source, target, share):
    """A VBR MP3 whose Xing/Info header states `share` of its frames: a header written before the
    encoder finished, or two recordings joined with `cat` (the first one's header stays)."""
    data = bytearray(open(source, "rb").read())
    at = data.find(b"Xing")
    if at < 0:
        at = data.find(b"Info")
    flags = struct.unpack(">I", data[at + 4:at + 8])[0]
    assert flags & 1, "no frame count in the Xing header"
    frames = struct.unpack(">I", data[at + 8:at + 12])[0]
    data[at + 8:at + 12] = struct.pack(">I", int(frames * share))
    open(target, "wb").write(bytes(data))


def mp3_frame_size(header):
    """The bytes of the MPEG Layer III frame whose 4-byte header is `header` (MPEG-1, -2 and -2.5:
    from its bit rate, its sample rate and its padding bit)."""
    assert header[0] == 0xFF and header[1] & 0xE0 == 0xE0, "no frame header"
    version = header[1] >> 3 & 3
    rate = [44100, 48000, 32000][header[2] >> 2 & 3] >> {3: 0, 2: 1, 0: 2}[version]
    mpeg1_kbps = [0, 32, 40, 48, 56, 64, 80, 96, 112, 128, 160, 192, 224, 256, 320]
    mpeg2_kbps = [0, 8, 16, 24, 32, 40, 48, 56, 64, 80, 96, 112, 128, 144, 160]
    kbps = (mpeg1_kbps if version == 3 else mpeg2_kbps)[header[2] >> 4]
    return (144 if version == 3 else 72) * kbps * 1000 // rate + (header[2] >> 1 & 1)


def with_vbri_header(source, target, frames_per_entry=8, entry_bytes=2, scale=1):
    """A VBR MP3 as Fraunhofer's encoder writes one: a first frame holding a VBRI header (32 bytes
    after the frame's header: "VBRI", version 1, delay, quality, the stream's bytes and frames, the
    table's entries, scale, bytes an entry and frames an entry, then the table: the bytes of each
    `frames_per_entry` frames over `scale`) before the frames of `source`, an MP3 with no Xing or
    Info frame (ffmpeg -write_xing 0, -id3v2_version 0). No Debian encoder writes VBRI."""
    data = open(source, "rb").read()
    sizes, at = [], 0
    while at + 4 <= len(data):
        sizes.append(mp3_frame_size(data[at:at + 4]))
        at += sizes[-1]
    table = [sum(sizes[k:k + frames_per_entry]) // scale for k in range(0, len(sizes), frames_per_entry)]

    def fields(stream_bytes):
        return (b"VBRI" + struct.pack(">HHHII", 1, 1105, 75, stream_bytes, len(sizes))
                + struct.pack(">HHHH", len(table), scale, entry_bytes, frames_per_entry)
                + b"".join(entry.to_bytes(entry_bytes, "big") for entry in table))

    # The header's frame: the first frame's header at the lowest bit rate whose frame holds the fields.
    first = bytearray(data[:4])
    for index in range(1, 15):
        first[2] = first[2] & 0x0D | index << 4  # that bit rate, no padding
        header_size = mp3_frame_size(first)
        if header_size >= 36 + len(fields(0)):
            break
    frame = bytes(first) + bytes(32) + fields(header_size + len(data))
    open(target, "wb").write(frame + bytes(header_size - len(frame)) + data)


def make_cases(out, label, stem):
    """The cases of one source passage; returns (case, file, shift_s) rows."""
    wav, txt = stem + ".wav", stem + ".txt"
    truth = json.load(open(stem + ".json"))
    first_start = min(s["start"] for s in truth["syllables"])
    last_end = max(s["end"] for s in truth["syllables"])
    folder = os.path.join(out, label)
    os.makedirs(folder, exist_ok=True)
    rows = []

    def path(name):
        return os.path.join(folder, name)

    def case(name, file, shift_s=0.0, scale=1.0):
        rows.append((f"{label}/{name}", file, txt, stem + ".json", shift_s, scale))

    ref = path("ref.wav")
    sox(wav, "-b", "16", ref, "rate", "-v", "16k", "remix", "-")
    case("16 kHz WAV (reference)", ref)
    # A voice through a phone: the telephone band at 8 kHz, stored as each phone or voice mail does.
    narrow = path("narrow.wav")
    sox(ref, narrow, "sinc", "300-3400", "rate", "-v", "8k")
    case("8 kHz 300-3400 Hz", narrow)
    for name, options in [("alaw.wav", ["-e", "a-law"]), ("ulaw.wav", ["-e", "mu-law"]), ("gsm.wav", ["-e", "gsm-full-rate"])]:
        sox(narrow, *options, path(name))
        case(f"8 kHz {name}", path(name))
    # AMR-NB through sox's libopencore-amrnb (-C is the mode: 7 is 12.2 kb/s, 0 is 4.75). Debian's
    # sox and FFmpeg have no AMR-WB encoder: tests/audio/damaged_audio_test.cpp makes its frames by hand.
    sox(narrow, "-t", "amr-nb", "-C", "7", path("phone.amr"))
    case("AMR-NB 12.2 kb/s", path("phone.amr"))
    sox(narrow, "-t", "amr-nb", "-C", "0", path("phone475.amr"))
    case("AMR-NB 4.75 kb/s", path("phone475.amr"))
    ffmpeg("-i", narrow, "-c:a", "libmp3lame", "-b:a", "16k", path("narrow.mp3"))
    case("8 kHz MP3 16 kb/s", path("narrow.mp3"))
    ffmpeg("-i", ref, "-c:a", "libopus", "-b:a", "12k", path("voice.opus"))
    case("Opus 12 kb/s", path("voice.opus"))
    ffmpeg("-i", ref, "-ac", "2", "-ar", "48000", "-c:a", "aac", "-b:a", "64k", path("phone.m4a"))
    case("AAC 48 kHz stereo M4A", path("phone.m4a"))
    # Heavy compression and a phone's automatic gain: the pauses' room pulled up to speech's level.
    sox(ref, path("compand.wav"), "compand", "0.005,0.1", "6:-70,-70,-60,-20,-30,-12,0,-6", "-5", "-90", "0.05")
    case("heavy compression (compand)", path("compand.wav"))
    ffmpeg("-i", ref, "-af", "dynaudnorm=f=100:g=5:m=30", path("agc.wav"))
    case("AGC (dynaudnorm, 30x gain)", path("agc.wav"))
    sox(ref, path("clipped.wav"), "gain", "12")
    case("clipped (+12 dB)", path("clipped.wav"))
    sox(ref, path("clipped24.wav"), "gain", "24")
    case("clipped (+24 dB)", path("clipped24.wav"))
    # Clipped hard: a recorder's gain far too high, the voice a square wave but for its quiet ends.
    sox(ref, path("clipped40.wav"), "gain", "40")
    case("clipped hard (+40 dB)", path("clipped40.wav"))
    # A rate mismatch: 44.1 kHz sound stored as 48 kHz (a capture card, an editor's wrong project
    # rate) plays 8.8% fast and high; here the header's rate is raised by 48/44.1, and every time of
    # the truth shrinks by 44.1/48.
    with_wav_rate(ref, path("fast.wav"), 48000 / 44100)
    case("rate in the header 48/44.1 too high (plays fast)", path("fast.wav"), 0.0, 44100 / 48000)
    # Dropouts: a call's lost packets, 60 ms of nothing once a second. The volume is judged every 16
    # samples (1 ms): judged per block as ffmpeg hands them on (128 ms), the case held 128 ms of
    # zeros 11 times in its 19.5 s, not 60 ms every second (sessions 13-16).
    ffmpeg("-i", ref, "-af", "asetnsamples=n=16:p=0,volume='if(lt(mod(t,1),0.06),0,1)':eval=frame", path("dropouts.wav"))
    case("dropouts (60 ms a second)", path("dropouts.wav"))
    # A notification beep (two 880 Hz tones of 80 ms, -12 dBFS) in the middle of the speech, and one
    # starting 0.3 s before it (ending 80 ms before the first onset); and a recorder's start beep
    # 0.6 s before the speech, the passage padded by a second of digital silence.
    middle = (first_start + last_end) / 2
    sox(ref, path("padded1.wav"), "pad", "1", "0")
    for name, source, at, shift in [("beep_middle.wav", ref, middle, 0.0),
                                    ("beep_before.wav", ref, max(0.0, first_start - 0.3), 0.0),
                                    ("beep_0.6s_before.wav", path("padded1.wav"), first_start + 1.0 - 0.6, 1.0)]:
        ffmpeg("-i", source, "-f", "lavfi", "-i",
               "sine=f=880:d=0.08:sample_rate=16000,volume=0.25,apad=pad_dur=0.06[a];"
               "sine=f=880:d=0.08:sample_rate=16000,volume=0.25[b];[a][b]concat=v=0:a=1",
               "-filter_complex", f"[1]adelay={int(at * 1000)}[beep];[0][beep]amix=inputs=2:duration=first:normalize=0",
               path(name))
        case(name.replace(".wav", "").replace("_", " "), path(name), shift)
    # Speech from the first sample to the last: the file cut at the truth's first onset and last end.
    sox(ref, path("tight.wav"), "trim", f"{first_start:.4f}", f"={last_end:.4f}")
    case("speech from the first sample to the last", path("tight.wav"), -first_start)
    # Long silences: a minute of digital zeros, a minute of a faint room, before the speech.
    sox(ref, path("silence60.wav"), "pad", "60", "0")
    case("60 s of digital silence before", path("silence60.wav"), 60.0)
    length = duration_s(ref)
    sox("-n", "-r", "16k", "-b", "16", path("room.wav"), "synth", f"{60 + length:.3f}", "pinknoise", "vol", "0.003")
    sox("-m", path("room.wav"), path("silence60.wav"), path("room60.wav"))
    case("60 s of faint room before", path("room60.wav"), 60.0)
    # Channels.
    sox(ref, "-c", "2", path("stereo.wav"))
    case("stereo, the same in both", path("stereo.wav"))
    sox(ref, path("left.wav"), "remix", "1", "0")
    case("stereo, right silent", path("left.wav"))
    ffmpeg("-i", ref, "-af", "pan=5.1|FC=c0", path("surround.wav"))
    case("5.1, speech in the centre only", path("surround.wav"))
    # Sample formats.
    for name, options in [("u8.wav", ["-b", "8", "-e", "unsigned"]), ("s24.wav", ["-b", "24"]),
                          ("s32.wav", ["-b", "32"]), ("f32.wav", ["-e", "float", "-b", "32"]),
                          ("f64.wav", ["-e", "float", "-b", "64"])]:
        sox(ref, *options, path(name))
        case(name.replace(".wav", " WAV"), path(name))
    wav_with_chunks(ref, path("chunks.wav"))
    case("WAV with LIST and cue chunks", path("chunks.wav"))
    ffmpeg("-i", ref, "-rf64", "always", path("rf64.wav"))
    case("RF64", path("rf64.wav"))
    for level in (0.1, 0.3):
        sox(ref, path(f"dc{level}.wav"), "vol", "0.6", "dcshift", str(level))
        case(f"DC offset {level} (speech at 0.6)", path(f"dc{level}.wav"))
    sox(ref, path("quiet50.wav"), "gain", "-n", "-50")
    case("-50 dBFS peak", path("quiet50.wav"))
    # What recorders, phones and editors write (session 14).
    with_wav_sizes(ref, path("streamed.wav"), 0xFFFFFFFF, 0xFFFFFFFF)
    case("WAV sizes 0xFFFFFFFF (streamed)", path("streamed.wav"))
    with_wav_sizes(ref, path("sizes0.wav"), 0, 0)
    case("WAV sizes 0 (recorder not closed)", path("sizes0.wav"))
    with_wav_sizes(ref, path("stale.wav"), None, lambda real: real // 2 & ~1)
    case("WAV data size half of it (stale header)", path("stale.wav"))
    with_wav_sizes(ref, path("riff_wrong.wav"), 1234, None)
    case("WAV RIFF size wrong", path("riff_wrong.wav"))
    sox(ref, path("r11k.wav"), "rate", "-v", "11025")
    case("11.025 kHz WAV", path("r11k.wav"))
    ffmpeg("-f", "lavfi", "-i", "nullsrc=s=600x600,geq=random(1)*255:128:128", "-frames:v", "1", "-q:v", "2", path("cover.jpg"))
    ffmpeg("-i", ref, "-i", path("cover.jpg"), "-map", "0:a", "-map", "1:v", "-c:a", "libmp3lame", "-ar", "44100",
           "-b:a", "64k", "-c:v", "copy", "-id3v2_version", "3", "-write_id3v1", "1", "-metadata", "title=memo",
           "-metadata:s:v", "comment=Cover (front)", path("cover.mp3"))
    case("MP3 44.1 kHz with ID3v2 cover art", path("cover.mp3"))
    ffmpeg("-i", ref, "-c:a", "libmp3lame", "-q:a", "5", "-ar", "44100", path("vbr.mp3"))
    case("VBR MP3 (Xing header)", path("vbr.mp3"))
    with_xing_frames(path("vbr.mp3"), path("vbr_short_header.mp3"), 0.5)
    case("VBR MP3, Xing header states half", path("vbr_short_header.mp3"))
    # The same as Fraunhofer's encoder writes it: a VBRI header, whose table gives the bytes of
    # each 8 frames (0.21 s), in place of LAME's Xing header (session 21).
    ffmpeg("-i", ref, "-c:a", "libmp3lame", "-q:a", "5", "-ar", "44100", "-write_xing", "0", "-id3v2_version", "0",
           path("vbr_bare.mp3"))
    with_vbri_header(path("vbr_bare.mp3"), path("vbri.mp3"))
    case("VBR MP3 (VBRI header)", path("vbri.mp3"))
    sox(ref, path("inverted.wav"), "remix", "1", "1i")
    case("stereo, one channel phase-inverted", path("inverted.wav"))
    sox("-n", "-r", "16k", "-b", "16", path("hiss.wav"), "synth", f"{length:.3f}", "whitenoise", "vol", "0.01")
    sox("-M", ref, path("hiss.wav"), path("hiss_right.wav"))
    case("stereo, right a dead mic's hiss", path("hiss_right.wav"))
    ffmpeg("-i", ref, "-ac", "1", "-ar", "48000", "-c:a", "aac", "-b:a", "64k", "-brand", "mp42", path("memo.m4a"))
    case("voice memo: AAC 48 kHz mono M4A", path("memo.m4a"))
    ffmpeg("-i", ref, "-ac", "1", "-ar", "48000", "-c:a", "alac", path("alac.m4a"))
    case("voice memo: ALAC 48 kHz M4A", path("alac.m4a"))
    ffmpeg("-i", path("phone.amr"), "-c:a", "copy", path("phone.3gp"))
    case("AMR-NB in 3GP (Android recorder)", path("phone.3gp"))
    ffmpeg("-i", ref, "-c:a", "wmav2", "-b:a", "32k", path("voice.wma"))
    case("WMA (Windows recorder)", path("voice.wma"))
    # Started late, stopped early, or left running: the speech cut inside its first or last
    # syllable, and a minute of a faint room after it.
    into = first_start + 0.06
    sox(ref, path("mid_word_start.wav"), "trim", f"{into:.4f}")
    case("starts 60 ms into the first syllable", path("mid_word_start.wav"), -into)
    last_start = max(s["start"] for s in truth["syllables"])
    sox(ref, path("mid_word_end.wav"), "trim", "0", f"{last_start + 0.08:.4f}")
    case("ends 80 ms into the last syllable", path("mid_word_end.wav"))
    sox(ref, path("silence60_after.wav"), "pad", "0", "60")
    sox("-m", path("room.wav"), path("silence60_after.wav"), path("room60_after.wav"))
    case("60 s of faint room after", path("room60_after.wav"))
    picture = ["-f", "lavfi", "-i", f"color=c=gray:s=16x16:r=2:d={length:.3f}"]
    # Phone apps as users send their recordings on (session 21). WhatsApp's voice notes are Opus in
    # Ogg at 16 kHz, mono, for speech (.ogg, .opus); Telegram's Opus at 48 kHz (.oga); an Android
    # recorder's AAC in 3GP; a call recorder's telephone band at 8 kHz under a phone's automatic
    # gain, fast enough to pump (10 ms frames, the pauses' hiss pulled up 20x).
    ffmpeg("-i", ref, "-ac", "1", "-ar", "16000", "-c:a", "libopus", "-b:a", "16k", "-application", "voip",
           path("whatsapp.ogg"))
    case("WhatsApp voice note: Opus 16 kHz voip in .ogg", path("whatsapp.ogg"))
    ffmpeg("-i", ref, "-ac", "1", "-ar", "48000", "-c:a", "libopus", "-b:a", "32k", "-f", "ogg", path("telegram.oga"))
    case("Telegram voice message: Opus 48 kHz in .oga", path("telegram.oga"))
    ffmpeg("-i", ref, "-ac", "1", "-c:a", "aac", "-b:a", "24k", path("android_aac.3gp"))
    case("Android recorder: AAC in 3GP", path("android_aac.3gp"))
    # AAC where the container does not state the encoder's delay (an MP4's edit list does): a raw
    # AAC file (ADTS), as an Android recorder's AAC setting and call recorders write it, and a
    # screen recorder's MKV (OBS's default sound).
    ffmpeg("-i", ref, "-ac", "1", "-c:a", "aac", "-b:a", "32k", path("recorder.aac"))
    case("raw AAC (.aac, ADTS)", path("recorder.aac"))
    ffmpeg(*picture, "-i", ref, "-c:v", "libvpx", "-b:v", "8k", "-c:a", "aac", "-b:a", "32k", "-shortest",
           path("screen.mkv"))
    case("AAC in MKV (a screen recorder's)", path("screen.mkv"))
    ffmpeg("-i", narrow, "-af", "dynaudnorm=f=10:g=3:m=20", path("call_agc.wav"))
    case("call recording: 8 kHz 300-3400 Hz, AGC pumping", path("call_agc.wav"))
    # A long quiet lead: 20 s of a faint room (a recorder started early, left in a pocket), then a
    # click (the phone picked up, 10 ms of noise at -6 dBFS) 0.5 s before the speech.
    sox(ref, path("padded20.wav"), "pad", "20", "0")
    sox("-n", "-r", "16k", "-b", "16", path("room20.wav"), "synth", f"{20 + length:.3f}", "pinknoise", "vol", "0.003")
    sox("-n", "-r", "16k", "-b", "16", path("click.wav"), "synth", "0.01", "whitenoise", "vol", "0.5",
        "pad", f"{20 + first_start - 0.5:.3f}", "0")
    sox("-m", path("room20.wav"), path("padded20.wav"), path("click.wav"), path("lead_click.wav"))
    case("20 s of faint room, a click 0.5 s before the speech", path("lead_click.wav"), 20.0)
    # A WeChat or QQ voice message: SILK v3 ("#!SILK_V3" after WeChat's byte 2, then frames of a
    # 2-byte length and their bytes), often named .amr. No encoder in Debian: the frames here are
    # random bytes, for talkface only has to say what it is.
    generator = random.Random(5)
    silk = b"\x02#!SILK_V3"
    for _ in range(int(length * 50)):
        size = generator.randrange(20, 60)
        silk += struct.pack("<h", size) + bytes(generator.randrange(256) for _ in range(size))
    open(path("wechat.amr"), "wb").write(silk + b"\xff\xff")
    case("WeChat voice message (SILK v3, named .amr)", path("wechat.amr"))
    # A WAV whose header states more than it holds: a recorder that wrote the size it meant to
    # record, then crashed.
    with_wav_sizes(ref, path("overstated.wav"), None, lambda real: real * 2)
    case("WAV data size twice its data (recorder crashed)", path("overstated.wav"))
    # Session 23: what a browser, a camcorder, a TV recorder and a dictaphone write. A browser's
    # MediaRecorder: Chrome's Opus at 48 kHz in a live WebM (no duration, no index, sizes unknown),
    # Safari's AAC in a fragmented MP4. A video's 48 kHz stereo sound after 30 s of silence (a
    # talk's recording before the talk). A camcorder's AVCHD .mts (AC-3 in an MPEG transport
    # stream), a TV recording's .ts and an old camera's or a DVD's .mpg (MP2), with a picture; a
    # dictaphone's MP3 inside a WAV.
    ffmpeg("-i", ref, "-ac", "1", "-ar", "48000", "-c:a", "libopus", "-b:a", "32k", "-f", "webm", "-live", "1",
           path("mediarecorder.webm"))
    case("browser MediaRecorder: Opus in a live WebM", path("mediarecorder.webm"))
    ffmpeg("-i", ref, "-ac", "1", "-ar", "48000", "-c:a", "aac", "-b:a", "64k", "-movflags",
           "frag_keyframe+empty_moov+default_base_moof", path("fragmented.mp4"))
    case("browser MediaRecorder: AAC in a fragmented MP4", path("fragmented.mp4"))
    sox(ref, path("padded30.wav"), "pad", "30", "0")
    lead_picture = ["-f", "lavfi", "-i", f"color=c=gray:s=16x16:r=2:d={30 + length:.3f}"]
    ffmpeg(*lead_picture, "-i", path("padded30.wav"), "-c:v", "libx264", "-crf", "40", "-c:a", "aac", "-ar", "48000",
           "-ac", "2", "-b:a", "96k", "-shortest", path("lead30.mp4"))
    case("video, AAC 48 kHz stereo after 30 s of silence", path("lead30.mp4"), 30.0)
    for name, codecs in [("camcorder.mts", ["-c:v", "libx264", "-crf", "40", "-c:a", "ac3", "-ac", "2", "-b:a", "128k", "-f", "mpegts"]),
                         ("tv.ts", ["-c:v", "mpeg2video", "-r", "25", "-c:a", "mp2", "-b:a", "128k", "-f", "mpegts"]),
                         ("camera.mpg", ["-c:v", "mpeg1video", "-r", "25", "-c:a", "mp2", "-b:a", "128k", "-f", "mpeg"])]:
        ffmpeg(*picture, "-i", ref, "-ar", "48000", *codecs, "-shortest", path(name))
        case(name, path(name))
    ffmpeg("-i", ref, "-c:a", "libmp3lame", "-b:a", "32k", "-f", "wav", path("mp3_in.wav"))
    case("MP3 inside a WAV (a dictaphone's)", path("mp3_in.wav"))
    # Several sound tracks: a screen recorder's (OBS writes the desktop's sound and the microphone's
    # as two tracks, the first empty where nothing played), the desktop's music first, and three
    # (music, an empty track, the voice). The music: a held chord under a plucked line, 8 notes in 3 s.
    silence = ["-f", "lavfi", "-i", f"anullsrc=r=48000:cl=stereo:d={length:.3f}"]
    music = ["-f", "lavfi", "-i", "aevalsrc=0.06*sin(2*PI*220*t)+0.04*sin(2*PI*277.2*t)+0.04*sin(2*PI*329.6*t)"
             "+0.2*(0.1+0.9*exp(-6*mod(t\\,0.375)))*sin(2*PI*t*440*pow(2\\,floor(mod(t/0.375\\,5))*2/12))"
             f":s=48000:d={length:.3f}"]
    voice = ["-i", ref]
    # A drum kit alone (a beat under a stream, a backing track): a kick falling from 130 to 50 Hz on
    # each beat, a snare (noise and 190 Hz) on the second and fourth, a hi-hat each half beat; as
    # many low-energy frames as speech has, so the voice beside it needs the second witness.
    drums = ["-f", "lavfi", "-i", "aevalsrc=0.3*(sin(2*PI*(50*mod(t\\,0.5)+3.2*(1-exp(-mod(t\\,0.5)/0.04))))"
             "*exp(-mod(t\\,0.5)/0.15)+(0.5*(2*random(0)-1)+0.3*sin(2*PI*190*t))*exp(-mod(t+0.25\\,0.5)/0.1)"
             "*lt(mod(t+0.25\\,1)\\,0.5)+0.2*(2*random(1)-1)*exp(-mod(t\\,0.25)/0.03))"
             f":s=48000:d={length:.3f}"]
    for name, inputs in [("tracks_silent_voice.mp4", silence + voice), ("tracks_music_voice.mkv", music + voice),
                         ("tracks_music_silent_voice.mp4", music + silence + voice),
                         ("tracks_drums_voice.mkv", drums + voice), ("tracks_voice_drums.mkv", voice + drums)]:
        maps = ["-map", "0:v"] + [arg for i in range(inputs.count("-i")) for arg in ("-map", f"{i + 1}:a")]
        ffmpeg(*picture, *inputs, *maps, "-ar", "48000", "-c:v", "libx264", "-crf", "40", "-c:a", "aac", "-b:a", "64k",
               "-shortest", path(name))
        case(f"{name}: {name.split('.')[0].replace('tracks_', '').replace('_', ', ')} tracks", path(name))
    # Cut mid-frame a second after the speech (a download or a copy broken off): refused, naming
    # where the sound ends and how long the header said it was.
    sox(ref, path("tail.wav"), "pad", "0", "1")
    for name, encode in [("tail.mp3", ["-c:a", "libmp3lame", "-b:a", "32k"]), ("tail.flac", []),
                         ("tail.opus", ["-c:a", "libopus", "-b:a", "16k"])]:
        ffmpeg("-i", path("tail.wav"), *encode, path(name))
    for name in ["tail.wav", "tail.mp3", "tail.flac", "tail.opus"]:
        data = open(path(name), "rb").read()
        open(path("cut_" + name), "wb").write(data[:int(len(data) * (last_end + 0.5) / (length + 1)) + 7])
        case(f"{name.replace('tail.', '')} cut mid-frame after the speech", path("cut_" + name))
    # Video sound tracks and broken files.
    for name, codecs in [("clip.mkv", ["-c:v", "libvpx", "-b:v", "8k", "-c:a", "libopus", "-b:a", "16k"]),
                         ("clip.webm", ["-c:v", "libvpx", "-b:v", "8k", "-c:a", "libopus", "-b:a", "16k"]),
                         ("clip.mp4", ["-c:v", "libx264", "-crf", "40", "-c:a", "aac", "-b:a", "32k", "-movflags", "+faststart"])]:
        ffmpeg(*picture, "-i", ref, *codecs, "-shortest", path(name))
        case(name, path(name))
        scratched(path(name), path("scratched_" + name))
        case("scratched " + name, path("scratched_" + name))
    # A video whose sound track starts 0.5 s after its picture (a camera or screen recorder that
    # starts the sound late, an editor's offset): players play silence until then, so the times
    # a user lays over the video are the picture's.
    for name, codecs in [("offset_clip.mp4", ["-c:v", "libx264", "-crf", "40", "-c:a", "aac", "-b:a", "32k"]),
                         ("offset_clip.mkv", ["-c:v", "libvpx", "-b:v", "8k", "-c:a", "libopus", "-b:a", "16k"])]:
        ffmpeg(*picture, "-itsoffset", "0.5", "-i", ref, "-map", "0:v", "-map", "1:a", *codecs, path(name))
        case(name.replace("offset_", "") + ", its sound starting 0.5 s after its picture", path(name), 0.5)
    # The same MP4 (+faststart: its index, the moov box, first) scratched inside its index.
    scratched(path("clip.mp4"), path("scratched_index_clip.mp4"), share=1 / 100)
    case("scratched clip.mp4 in its index (faststart)", path("scratched_index_clip.mp4"))
    # A WebM whose clusters are as long as the recording (FFmpeg's default 5 s clusters hold a short
    # clip or a voice message whole): a scratch half way in loses the rest of the cluster, and no
    # cluster after it says where the sound belonged.
    ffmpeg(*picture, "-i", ref, "-c:v", "libvpx", "-b:v", "8k", "-c:a", "libopus", "-b:a", "16k",
           "-cluster_time_limit", "60000", "-shortest", path("one_cluster.webm"))
    scratched(path("one_cluster.webm"), path("scratched_one_cluster.webm"), share=1 / 2)
    case("scratched one_cluster.webm (half way in)", path("scratched_one_cluster.webm"))
    ffmpeg("-i", ref, "-c:a", "libvorbis", "-q:a", "2", path("voice.ogg"))
    case("Ogg Vorbis", path("voice.ogg"))
    scratched(path("voice.ogg"), path("scratched_voice.ogg"))
    case("scratched voice.ogg", path("scratched_voice.ogg"))
    # The same from inside its first page of sound (after Vorbis's headers): a loss at the start.
    ogg = open(path("voice.ogg"), "rb").read()
    page = ogg.find(b"OggS")
    while struct.unpack("<q", ogg[page + 6:page + 14])[0] <= 0:
        page = ogg.find(b"OggS", page + 4)
    scratched(path("voice.ogg"), path("scratched_start_voice.ogg"), share=(page + 40) / len(ogg))
    case("scratched voice.ogg in its first page of sound", path("scratched_start_voice.ogg"))
    scratched(path("voice.opus"), path("scratched_voice.opus"))
    case("scratched voice.opus", path("scratched_voice.opus"))
    # The same from 40 bytes into a page near its end (the fourth from last), inside the page's
    # segment table: the header then claims more bytes than the file holds.
    opus = open(path("voice.opus"), "rb").read()
    pages = [at for at in range(len(opus)) if opus.startswith(b"OggS", at)]
    scratched(path("voice.opus"), path("scratched_header_voice.opus"), share=(pages[-4] + 40) / len(opus))
    case("scratched voice.opus in a page's header near its end", path("scratched_header_voice.opus"))
    scratched(path("phone.m4a"), path("scratched_phone.m4a"))
    case("scratched phone.m4a", path("scratched_phone.m4a"))
    scratched(path("cover.mp3"), path("scratched_cover.mp3"))
    case("scratched cover.mp3", path("scratched_cover.mp3"))
    # The scratch above hits the cover art (a third of that file is the picture); these hit the
    # sound: a phone's call recorder at 8 kHz (LAME-tagged), sox's untagged MP3, a VBR one.
    sox(narrow, "-C", "16", path("narrow_sox.mp3"))
    for name in ["narrow.mp3", "narrow_sox.mp3", "vbr.mp3", "vbri.mp3"]:
        scratched(path(name), path("scratched_" + name))
        case("scratched " + name + " (in its sound)", path("scratched_" + name))
    sox(ref, path("voice.flac"))
    scratched(path("voice.flac"), path("scratched_voice.flac"))
    case("scratched voice.flac", path("scratched_voice.flac"))
    scratched(ref, path("scratched_ref.wav"))
    case("scratched 16-bit WAV (a burst of noise)", path("scratched_ref.wav"))
    mkv = open(path("clip.mkv"), "rb").read()
    open(path("header_only.mkv"), "wb").write(mkv[:200])
    case("header-only MKV", path("header_only.mkv"))
    ffmpeg(*picture, "-c:v", "libvpx", "-b:v", "8k", path("silent_video.webm"))
    case("a video without sound", path("silent_video.webm"))
    case("a missing file", path("missing.wav"))
    return rows


def make(args):
    os.makedirs(args.out, exist_ok=True)
    sources = [tuple(s.split("=", 1)) for s in args.source] if args.source else DEFAULT_SOURCES
    rows = []
    for label, stem in sources:
        rows += make_cases(args.out, label, stem)
    with open(os.path.join(args.out, "cases.tsv"), "w") as f:
        for row in rows:
            f.write("\t".join(str(v) for v in row) + "\n")
    print(f"{len(rows)} cases in {args.out}/cases.tsv")


def score(result, truth, shift_s, scale):
    """% of onsets within 50 and 100 ms of the truth's times times `scale` plus `shift_s`; an onset
    the case cut off (a recording started late) is held to the file's start, where an aligner can
    at best put it."""
    errors = []
    syllables = truth["syllables"]
    if len(result["syllables"]) != len(syllables):
        return None
    for got, want in zip(result["syllables"], syllables):
        errors.append(abs(got["start"] - max(want["start"] * scale + shift_s, 0.0)))
    within = lambda limit: 100.0 * sum(e <= limit for e in errors) / len(errors)
    return within(0.05), within(0.1)


def run_cases(args):
    rows = [line.rstrip("\n").split("\t") for line in open(os.path.join(args.out, "cases.tsv"))]
    print(f"{'case':52} {'50 ms':>6} {'100 ms':>6}  exit / message")
    for name, file, txt, truth_path, shift, *scale in rows:
        if args.case and args.case not in name:
            continue
        done = subprocess.run([args.talkface, "align", file, txt, "--json"], capture_output=True, text=True)
        if done.returncode == 0:
            result = json.loads(done.stdout)
            scored = score(result, json.load(open(truth_path)), float(shift), float(scale[0]) if scale else 1.0)
            # What the reader told the user of the file (damage, a stale header), without its path.
            said = "".join(f"  warns: {w.replace(file + ': ', '', 1)}" for w in result["warnings"]
                           if w.startswith(file + ": "))
            if scored is None:
                print(f"{name:52} {'?':>6} {'?':>6}  syllable count differs{said}")
            else:
                print(f"{name:52} {scored[0]:6.1f} {scored[1]:6.1f}{said}")
        else:
            message = (done.stderr.strip().splitlines() or ["(nothing on stderr)"])[0]
            print(f"{name:52} {'-':>6} {'-':>6}  exit {done.returncode}: {message}")


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    commands = parser.add_subparsers(dest="command", required=True)
    maker = commands.add_parser("make")
    maker.add_argument("out")
    maker.add_argument("--source", action="append", help="LABEL=PATH/STEM of a corpus passage (.wav, .txt, .json)")
    runner = commands.add_parser("run")
    runner.add_argument("out")
    runner.add_argument("talkface")
    runner.add_argument("--case", help="only the cases whose name holds this")
    args = parser.parse_args()
    for tool in ("sox", "soxi", "ffmpeg"):
        if shutil.which(tool) is None:
            sys.exit(f"sweep_bench.py: {tool} is needed (cmake/install-deps.sh bench installs it)")
    make(args) if args.command == "make" else run_cases(args)


if __name__ == "__main__":
    main()

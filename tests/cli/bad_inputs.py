"""Broken files of the kinds users have (issue 13, "Bad input"), made from the test data.

Each maker writes one file into a folder and returns its path. test_bad_input.py runs them through
the command and the Python module; bench/README.md's session 27 section lists what each gave.
"""

import math
import os
import re
import struct
import wave

SOURCE_DIR = os.environ.get("TALKFACE_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", ".."))
SPEECH = os.path.join(SOURCE_DIR, "tests", "data", "speech")
AUDIO = os.path.join(SOURCE_DIR, "tests", "data", "audio")
FACES = os.path.join(SOURCE_DIR, "samples", "faces")

# WAVE_FORMAT tags (RFC 2361)
PCM, IEEE_FLOAT, ALAW, MULAW = 1, 3, 6, 7


def speech_samples():
    """one_sentence.wav's 16-bit samples at 16 kHz, mono: a voice its transcript says."""
    with wave.open(os.path.join(SPEECH, "one_sentence.wav"), "rb") as w:
        frames = w.readframes(w.getnframes())
    return list(struct.unpack("<%dh" % (len(frames) // 2), frames))


def wav_bytes(data, *, tag=PCM, channels=1, rate_hz=16000, bits=16, data_size=None):
    """A WAV file: a fmt chunk saying `tag`, `channels`, `rate_hz`, `bits`, then `data`, whose
    chunk states `data_size` (default: its real size)."""
    block_align = channels * bits // 8
    fmt = struct.pack("<HHIIHH", tag, channels, rate_hz, (rate_hz * block_align) & 0xFFFFFFFF, block_align, bits)
    if tag != PCM:
        fmt += struct.pack("<H", 0)
    stated = len(data) if data_size is None else data_size
    body = b"WAVE" + b"fmt " + struct.pack("<I", len(fmt)) + fmt + b"data" + struct.pack("<I", stated) + data
    return b"RIFF" + struct.pack("<I", min(len(body), 0xFFFFFFFF)) + body


def pcm16(samples):
    return struct.pack("<%dh" % len(samples), *samples)


def alaw(sample):
    """G.711 A-law of a 16-bit sample."""
    sign = 0x80 if sample >= 0 else 0x00
    magnitude = min(abs(sample) if sample >= 0 else -sample - 1, 32635) >> 3
    if magnitude < 32:
        code = magnitude >> 1
    else:
        exponent = magnitude.bit_length() - 5
        code = (exponent << 4) | ((magnitude >> exponent) & 0x0F)
    return (code | sign) ^ 0x55


def mulaw(sample):
    """G.711 mu-law of a 16-bit sample."""
    sign = 0x80 if sample < 0 else 0x00
    magnitude = min(abs(sample), 32635) + 132
    exponent = magnitude.bit_length() - 8
    return ~(sign | (exponent << 4) | ((magnitude >> (exponent + 3)) & 0x0F)) & 0xFF


def write(folder, name, data):
    path = os.path.join(folder, name)
    with open(path, "wb") as f:
        f.write(data)
    return path


def read(path):
    with open(path, "rb") as f:
        return f.read()


# Audio: name -> bytes. The speech is one_sentence's but where transcript_of() names another.
def transcript_of(name):
    source = {".flac": "comma_pause.txt", ".ogg": "stereo_44k.txt"}.get(os.path.splitext(name)[1], "one_sentence.txt")
    return os.path.join(SPEECH, source)


def audio_files():
    voice = speech_samples()
    good = wav_bytes(pcm16(voice))
    header_end = good.index(b"data") + 8
    stream = bytearray(good)
    stream[header_end - 4 : header_end] = b"\xff\xff\xff\xff"
    stream[4:8] = b"\xff\xff\xff\xff"
    float_voice = b"".join(struct.pack("<f", s / 32768.0) for s in voice)
    non_finite = bytearray(float_voice)
    for i, value in enumerate((math.nan, math.inf, -math.inf)):
        at = (len(voice) // 4 * (i + 1)) * 4
        non_finite[at : at + 4 * 100] = struct.pack("<f", value) * 100
    mp3 = read(os.path.join(AUDIO, "sox_22050.mp3"))
    id3 = b"ID3\x04\x00\x00" + bytes([0x00, 0x00, 0x02, 0x00]) + b"\x00" * 256
    huge_id3 = b"ID3\x04\x00\x00" + bytes([0x7F, 0x7F, 0x7F, 0x7F]) + mp3
    m4a = read(os.path.join(AUDIO, "phone.m4a"))
    ogg = bytearray(read(os.path.join(SPEECH, "stereo_44k.ogg")))
    ogg[22] ^= 0xFF  # the first page's CRC
    flac = read(os.path.join(SPEECH, "comma_pause.flac"))
    return {
        "zero_bytes.wav": b"",
        "zero_bytes.mp3": b"",
        "text.wav": "小朋友們在公園裡放風箏。\n".encode(),
        "text.mp3": b"this is a text file, not an mp3\n" * 20,
        "cut_in_header.wav": good[:30],
        "cut_in_data.wav": good[: header_end + (len(good) - header_end) // 2],
        "data_past_end.wav": wav_bytes(pcm16(voice), data_size=len(voice) * 2 * 4),
        "data_size_stream.wav": bytes(stream),
        "zero_channels.wav": wav_bytes(pcm16(voice), channels=0),
        "rate_zero.wav": wav_bytes(pcm16(voice), rate_hz=0),
        "rate_1e9.wav": wav_bytes(pcm16(voice), rate_hz=10**9),
        "channels_64.wav": wav_bytes(pcm16([s for s in voice for _ in range(64)]), channels=64),
        "pcm8.wav": wav_bytes(bytes((s >> 8) + 128 for s in voice), bits=8),
        "pcm24.wav": wav_bytes(b"".join(struct.pack("<i", s << 8)[:3] for s in voice), bits=24),
        "float32.wav": wav_bytes(float_voice, tag=IEEE_FLOAT, bits=32),
        "alaw.wav": wav_bytes(bytes(alaw(s) for s in voice), tag=ALAW, bits=8),
        "mulaw.wav": wav_bytes(bytes(mulaw(s) for s in voice), tag=MULAW, bits=8),
        "float32_nan_inf.wav": wav_bytes(bytes(non_finite), tag=IEEE_FLOAT, bits=32),
        "id3_only.mp3": id3,
        "cut_mid_frame.mp3": mp3[: len(mp3) // 2 + 7],
        "huge_id3.mp3": huge_id3,
        "moov_cut.m4a": m4a[: m4a.rindex(b"moov") + 200],
        "no_sound.mp4": read(os.path.join(AUDIO, "no_sound.mp4")),
        "bad_crc.ogg": bytes(ogg),
        "total_too_long.flac": flac_with_total(flac, 10),
        "total_too_short.flac": flac_with_total(flac, 0.25),
    }


def flac_with_total(flac, scale):
    """`flac` with its STREAMINFO's total samples (36 bits at byte 21, low nibble on) scaled."""
    head = int.from_bytes(flac[21:26], "big")
    total = head & 0xFFFFFFFFF
    new_total = min(int(total * scale), 0xFFFFFFFFF)
    head = (head & ~0xFFFFFFFFF) | new_total
    return flac[:21] + head.to_bytes(5, "big") + flac[26:]


def ten_hour_silence(folder, name="ten_hours_silent.wav", rate_hz=16000):
    """A WAV of 10 hours of silence, sparse on disk: its header, then a hole of zeros."""
    data_size = 10 * 3600 * rate_hz * 2
    path = write(folder, name, wav_bytes(b"", rate_hz=rate_hz, data_size=data_size))
    os.truncate(path, os.path.getsize(path) + data_size)
    return path


# Transcripts: name -> bytes.
def transcript_files():
    return {
        "empty.txt": b"",
        "whitespace.txt": b" \t\n\r\n   \n\xe3\x80\x80\n",
        "punctuation.txt": "。，！？……；：、「」《》——.!?,;".encode(),
        "unknown_encoding.txt": "小朋友們在公園裡放風箏。".encode("big5"),
        "binary.txt": bytes(range(256)) * 8,
        "one_line_1mb.txt": ("小朋友們在公園裡放風箏" * 32000).encode(),
        "digits_40.txt": b"1234567890123456789012345678901234567890",
        "latin_only.txt": b"The quick brown fox jumps over the lazy dog.",
        "emoji_only.txt": "😀😃😄😁😆🎉".encode(),
    }


# Faces: name -> bytes, edits of samples/faces/male.xml.
def face_files():
    face = read(os.path.join(FACES, "male.xml")).decode()
    lines = face.splitlines(keepends=True)
    point_lines = [i for i, line in enumerate(lines) if "<point " in line]
    first = point_lines[0]

    def with_coordinates(x, y):
        return "".join(
            re.sub(r'x="[^"]*" y="[^"]*"', 'x="%s" y="%s"' % (x, y), line) if i in point_lines else line
            for i, line in enumerate(lines)
        )

    def edited(change):
        return "".join(change(list(lines))).encode()

    def first_point_with(attribute, value):
        return edited(
            lambda ls: ls[:first] + [re.sub(attribute + r'="[^"]*"', '%s="%s"' % (attribute, value), ls[first])] + ls[first + 1 :]
        )

    return {
        "point_missing.xml": edited(lambda ls: ls[:first] + ls[first + 1 :]),
        "point_duplicated.xml": edited(lambda ls: ls[: first + 1] + [ls[first]] + ls[first + 1 :]),
        "nan.xml": first_point_with("x", "nan"),
        "inf.xml": first_point_with("y", "inf"),
        "huge.xml": first_point_with("x", "1e308"),
        "all_equal.xml": with_coordinates(100, 100).encode(),
    }

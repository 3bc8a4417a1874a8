"""Broken files of the kinds users have (issue 13, "Bad input"), made from the test data.

Each maker writes one file into a folder and returns its path. test_bad_input.py runs them through
the command, the C ABI and the Python module; bench/README.md's session 27, 28 and 29 sections list
what each gave.
"""

import math
import os
import re
import struct
import sys
import wave

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "common"))
from container_layout import (FLAC_MAX_TOTAL, MP4_DURATION_FIELDS, after_id3, flac_frames_start,  # noqa: E402
                              flac_total_samples, mp3_frame_count_at, ogg_pages, set_ogg_page_crc,
                              with_flac_total_samples, with_matroska_duration, without_mdat)

SOURCE_DIR = os.environ.get("TALKFACE_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", ".."))
SPEECH = os.path.join(SOURCE_DIR, "tests", "data", "speech")
AUDIO = os.path.join(SOURCE_DIR, "tests", "data", "audio")
FACES = os.path.join(SOURCE_DIR, "samples", "faces")

# WAVE_FORMAT tags (RFC 2361)
PCM, IEEE_FLOAT, ALAW, MULAW, EXTENSIBLE = 1, 3, 6, 7, 0xFFFE
# A WAVE_FORMAT_EXTENSIBLE's SubFormat: the plain tag in the first 2 bytes of the KSDATAFORMAT GUID.
SUBFORMAT_TAIL = b"\x00\x00\x00\x00\x10\x00\x80\x00\x00\xaa\x00\x38\x9b\x71"


def speech_samples():
    """one_sentence.wav's 16-bit samples at 16 kHz, mono: a voice its transcript says."""
    with wave.open(os.path.join(SPEECH, "one_sentence.wav"), "rb") as w:
        frames = w.readframes(w.getnframes())
    return list(struct.unpack("<%dh" % (len(frames) // 2), frames))


def wav_bytes(data, *, tag=PCM, channels=1, rate_hz=16000, bits=16, data_size=None, sub_format=None, riff_size=None,
              before_data=b""):
    """A WAV file: a fmt chunk saying `tag`, `channels`, `rate_hz`, `bits` (WAVE_FORMAT_EXTENSIBLE
    with the tag `sub_format` when that is given), the chunks `before_data`, then `data`, whose chunk
    states `data_size` (default: its real size) in a RIFF chunk stating `riff_size` (default: its own)."""
    block_align = channels * bits // 8
    fmt_tag = tag if sub_format is None else EXTENSIBLE
    fmt = struct.pack("<HHIIHH", fmt_tag, channels, rate_hz, (rate_hz * block_align) & 0xFFFFFFFF, block_align, bits)
    if sub_format is not None:
        fmt += struct.pack("<HHI", 22, bits, 0x4 if channels == 1 else 0x3) + struct.pack("<H", sub_format) + SUBFORMAT_TAIL
    elif tag != PCM:
        fmt += struct.pack("<H", 0)
    stated = len(data) if data_size is None else data_size
    body = b"WAVE" + b"fmt " + struct.pack("<I", len(fmt)) + fmt + before_data + b"data" + struct.pack("<I", stated) + data
    riff = min(len(body), 0xFFFFFFFF) if riff_size is None else riff_size
    return b"RIFF" + struct.pack("<I", riff) + body


def chunk(name, payload):
    """A RIFF chunk, padded to an even size."""
    return name + struct.pack("<I", len(payload)) + payload + b"\x00" * (len(payload) % 2)


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
    pcm24 = b"".join(struct.pack("<i", s << 8)[:3] for s in voice)
    double_voice = bytearray(b"".join(struct.pack("<d", s / 32768.0) for s in voice))
    for i, value in enumerate((math.nan, math.inf, -math.inf)):
        at = (len(voice) // 4 * (i + 1)) * 8
        double_voice[at : at + 8 * 100] = struct.pack("<d", value) * 100
    huge_float = b"".join(struct.pack("<f", s * 1e34) for s in voice)
    tagged_mp3 = read(os.path.join(AUDIO, "ffmpeg_16000.mp3"))
    three_gp = read(os.path.join(AUDIO, "voice.3gp"))
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
        # Session 28: kinds the 41 lacked.
        "data_size_zero.wav": wav_bytes(pcm16(voice), data_size=0),
        "sizes_zero.wav": wav_bytes(pcm16(voice), data_size=0, riff_size=0),
        "data_size_ffffffff.wav": wav_bytes(pcm16(voice), data_size=0xFFFFFFFF),
        "extensible_pcm16.wav": wav_bytes(pcm16(voice), sub_format=PCM),
        "extensible_pcm24.wav": wav_bytes(pcm24, bits=24, sub_format=PCM),
        "extensible_float32_nan_inf.wav": wav_bytes(bytes(non_finite), bits=32, sub_format=IEEE_FLOAT),
        "float64_nan_inf.wav": wav_bytes(bytes(double_voice), tag=IEEE_FLOAT, bits=64),
        "float32_huge.wav": wav_bytes(huge_float, tag=IEEE_FLOAT, bits=32),
        "list_8mb.wav": wav_bytes(pcm16(voice), before_data=chunk(b"LIST", b"INFO" + b"\x00" * (8 << 20))),
        "list_past_end.wav": wav_bytes(pcm16(voice), before_data=b"LIST" + struct.pack("<I", 0x7FFFFFF0) + b"INFO"),
        "cut_mid_frame_tagged.mp3": tagged_mp3[: len(tagged_mp3) // 2 + 7],
        "stated_twice.mp3": mp3_with_stated_frames(tagged_mp3, 2),
        "stated_half.mp3": mp3_with_stated_frames(tagged_mp3, 0.5),
        "moov_at_end_cut.m4a": m4a[: len(m4a) // 2],
        "stated_twice.m4a": mp4_with_stated_length(m4a, 2),
        "stated_half.m4a": mp4_with_stated_length(m4a, 0.5),
        "two_tracks.mkv": read(os.path.join(AUDIO, "two_tracks.mkv")),
        "subtitle_only.mkv": read(os.path.join(AUDIO, "subtitle_only.mkv")),
        "voice.3gp": three_gp,
        "cut.3gp": three_gp[: len(three_gp) // 2],
        "noise_nb.amr": amr_noise(b"#!AMR\n", 0x3C, 31),
        "noise_wb.amr": amr_noise(b"#!AMR-WB\n", 0x44, 60),
        "cut_mid_frame.amr": amr_noise(b"#!AMR\n", 0x3C, 31)[:-15],
        # Session 29: kinds the 72 lacked.
        "bad_header.opus": opus_with_channels(read(os.path.join(AUDIO, "voice.opus")), 0),
        "bad_header.webm": webm_with_doc_type(read(os.path.join(AUDIO, "clip.webm")), b"xxxx"),
        "two_data_chunks.wav": two_data_chunks(good),
        "fmt_after_data.wav": fmt_after_data(good),
        "voice.aiff": aiff_bytes(voice),
        "voice.caf": caf_bytes(pcm16(voice)),
        "streaminfo_length.flac": flac[:5] + (100).to_bytes(3, "big") + flac[8:],
        # Session 30: samples that are not numbers, in another float container, and nothing else.
        "float32_nan_inf.caf": caf_bytes(bytes(non_finite), bits=32, is_float=True),
        "float32_all_nan.wav": wav_bytes(struct.pack("<f", math.nan) * len(voice), tag=IEEE_FLOAT, bits=32),
        # Session 33: bench/broken_files_sweep.py's finds.
        "four_bytes.wav": good[:4],
        "cut_in_data_header.wav": good[: header_end - 1],
        "header_only.flac": flac[: flac_frames_start(flac)],
        "cut_in_first_frame.flac": flac[: flac_frames_start(flac) + 100],
        "index_only.m4a": without_mdat(m4a),
        "cut_in_first_frames.mp3": tagged_mp3[: after_id3(tagged_mp3) + 150],
        "cut_in_header.mkv": read(os.path.join(AUDIO, "clip.mkv"))[:12],
        "damaged_header_page.ogg": with_second_page_damaged(read(os.path.join(SPEECH, "stereo_44k.ogg"))),
        "error_page.m4a": b"<!DOCTYPE html>\n<html><head><title>404 Not Found</title></head>\n"
        b"<body><h1>Not Found</h1><p>The requested URL was not found on this server.</p></body></html>\n",
        # Session 34: the sweep's files aligned without a word on main, and a few words as a recording.
        "nine_bytes.wav": b"not audio",
        "joined.wav": good + good,
        "joined.m4a": m4a + m4a,
        "joined.flac": flac + flac,
        "joined.mkv": read(os.path.join(AUDIO, "clip.mkv")) * 2,
        "huge_length.mp4": mp4_with_stated_length(read(os.path.join(AUDIO, "clip.mp4")), 1000),
        "huge_length.mkv": with_matroska_duration(read(os.path.join(AUDIO, "clip.mkv")), 1e15),
        "zeroed_block.wav": wav_bytes(pcm16(voice[:24000] + [0] * 2048 + voice[24000 + 2048 :])),
        "flipped_bytes.wav": wav_bytes(pcm16(with_high_bytes_flipped(voice, (3001, 12800, 20000, 36000, 40000)))),
    }


def with_second_page_damaged(ogg):
    """`ogg` with a byte of its second page (a Vorbis stream's comment and setup headers) changed: its
    check fails there."""
    data = bytearray(ogg)
    second = ogg_pages(ogg)[1][0]
    data[second + 27 + data[second + 26] + 10] ^= 0xFF
    return bytes(data)


def two_data_chunks(wav):
    """`wav` with its data split in two data chunks, as an editor that appends writes it."""
    at = wav.index(b"data")
    data = wav[at + 8 :]
    half = len(data) // 4 * 2
    body = b"WAVE" + wav[12:at] + chunk(b"data", data[:half]) + chunk(b"data", data[half:])
    return b"RIFF" + struct.pack("<I", len(body)) + body


def fmt_after_data(wav):
    """`wav` with its fmt chunk after its data chunk."""
    fmt_at = wav.index(b"fmt ")
    data_at = wav.index(b"data")
    return wav[:fmt_at] + wav[data_at:] + wav[fmt_at:data_at]


def opus_with_channels(opus, channels):
    """`opus` with its OpusHead stating `channels`, its first page's CRC made right again: a header
    that is damaged, not a page."""
    data = bytearray(opus)
    head = data.index(b"OpusHead")
    data[head + 9] = channels
    start, end, _ = ogg_pages(data)[0]
    set_ogg_page_crc(data, start, end)
    return bytes(data)


def webm_with_doc_type(webm, doc_type):
    """`webm` with the DocType of its EBML header ("webm") replaced."""
    at = webm.index(b"webm")
    return webm[:at] + doc_type + webm[at + 4 :]


def extended80(value):
    """An 80-bit IEEE 754 extended float (AIFF's sample rate) of a positive integer."""
    exponent = value.bit_length() - 1
    return struct.pack(">HQ", 16383 + exponent, value << (63 - exponent))


def aiff_bytes(samples, rate_hz=16000):
    """An AIFF (Apple's WAV, big-endian 16-bit) of `samples`."""
    comm = struct.pack(">hIh", 1, len(samples), 16) + extended80(rate_hz)
    ssnd = struct.pack(">II", 0, 0) + struct.pack(">%dh" % len(samples), *samples)
    body = b"AIFF" + b"COMM" + struct.pack(">I", len(comm)) + comm + b"SSND" + struct.pack(">I", len(ssnd)) + ssnd
    return b"FORM" + struct.pack(">I", len(body)) + body


def caf_bytes(pcm, *, bits=16, is_float=False, rate_hz=16000):
    """A CAF (Core Audio Format, iPhone's voice memos' container) of mono little-endian `pcm`: integers
    of `bits`, or floats."""
    flags = 0x2 | (0x1 if is_float else 0)  # little-endian; float
    desc = struct.pack(">d4sIIIII", rate_hz, b"lpcm", flags, bits // 8, 1, 1, bits)
    data = struct.pack(">I", 0) + pcm
    return (b"caff" + struct.pack(">HH", 1, 0) + b"desc" + struct.pack(">q", len(desc)) + desc + b"data" +
            struct.pack(">q", len(data)) + data)


def mp3_with_stated_frames(mp3, scale):
    """`mp3` with the frame count of its Xing/Info header (LAME's tag) scaled."""
    at = mp3_frame_count_at(mp3)
    frames = int.from_bytes(mp3[at : at + 4], "big")
    return mp3[:at] + int(frames * scale).to_bytes(4, "big") + mp3[at + 4 :]


def mp4_with_stated_length(mp4, scale):
    """`mp4` with the durations its mvhd, tkhd and mdhd boxes (version 0) state scaled."""
    data = bytearray(mp4)
    for box, offset in MP4_DURATION_FIELDS:
        at = data.index(box) + offset
        data[at : at + 4] = int(int.from_bytes(data[at : at + 4], "big") * scale).to_bytes(4, "big")
    return bytes(data)


def with_high_bytes_flipped(samples, indices):
    """16-bit `samples` with bit 14 of each at `indices` turned over: a byte a copy or a disk changed,
    high in its sample."""
    out = list(samples)
    for i in indices:
        out[i] = struct.unpack("<h", struct.pack("<H", (out[i] & 0xFFFF) ^ 0x4000))[0]
    return out


def amr_noise(magic, speech_header, speech_bytes, frames=150):
    """An AMR file (a phone's .amr: its magic, then 20 ms frames of a one-byte header and their
    bits) of `frames` frames of the highest rate, their bits pseudo-random: a noise."""
    state = 12345
    body = bytearray()
    for _ in range(frames):
        body.append(speech_header)
        for _ in range(speech_bytes):
            state = (state * 1103515245 + 12345) & 0x7FFFFFFF
            body.append(state >> 16 & 0xFF)
    return magic + bytes(body)


def flac_with_total(flac, scale):
    """`flac` with its STREAMINFO's total samples scaled."""
    return with_flac_total_samples(flac, min(int(flac_total_samples(flac) * scale), FLAC_MAX_TOTAL))


def ten_hour_silence(folder, name="ten_hours_silent.wav", rate_hz=16000):
    """A WAV of 10 hours of silence, sparse on disk: its header, then a hole of zeros."""
    data_size = 10 * 3600 * rate_hz * 2
    path = write(folder, name, wav_bytes(b"", rate_hz=rate_hz, data_size=data_size))
    os.truncate(path, os.path.getsize(path) + data_size)
    return path


def silence_then_voice(folder, hours, name="silence_then_voice.wav"):
    """A WAV of `hours` of silence, sparse on disk, then one_sentence's voice: a recorder left
    running before the speech."""
    voice = pcm16(speech_samples())
    silence_size = int(hours * 3600) * 16000 * 2
    path = write(folder, name, wav_bytes(b"", data_size=silence_size + len(voice)))
    with open(path, "ab") as f:
        f.truncate(os.path.getsize(path) + silence_size)
        f.seek(0, os.SEEK_END)
        f.write(voice)
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
        # Session 28: kinds the nine lacked.
        "utf16le_bom.txt": "\ufeff小朋友們在公園裡放風箏。\r\n".encode("utf-16-le"),
        "utf16be_bom.txt": "\ufeff小朋友們在公園裡放風箏。\n".encode("utf-16-be"),
        "utf8_bom.txt": "\ufeff小朋友們在公園裡放風箏。\n".encode(),
        "gb18030.txt": "小朋友们在公园里放风筝。\n".encode("gb18030"),
        "crlf.txt": "小朋友們在公園裡\r\n放風箏。\r\n".encode(),
        "cr_only.txt": "小朋友們在公園裡\r放風箏。\r".encode(),
        "bom_in_middle.txt": "小朋友們在公園裡\ufeff放風箏。\n".encode(),
        "nul_bytes.txt": "小朋友們在公園裡\0放風箏。\n".encode(),
        # Session 29: kinds the seventeen lacked.
        "punctuation_emoji.txt": "🎉！！😀……。🙏？".encode(),
        "wav_as_transcript.txt": read(os.path.join(SPEECH, "one_sentence.wav")),
        "png_as_transcript.txt": b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", b"\x00" * 13) + bytes(range(256)) * 4,
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

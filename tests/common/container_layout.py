"""Where the parts of an audio or video file stand: Ogg pages and their checksum, FLAC's metadata
blocks and stated length, MP4's top-level boxes and stated durations, an MP3's ID3v2 tag and LAME's
frame count, Matroska's stated duration. One reading for the two that damage files on purpose, tests/cli/bad_inputs.py and
bench/broken_files_sweep.py, so that a damage lands where both mean it to."""

import struct

# The boxes of an MP4 that state its duration, and where in each (version 0) the duration stands.
MP4_DURATION_FIELDS = ((b"mvhd", 20), (b"tkhd", 24), (b"mdhd", 20))
# FLAC's STREAMINFO states the total samples in 36 bits, the low nibble of byte 21 on.
FLAC_TOTAL_AT, FLAC_MAX_TOTAL = 21, 0xFFFFFFFFF


def ogg_crc(page):
    """The CRC of an Ogg page (its CRC field zero): polynomial 0x04C11DB7, not reflected."""
    crc = 0
    for byte in page:
        crc ^= byte << 24
        for _ in range(8):
            crc = (crc << 1) ^ 0x04C11DB7 if crc & 0x80000000 else crc << 1
        crc &= 0xFFFFFFFF
    return crc


def ogg_pages(data):
    """(start, end, granule) of each Ogg page."""
    pages, at = [], 0
    while data[at : at + 4] == b"OggS":
        segments = data[at + 26]
        body = sum(data[at + 27 : at + 27 + segments])
        end = at + 27 + segments + body
        pages.append((at, end, struct.unpack_from("<q", data, at + 6)[0]))
        at = end
    return pages


def set_ogg_page_crc(data, start, end):
    """Makes the CRC of the page at `start`..`end` of `data` (a bytearray) right again after a change."""
    data[start + 22 : start + 26] = b"\x00" * 4
    struct.pack_into("<I", data, start + 22, ogg_crc(bytes(data[start:end])))


def flac_frames_start(flac):
    """Where a FLAC's first frame starts: after "fLaC" and its metadata blocks (the last flagged)."""
    at = 4
    while True:
        is_last, length = flac[at] & 0x80, int.from_bytes(flac[at + 1 : at + 4], "big")
        at += 4 + length
        if is_last:
            return at


def flac_total_samples(flac):
    return int.from_bytes(flac[FLAC_TOTAL_AT : FLAC_TOTAL_AT + 5], "big") & FLAC_MAX_TOTAL


def with_flac_total_samples(flac, total):
    """`flac` with its STREAMINFO stating `total` samples."""
    head = int.from_bytes(flac[FLAC_TOTAL_AT : FLAC_TOTAL_AT + 5], "big")
    head = (head & ~FLAC_MAX_TOTAL) | total
    return flac[:FLAC_TOTAL_AT] + head.to_bytes(5, "big") + flac[FLAC_TOTAL_AT + 5 :]


def mp4_boxes(data):
    """(type, start, end) of the top-level boxes of an MP4/MOV."""
    boxes, at = [], 0
    while at + 8 <= len(data):
        size = struct.unpack_from(">I", data, at)[0]
        kind = data[at + 4 : at + 8]
        if size == 1:
            size = struct.unpack_from(">Q", data, at + 8)[0]
        if size < 8:
            break
        boxes.append((kind, at, at + size))
        at += size
    return boxes


def without_mdat(mp4):
    """An MP4's top-level boxes but its sound's (mdat): an index with no sound."""
    return b"".join(mp4[start:end] for kind, start, end in mp4_boxes(mp4) if kind != b"mdat")


def after_id3(mp3):
    """Where an MP3's first frame starts: after its ID3v2 tag (a size of 4 bytes of 7 bits)."""
    if mp3[:3] != b"ID3":
        return 0
    return 10 + sum((mp3[6 + i] & 0x7F) << (7 * (3 - i)) for i in range(4))


def mp3_frame_count_at(mp3):
    """Where LAME's Xing/Info tag states an MP3's frame count (4 bytes, big-endian), or None."""
    tag = max(mp3.find(b"Xing"), mp3.find(b"Info"))
    return None if tag < 0 else tag + 8


def with_matroska_duration(mkv, milliseconds):
    """`mkv` with its Segment's Info stating `milliseconds` (Duration, 0x4489: a float of 4 or 8 bytes,
    in milliseconds at the default TimestampScale), or None where it states no duration (a browser's
    WebM recorder writes none)."""
    at = mkv.find(b"\x44\x89")
    if at < 0:
        return None
    size = mkv[at + 2] & 0x7F
    return mkv[: at + 3] + struct.pack(">d" if size == 8 else ">f", milliseconds) + mkv[at + 3 + size :]

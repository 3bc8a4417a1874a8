"""Damaged copies of the test recordings, as disks, downloads and recorders leave them, for the
Python and command tests (tests/audio/damaged_audio_test.cpp makes the same in C++)."""


def scratched_copy(source, target, share, seed=3, count=2000):
    """`source` with `count` pseudo-random bytes a `share` of the way in, as a bad sector or a broken
    download leaves them (the generator of damaged_audio_test.cpp), written to `target`."""
    data = bytearray(source.read_bytes())
    at = int(len(data) * share)
    for i in range(count):
        seed = (seed * 1664525 + 1013904223) & 0xFFFFFFFF
        data[at + i] = seed >> 24
    target.write_bytes(bytes(data))
    return target


def stale_wav_copy(source, target):
    """The WAV `source` with its data size halved, as a recorder that stopped without bringing its
    header up to date leaves it, written to `target`."""
    data = bytearray(source.read_bytes())
    at = data.find(b"data")
    size = int.from_bytes(data[at + 4:at + 8], "little")
    data[at + 4:at + 8] = ((size // 2) & ~3).to_bytes(4, "little")
    target.write_bytes(bytes(data))
    return target

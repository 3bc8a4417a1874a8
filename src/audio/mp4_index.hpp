// Whether an MP4-family file (MP4, M4A, MOV) lacks its index, told from its top-level boxes alone:
// FFmpeg only says "Invalid data found" of such a file, which is the commonest damage to a phone's
// recording (issue #13).
#ifndef TALKFACE_AUDIO_MP4_INDEX_HPP
#define TALKFACE_AUDIO_MP4_INDEX_HPP

#include <cstdint>
#include <optional>
#include <string>

namespace talkface::detail {

// True for a file that opens with an ISO base media "ftyp" box and whose top-level boxes, walked to
// the end of the file, hold no "moov": the index without which no sample can be found. Encoders and
// recorders write it last unless told otherwise (ffmpeg's +faststart), so a file cut while it was
// copied or recorded, or one still being written, lacks it. False for anything else, including a
// file that cannot be read (the caller reports that).
bool is_mp4_without_index(const std::string& path);

// Where an MP4-family file's index (its top-level "moov" box) lies, in bytes from the file's start,
// and the first byte where its box structure breaks, if it does.
struct Mp4Index {
    std::uint64_t start_byte = 0;
    std::uint64_t end_byte = 0;
    std::optional<std::uint64_t> broken_at_byte;
    // Whether an edit list ("elst") lies among the boxes walked: where none does (a fragmented MP4
    // as FFmpeg 5.1 writes it), nothing states an encoder's delay.
    bool has_edit_list = false;
};

// The index of a file that opens with an "ftyp" box and holds a "moov" box among its top-level
// boxes; nullopt for anything else. The index's box structure is walked through the boxes that
// hold boxes (trak, mdia, minf, stbl ...): a box whose type is not four characters, or whose size
// runs past its parent's end or leaves part of it over, breaks it, as a scratch or a bad sector
// inside the index leaves it (FFmpeg then finds no sound track, or "Invalid data"). A table's
// entries are not checked, only the boxes around them.
std::optional<Mp4Index> find_mp4_index(const std::string& path);

// Where a second MP4-family file begins inside the file at `path`: the byte of a top-level "ftyp"
// box after the first, as two files joined leave it (a copy appended to itself, `cat` of two
// recordings); FFmpeg reads the first file's index and stops at its end, silently. nullopt where
// there is none, or the top-level boxes break before one (a box cut off, bytes that are no box).
std::optional<std::uint64_t> second_file_byte(const std::string& path);

}  // namespace talkface::detail

#endif

// A second MP3 stream joined to a first where no tag tells it (issue 13, "Bad input"): sox writes an
// MP3 of frames alone, no ID3 tag and no Xing tag, so two different recordings of one rate and one
// bit rate, joined by `cat`, are frames the decoder reads on as one stream, with nothing in their
// headers, their length or their rate to mark the join. What marks it is the bit reservoir: a
// Layer III frame's main data may start in the bytes the frames before it left unused (its
// main_data_begin counts them back), and an encoder fills them, as a stream's bytes are its budget;
// only a stream's first frame starts its data afresh, with none. A frame that carries sound and
// starts afresh where the frames before left bytes unused is a second encoder's first frame. So is
// a frame holding an encoder's header (a Xing, Info or VBRI tag: LAME and FFmpeg write one, in a
// stream's first frame) anywhere after the first frame: where the second recording opens in digital
// silence its first frames are empty, and point nowhere in the reservoir (LAME as FFmpeg runs it).
#ifndef TALKFACE_AUDIO_MP3_RESTART_HPP
#define TALKFACE_AUDIO_MP3_RESTART_HPP

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>

namespace talkface::detail {

// Where a second stream starts: the frame's first byte, its time as the file decodes (the frames of
// sound before it, at the first frame's rate, less the delay the reader drops from the start), and how many
// reservoir bytes the frames before it left that it did not use; or that the frame holds an encoder's header
// (then no byte was left unused that tells).
struct Mp3Restart {
    std::uint64_t byte = 0;
    double seconds = 0.0;
    std::size_t unused_bytes = 0;
    bool is_header_frame = false;
};

// The first restart in the file at `path`, if it opens as an MP3 (an ID3 tag, or a Layer III frame):
// its frames walked by their headers and side information (a second ID3 tag stepped over) to the
// first that is not a Layer III frame of the first's version, rate and channels. Reads a frame's
// first bytes only.
std::optional<Mp3Restart> restarted_mp3_stream(const std::string& path);

}  // namespace talkface::detail

#endif

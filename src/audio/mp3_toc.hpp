// A variable-rate MP3's table of contents: the Xing (or LAME's Info) header in its first frame
// states how many frames and bytes the stream holds and, for each 1% of its time, how far into its
// bytes that time lies (in 256ths). Players seek by it; the reader places what follows a scratch
// by it (ffmpeg_source.cpp), since a variable rate gives the lost bytes no time of their own.
#ifndef TALKFACE_AUDIO_MP3_TOC_HPP
#define TALKFACE_AUDIO_MP3_TOC_HPP

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace talkface::detail {

struct Mp3Toc {
    std::int64_t first_byte = 0;    // where the stream's first frame (the header's own) starts in the file
    std::int64_t stream_bytes = 0;  // the stream's bytes from there, as the header states them
    double samples = 0.0;           // the stream's length in samples, as the header states it
    std::array<unsigned char, 100> entries{};  // entry i: the byte at i% of the time, in 256ths
    // "Xing", which LAME writes for a variable rate ("Info" for a constant one): the first frames
    // of a variable-rate file, silence, may all be of one size.
    bool is_variable_rate = false;

    // The sample at which the byte `file_byte` of the file lies: the table read backwards, linear
    // between its entries. Accurate to a 256th of the stream's bytes at each entry, which the
    // difference of two nearby bytes mostly cancels.
    double sample_at(std::int64_t file_byte) const;
};

// The table of `file` (its first bytes: an ID3v2 tag, then the first frame), if its first frame is
// MPEG Layer III with a Xing or Info header that states its frames and holds a table. The stream's
// bytes are the header's, or the file's (`file_size`) from the first frame when it does not state them.
std::optional<Mp3Toc> read_mp3_toc(std::string_view file, std::int64_t file_size);

// read_mp3_toc of the file at `path`; none if it cannot be read.
std::optional<Mp3Toc> read_mp3_toc_file(const std::string& path);

}  // namespace talkface::detail

#endif

// An MPEG Layer III frame's header, and a variable-rate MP3's table of contents, which players seek by: the
// reader places what follows a scratch by it (ffmpeg_source.cpp), since a variable rate gives the lost bytes
// no time of their own. Two encoders write one in the stream's first frame, in two layouts:
// - the Xing (or LAME's Info) header: how many frames and bytes the stream holds and, for each 1% of
//   its time, how far into its bytes that time lies (in 256ths);
// - the VBRI header of Fraunhofer's encoder: how many frames the stream holds and, for each stretch
//   of a fixed number of frames, how many bytes that stretch takes (an entry of 1-4 bytes times a
//   scale), counted from the frame after the header's own.
#ifndef TALKFACE_AUDIO_MP3_TOC_HPP
#define TALKFACE_AUDIO_MP3_TOC_HPP

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace talkface::detail {

// What an MPEG Layer III frame's 4-byte header says of the frame.
struct Mp3FrameHeader {
    int version = 0;  // 3 MPEG-1, 2 MPEG-2, 0 MPEG-2.5
    bool is_mono = false;
    bool has_crc = false;  // a 16-bit check follows the header, before the side information
    int rate_hz = 0;
    std::size_t samples = 0;  // a frame's samples: 1152 (MPEG-1), 576
    std::size_t bytes = 0;    // the frame's own size, padding byte included; 0 in free format
};

// The header at the start of `bytes` (at least 4), if it is an MPEG Layer III frame's.
std::optional<Mp3FrameHeader> read_mp3_frame_header(std::string_view bytes);

// The size of a Layer III frame's side information, after its header (and its check, if it has one):
// where its main data's first byte lies.
std::size_t mp3_side_info_bytes(const Mp3FrameHeader& header);

// Where a Xing or Info tag stands in a frame: after its header and where its side information would stand
// without a check. LAME writes a header frame with a check (-p) so, the check's 2 bytes in the place of
// the side information's first 2 ("the Xing data still starts at the same offset", its VbrTag.c), and
// FFmpeg reads the tag there, as it reads its own, which has no check.
std::size_t mp3_xing_tag_at(const Mp3FrameHeader& header);

// Whether `frame` (a Layer III frame read from its header on, `header` its header) holds an encoder's
// header, a Xing, Info or VBRI tag: LAME, FFmpeg and Fraunhofer's encoder write one in a recording's
// first frame, in place of sound.
bool is_mp3_tag_frame(std::string_view frame, const Mp3FrameHeader& header);

// An MP3 without a LAME tag (sox writes none) does not say how many samples of encoder delay lead
// its first frame, and FFmpeg then keeps them: sox's 22.05 kHz MP3s came out 50 ms late. LAME, the
// encoder behind sox, ffmpeg and Audacity alike, delays by 576 samples, and the decoder adds 529: the
// numbers a LAME tag would carry.
constexpr std::size_t kUntaggedMp3DelayFrames = 576 + 529;

// The samples the reader drops from the start of the stream whose first frame is `frame` (read from
// its header on, `header` its header): the encoder's delay a LAME tag after a Xing or Info tag states
// (written by LAME, or by FFmpeg as "Lavf" or "Lavc"), and the decoder's 529, as FFmpeg's MP3 reader
// drops them; kUntaggedMp3DelayFrames without one (ffmpeg_source.cpp drops those).
std::size_t mp3_start_skip_frames(std::string_view frame, const Mp3FrameHeader& header);

struct Mp3Toc {
    // A byte of the file and the sample the table places there.
    struct Point {
        double byte = 0.0;
        double sample = 0.0;
    };
    // In order of byte and of sample, from the stream's start to its end as the header states them.
    std::vector<Point> points;
    // "Xing", which LAME writes for a variable rate ("Info" for a constant one), or VBRI, which
    // Fraunhofer's encoder writes only for a variable rate: the first frames of a variable-rate
    // file, silence, may all be of one size.
    bool is_variable_rate = false;
    // A VBRI table's points lie where frames start (each entry counts whole frames, to its scale's
    // rounding); a Xing table's lie between them, its bytes floored to 256ths of the stream (77 ms
    // of a 20 s recording), so only the difference of two nearby bytes' samples is accurate.
    bool points_on_frames = false;

    // The sample at which the byte `file_byte` of the file lies: the table read backwards, linear
    // between its points. Accurate to an entry's rounding (a 256th of the stream's bytes in a Xing
    // table, the scale in a VBRI one), which the difference of two nearby bytes mostly cancels.
    double sample_at(std::int64_t file_byte) const;
};

// Where an MP3's first frame starts in `file` (its first bytes): past an ID3v2 tag (its size is 4
// bytes of 7 bits each, a footer after it if a flag says so); 0 without one.
std::size_t after_id3(std::string_view file);

// The table of `file` (its first bytes: an ID3v2 tag, then the first frame), if its first frame is
// MPEG Layer III with a Xing or Info header that states its frames and holds a table, or with a
// VBRI header whose table lies within `file`. A Xing stream's bytes are the header's, or the file's
// (`file_size`) from the first frame when it does not state them.
std::optional<Mp3Toc> read_mp3_toc(std::string_view file, std::int64_t file_size);

// read_mp3_toc of the file at `path`; none if it cannot be read.
std::optional<Mp3Toc> read_mp3_toc_file(const std::string& path);

}  // namespace talkface::detail

#endif

#include "audio/mp3_restart.hpp"

#include <algorithm>
#include <string_view>

#include "audio/file_blocks.hpp"
#include "audio/mp3_toc.hpp"

namespace talkface::detail {

namespace {

// The most bytes read of a frame: its header, check and side information, and the name of a tag that
// may follow them (Xing or Info), or follow the header 32 bytes on (VBRI).
constexpr std::size_t kMostFrameHead = 4 + 2 + 32 + 4;

// A frame that starts afresh carries sound, or none: a frame holding its scale factors alone (20-22
// bits in FFmpeg's LAME frames of near silence, which begin at their own byte) is no restart. A frame
// of none (digital silence) points where its data would begin: LAME as sox runs it points at the
// whole reservoir, so a stream's first empty frame points at its own area, and the next frame's data
// begins there; LAME as FFmpeg runs it writes 0 in every empty frame, and the frame after one points
// back past it, at the whole reservoir, as far as its 8 or 9 bits reach. Where a frame's area is more
// than the reservoir LAME keeps (FFmpeg's and sox's at 16 kHz 32 kb/s: 131 bytes, 124 kept), its empty
// frames point at the reservoir they hold, 124 bytes back, and a stream's first empty frame at none: the
// next empty frame points inside its area, short of its start. A continuing stream's empty frame points
// nowhere only where its empty frames all do (the next one then points nowhere too), so an empty frame
// after it that points into its area keeps the restart.
constexpr std::size_t kLeastSoundBits = 128;

// LAME keeps no more reservoir than its most (at most the 255 or 511 bytes main_data_begin reaches):
// where a frame's own data leaves that much of its area unused, what the reservoir would hold past its
// most is written out as ancillary bytes, the oldest first, and the frame points back past none of them
// (its reservoir.c, "drain as many bits as possible into previous frame ancillary data"). So a frame of a
// continuing stream starts afresh where its area is large for its sound: a person's speech ending in
// digital silence at 16 kHz 128 kb/s (253 bytes of sound in a 563-byte area), a steady tone's every
// frame. The most is not written in the stream, but it is at least the most reservoir the frames before
// were seen to point back into: a frame leaving no fewer bytes unused than that could be such a drain,
// and is no restart.
bool may_drain_reservoir(std::size_t area, std::size_t bits, std::size_t most_begin_back) {
    return area - std::min(area, (bits + 7) / 8) >= most_begin_back;
}

// The fewest reservoir bytes left unused that a restart throws away: a frame's main data ends
// within a byte (its bits are not padded), and an encoder that starts afresh leaves many more (LAME's
// last frames of a stream: 100-255 in sox's and FFmpeg's files).
constexpr std::size_t kLeastUnusedBytes = 8;

// What a Layer III frame's side information says of its main data: where it begins (bytes back
// from the frame's own main data) and how many bits it takes, every granule and channel summed.
struct MainData {
    std::size_t begin_back = 0;
    std::size_t bits = 0;
};

// `side` (mp3_side_info_bytes(header) bytes) read field by field, most significant bit first:
// main_data_begin (9 bits in MPEG-1, 8 in MPEG-2 and 2.5), the private bits and (MPEG-1) the scale
// factor selection, then for each granule (2 in MPEG-1, 1) and channel, part2_3_length (12 bits)
// and the rest of that channel's fields (47 bits in MPEG-1, 51).
MainData read_main_data(std::string_view side, const Mp3FrameHeader& header) {
    std::size_t bit = 0;
    const auto take = [&](std::size_t count) {
        std::size_t value = 0;
        for (std::size_t k = 0; k < count; ++k, ++bit)
            value = value << 1 | ((static_cast<unsigned char>(side[bit / 8]) >> (7 - bit % 8)) & 1);
        return value;
    };
    const bool is_mpeg1 = header.version == 3;
    const std::size_t channels = header.is_mono ? 1 : 2;
    MainData data;
    data.begin_back = take(is_mpeg1 ? 9 : 8);
    bit += is_mpeg1 ? (header.is_mono ? 5 : 3) + 4 * channels : channels;
    for (std::size_t granule = 0; granule < (is_mpeg1 ? 2U : 1U); ++granule)
        for (std::size_t channel = 0; channel < channels; ++channel) {
            data.bits += take(12);
            bit += is_mpeg1 ? 47 : 51;
        }
    return data;
}

bool same_stream(const Mp3FrameHeader& first, const Mp3FrameHeader& frame) {
    return frame.version == first.version && frame.rate_hz == first.rate_hz && frame.is_mono == first.is_mono;
}

}  // namespace

std::optional<Mp3Restart> restarted_mp3_stream(const std::string& path) {
    FileBlocks file(path);
    std::uint64_t at = after_id3(file.at(0, 10));
    const auto first = read_mp3_frame_header(file.at(at, 4));
    if (!first || first->bytes == 0) return std::nullopt;
    // The join's time as the reader decodes the file: the first frame is no sound where it is an
    // encoder's header, and the encoder's and decoder's delay is dropped from the start (a user cuts
    // the file there: the frames alone counted 3.42 s where the second recording starts at 3.315).
    const std::string_view first_frame = file.at(at, first->bytes);
    const std::size_t header_frames = is_mp3_tag_frame(first_frame, *first) ? 1 : 0;
    const std::size_t skipped = mp3_start_skip_frames(first_frame, *first);
    const auto join_seconds = [&](std::size_t frames_before) {
        const std::size_t samples = (frames_before - header_frames) * first->samples;
        return static_cast<double>(samples > skipped ? samples - skipped : 0) / first->rate_hz;
    };

    // In the bytes of the frames' main data areas (each frame's bytes past its side information)
    // laid end to end: where the current frame's area starts, and where the main data before it ends.
    std::uint64_t area_start = 0;
    std::optional<std::uint64_t> data_end;
    std::size_t frames_before = 0;
    // A restart, kept once a frame follows it: an empty frame's, once the next frame's data begins
    // where the empty frame's area began, or, the next frame empty too, inside that area (kLeastSoundBits).
    std::optional<Mp3Restart> candidate;
    std::optional<std::size_t> next_begin_back;
    std::size_t most_begin_back = 0;
    while (true) {
        std::string_view bytes = file.at(at, kMostFrameHead);
        if (bytes.substr(0, 3) == "ID3") {
            at += after_id3(file.at(at, 10));
            bytes = file.at(at, kMostFrameHead);
        }
        const auto header = read_mp3_frame_header(bytes);
        if (!header || header->bytes == 0 || !same_stream(*first, *header)) return std::nullopt;
        const std::size_t side_start = 4 + (header->has_crc ? 2 : 0);
        const std::size_t side_bytes = mp3_side_info_bytes(*header);
        if (bytes.size() < side_start + side_bytes + 4 || header->bytes < side_start + side_bytes)
            return std::nullopt;
        // An encoder's header frame (a Xing, Info or VBRI tag) holds no sound, nor a reservoir.
        const bool is_tag_frame = is_mp3_tag_frame(bytes, *header);
        if (is_tag_frame && frames_before > 0) return Mp3Restart{at, join_seconds(frames_before), 0, true};
        if (!is_tag_frame) {
            const MainData data = read_main_data(bytes.substr(side_start, side_bytes), *header);
            if (candidate && (!next_begin_back || data.begin_back == *next_begin_back ||
                              (data.bits == 0 && data.begin_back > 0 && data.begin_back <= *next_begin_back)))
                return candidate;
            candidate.reset();
            if (data.begin_back > area_start) return std::nullopt;  // data before the stream's start
            const std::uint64_t begin = area_start - data.begin_back;
            const std::size_t area = header->bytes - side_start - side_bytes;
            if (data_end && data.begin_back == 0 && begin >= *data_end + kLeastUnusedBytes &&
                (data.bits >= kLeastSoundBits || data.bits == 0) &&
                !may_drain_reservoir(area, data.bits, most_begin_back)) {
                candidate =
                    Mp3Restart{at, join_seconds(frames_before), static_cast<std::size_t>(begin - *data_end)};
                next_begin_back = data.bits == 0 ? std::optional<std::size_t>(area) : std::nullopt;
            }
            data_end = begin + (data.bits + 7) / 8;
            area_start += area;
            most_begin_back = std::max(most_begin_back, data.begin_back);
        }
        ++frames_before;
        at += header->bytes;
    }
}

}  // namespace talkface::detail

#include "audio/joined_copy.hpp"

#include <algorithm>
#include <array>
#include <fstream>
#include <functional>
#include <string_view>
#include <utility>
#include <vector>

#include "audio/chained_stream.hpp"
#include "audio/mp3_restart.hpp"
#include "audio/mp3_toc.hpp"
#include "audio/repeated_sound.hpp"
#include "common/number_format.hpp"

namespace talkface::detail {

namespace {

// How a note of a join ends: what it is, and what to do.
constexpr const char* kJoinedToFirst =
    ", joined to the first (as an upload or a copy that appends to a file leaves it); cut the file "
    "there and align each recording on its own";
std::string second_begins_there() {
    return std::string(": a second copy of the recording, or a second recording, begins there") +
           kJoinedToFirst;
}

// A join whose time the file does not tell.
JoinedRecording untimed(std::string description) {
    return {std::move(description), std::nullopt};
}

// The first byte from `start` on of the file `in` reads where `find` finds what it looks for: the
// file read a block at a time, each block after the last `overlap` bytes of the one before, so
// that what spans two blocks is found; `find` gets a block and gives the offset in it, or nullopt.
std::optional<std::uint64_t> find_in_blocks(
    std::ifstream& in, std::uint64_t start, std::size_t overlap,
    const std::function<std::optional<std::size_t>(std::string_view)>& find) {
    constexpr std::size_t kBlockBytes = 1 << 20;
    std::vector<char> block(kBlockBytes + overlap);
    in.clear();
    in.seekg(static_cast<std::streamoff>(start));
    std::uint64_t block_start = start;  // the file's byte at block[0]
    std::size_t carried = 0;
    while (in) {
        in.read(block.data() + carried, static_cast<std::streamsize>(kBlockBytes));
        const std::size_t held = carried + static_cast<std::size_t>(in.gcount());
        if (const auto found = find(std::string_view(block.data(), held))) return block_start + *found;
        if (held <= overlap) return std::nullopt;
        carried = overlap;
        std::copy(block.begin() + static_cast<std::ptrdiff_t>(held - carried),
                  block.begin() + static_cast<std::ptrdiff_t>(held), block.begin());
        block_start += held - carried;
    }
    return std::nullopt;
}

// The most bytes from a frame's start to its Xing or Info tag's end.
constexpr std::size_t kMostTagEnd = 4 + 32 + 4;

// Where a Layer III frame holding a Xing or Info tag starts in `bytes`: the tag where mp3_xing_tag_at
// places it, the side information before it all zero (an encoder's header frame holds no sound) but for
// a check's 2 bytes after the header, where the frame has one.
std::optional<std::size_t> tag_frame_in(std::string_view bytes) {
    for (const std::string_view tag : {"Xing", "Info"}) {
        for (std::size_t at = bytes.find(tag); at != std::string_view::npos; at = bytes.find(tag, at + 1)) {
            for (const std::size_t side_info : {9, 17, 32}) {
                if (at < 4 + side_info) continue;
                const std::size_t frame = at - 4 - side_info;
                const auto header = read_mp3_frame_header(bytes.substr(frame, 4));
                if (!header || mp3_side_info_bytes(*header) != side_info) continue;
                const std::size_t check = header->has_crc ? 2 : 0;
                const std::string_view side = bytes.substr(frame + 4 + check, side_info - check);
                if (std::all_of(side.begin(), side.end(), [](char byte) { return byte == 0; })) return frame;
            }
        }
    }
    return std::nullopt;
}

// Where an MP3's first frame starts (past its ID3 tag) and its header, in a file that opens as an
// MP3 (an ID3 tag, or a Layer III frame).
std::optional<std::pair<std::uint64_t, Mp3FrameHeader>> first_mp3_frame(std::ifstream& in) {
    std::string head(10, '\0');
    in.clear();
    in.seekg(0);
    if (!in.read(head.data(), static_cast<std::streamsize>(head.size()))) return std::nullopt;
    const std::size_t first_frame = after_id3(head);
    std::array<char, 4> frame{};
    in.seekg(static_cast<std::streamoff>(first_frame));
    if (!in.read(frame.data(), frame.size())) return std::nullopt;
    const auto header = read_mp3_frame_header(std::string_view(frame.data(), frame.size()));
    if (!header) return std::nullopt;
    return std::pair{static_cast<std::uint64_t>(first_frame), *header};
}

// The first byte past an MP3's first frame where a frame holding a Xing or Info tag starts: LAME and
// FFmpeg write the tag once, in a recording's first frame (its length and table of contents), so a
// second one starts a second recording, tagged with ID3 or not, the same recording or another.
std::optional<std::uint64_t> second_mp3_tag_frame_byte(std::ifstream& in) {
    const auto first = first_mp3_frame(in);
    if (!first) return std::nullopt;
    return find_in_blocks(in, first->first + 1, kMostTagEnd - 1, tag_frame_in);
}

// The byte where the frames an MP3's first frame's Xing or Info tag counts end, where a second
// stream starts there (a frame, or an ID3 tag) rather than the file ending (or a tag that closes it,
// ID3v1's or APE's): a second recording, even one with no tag of its own. Reads the header only.
std::optional<std::uint64_t> past_stated_mp3_bytes(std::ifstream& in) {
    const auto first = first_mp3_frame(in);
    if (!first) return std::nullopt;
    const auto& [first_frame, header] = *first;
    std::array<char, 16> tag{};  // "Xing", its flags, its frame count, its byte count
    in.seekg(static_cast<std::streamoff>(first_frame + mp3_xing_tag_at(header)));
    if (!in.read(tag.data(), tag.size())) return std::nullopt;
    const std::string_view fields(tag.data(), tag.size());
    if (fields.substr(0, 4) != "Xing" && fields.substr(0, 4) != "Info") return std::nullopt;
    const auto big_endian = [&](std::size_t at) {
        std::uint32_t value = 0;
        for (std::size_t k = at; k < at + 4; ++k) value = value << 8 | static_cast<unsigned char>(fields[k]);
        return value;
    };
    constexpr std::uint32_t kFrames = 1;
    constexpr std::uint32_t kBytes = 2;
    const std::uint32_t flags = big_endian(4);
    if ((flags & kBytes) == 0) return std::nullopt;
    const std::uint64_t end = first_frame + big_endian((flags & kFrames) != 0 ? 12 : 8);
    std::array<char, 4> next{};
    in.seekg(static_cast<std::streamoff>(end));
    if (!in.read(next.data(), next.size())) return std::nullopt;
    const std::string_view after(next.data(), next.size());
    if (after.substr(0, 3) != "ID3" && !read_mp3_frame_header(after)) return std::nullopt;
    return end;
}

// The first byte past a FLAC's start where a second FLAC stream starts: its "fLaC" and the header of
// the STREAMINFO block every stream opens with (its type 0 and length 34, whether or not it is the
// last metadata block), 8 bytes no frame's sound holds by chance. A second recording's STREAMINFO
// states its own length, frame sizes and checksum, so its first 32 bytes are not the first's.
std::optional<std::uint64_t> second_flac_stream_byte(std::ifstream& in) {
    std::array<char, 4> signature{};
    in.clear();
    in.seekg(0);
    if (!in.read(signature.data(), signature.size()) || std::string_view(signature.data(), 4) != "fLaC")
        return std::nullopt;
    constexpr std::size_t kStreamHeader = 8;
    return find_in_blocks(in, 4, kStreamHeader - 1, [](std::string_view block) -> std::optional<std::size_t> {
        for (std::size_t at = block.find("fLaC"); at != std::string_view::npos;
             at = block.find("fLaC", at + 1)) {
            const std::string_view header = block.substr(at + 4, 4);
            if (header.size() == 4 && (static_cast<unsigned char>(header[0]) & 0x7F) == 0 &&
                header.substr(1) == std::string_view("\0\0\x22", 3))
                return at;
        }
        return std::nullopt;
    });
}

}  // namespace

std::optional<std::uint64_t> repeated_opening_byte(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::string opening(kOpeningBytes, '\0');
    if (!in.read(opening.data(), static_cast<std::streamsize>(opening.size()))) return std::nullopt;
    const std::string_view start(opening);
    if (start.substr(0, 4) != "fLaC" && start.substr(0, 4) != "OggS" &&
        start.substr(0, 4) != "\x1a\x45\xdf\xa3" && start.substr(0, 3) != "ID3")
        return std::nullopt;
    return find_in_blocks(in, kOpeningBytes, kOpeningBytes - 1,
                          [&](std::string_view block) -> std::optional<std::size_t> {
                              const std::size_t found = block.find(start);
                              if (found == std::string_view::npos) return std::nullopt;
                              return found;
                          });
}

std::optional<JoinedRecording> describe_second_stream(const std::string& path) {
    if (const auto chained = chained_stream(path)) {
        const std::string where = " starts at byte " + std::to_string(chained->byte);
        const bool is_first_timed = chained->first_seconds > 0.0;
        const std::string first_time =
            is_first_timed ? " (" + format_fixed(chained->first_seconds, 3) + " s)" : std::string();
        const std::optional<double> second_starts_s =
            is_first_timed ? std::optional<double>(chained->first_seconds) : std::nullopt;
        if (chained->container == ChainedStream::Container::matroska) {
            const std::string segment_end = chained->is_live_segment
                                                ? ", where the first's Segment, of unknown size (a live "
                                                  "recording's, as a browser writes it), ends" +
                                                      first_time
                                                : ", where the first's Segment ends" + first_time;
            return JoinedRecording{
                "a second Matroska file (its own EBML header and Segment, which open a recording)" + where +
                    segment_end + second_begins_there(),
                second_starts_s};
        }
        const std::string first_end = is_first_timed ? ", where the first ends" + first_time : std::string();
        return JoinedRecording{"a second Ogg stream (its own header pages, which open a recording)" + where +
                                   first_end + second_begins_there(),
                               second_starts_s};
    }
    const auto restart = restarted_mp3_stream(path);
    if (!restart) return std::nullopt;
    const std::string frame = "its MP3 frame at byte " + std::to_string(restart->byte) + " (" +
                              format_fixed(restart->seconds, 3) + " s) ";
    const std::string why =
        restart->is_header_frame
            ? "holds an encoder's header (a Xing, Info or VBRI tag), which an encoder writes once, in a "
              "recording's first frame"
            : "begins its data afresh, throwing away the " + std::to_string(restart->unused_bytes) +
                  " bytes the frames before it left free for it, as only a recording's first frame does";
    return JoinedRecording{frame + why + second_begins_there(), restart->seconds};
}

std::optional<JoinedRecording> describe_joined_copy(const std::string& path) {
    const std::string joined = second_begins_there();
    if (const auto second = repeated_opening_byte(path)) {
        // A chained Ogg or Matroska file's second stream opens with the first's header bytes (a copy, or
        // two files of one encoder's settings): its walk tells where the first's sound ends.
        const auto chained = chained_stream(path);
        const bool is_timed = chained && chained->byte == *second && chained->first_seconds > 0.0;
        const std::string first_end =
            is_timed ? ", where the first recording ends (" + format_fixed(chained->first_seconds, 3) + " s)"
                     : std::string();
        return JoinedRecording{"its first " + std::to_string(kOpeningBytes) +
                                   " bytes (its header) recur at byte " + std::to_string(*second) +
                                   first_end + joined,
                               is_timed ? std::optional<double>(chained->first_seconds) : std::nullopt};
    }
    std::ifstream in(path, std::ios::binary);
    if (const auto second = second_flac_stream_byte(in))
        return untimed(
            "a second FLAC stream header (\"fLaC\" and its STREAMINFO block, which open a recording) "
            "starts at byte " +
            std::to_string(*second) + joined);
    if (const auto second = second_mp3_tag_frame_byte(in))
        return untimed(
            "a second MP3 header frame (a Xing or Info tag, which an encoder writes once, in a "
            "recording's first frame) starts at byte " +
            std::to_string(*second) + joined);
    if (const auto end = past_stated_mp3_bytes(in))
        return untimed("its first frame's Xing or Info tag counts its MP3 frames to byte " +
                       std::to_string(*end) + ", and a second stream of frames starts there" + joined);
    if (const auto repeat = repeated_sound(path)) {
        const auto seconds = [&](std::size_t frame) {
            return format_fixed(static_cast<double>(frame) / repeat->sample_rate_hz, 3) + " s";
        };
        const std::size_t second_starts = repeat->repeat_frame - repeat->original_frame;
        return JoinedRecording{
            "its sound from " + seconds(repeat->repeat_frame) + " to its end is its sound from " +
                seconds(repeat->original_frame) +
                " on again, sample for sample, as no voice repeats itself: a second copy of the recording "
                "begins at " +
                seconds(second_starts) + kJoinedToFirst,
            static_cast<double>(second_starts) / repeat->sample_rate_hz};
    }
    return describe_second_stream(path);
}

}  // namespace talkface::detail

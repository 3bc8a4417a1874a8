#include "audio/mp3_toc.hpp"

#include <algorithm>
#include <array>
#include <fstream>
#include <utility>

namespace talkface::detail {

namespace {

// `count` bytes (1-4) at `at`, most significant first.
std::uint32_t big_endian(std::string_view bytes, std::size_t at, std::size_t count = 4) {
    std::uint32_t value = 0;
    for (std::size_t k = 0; k < count; ++k) value = value << 8 | static_cast<unsigned char>(bytes[at + k]);
    return value;
}

// The Xing or Info header's table after the first frame's side information (`at`).
std::optional<Mp3Toc> read_xing_toc(std::string_view file, std::int64_t file_size, std::size_t start,
                                    const Mp3FrameHeader& header, std::size_t at) {
    if (file.size() < at + 8 || (file.substr(at, 4) != "Xing" && file.substr(at, 4) != "Info"))
        return std::nullopt;
    const std::uint32_t flags = big_endian(file, at + 4);
    constexpr std::uint32_t kFrames = 1;
    constexpr std::uint32_t kBytes = 2;
    constexpr std::uint32_t kTable = 4;
    if ((flags & kFrames) == 0 || (flags & kTable) == 0) return std::nullopt;
    Mp3Toc toc;
    toc.is_variable_rate = file.substr(at, 4) == "Xing";
    at += 8;
    if (file.size() < at + 4) return std::nullopt;
    const double samples = static_cast<double>(big_endian(file, at)) * static_cast<double>(header.samples);
    at += 4;
    const auto first_byte = static_cast<std::int64_t>(start);
    std::int64_t stream_bytes = file_size - first_byte;
    if ((flags & kBytes) != 0) {
        if (file.size() < at + 4) return std::nullopt;
        stream_bytes = big_endian(file, at);
        at += 4;
    }
    constexpr std::size_t kEntries = 100;
    if (file.size() < at + kEntries || samples <= 0.0 || stream_bytes <= 0) return std::nullopt;
    const auto entries = file.substr(at, kEntries);
    if (!std::is_sorted(entries.begin(), entries.end(), [](char a, char b) {
            return static_cast<unsigned char>(a) < static_cast<unsigned char>(b);
        }))
        return std::nullopt;
    for (std::size_t k = 0; k < kEntries; ++k)
        toc.points.push_back({static_cast<double>(first_byte) + static_cast<unsigned char>(entries[k]) *
                                                                    static_cast<double>(stream_bytes) / 256.0,
                              static_cast<double>(k) / 100.0 * samples});
    toc.points.push_back({static_cast<double>(first_byte + stream_bytes), samples});
    return toc;
}

// The VBRI header's table, 32 bytes after the first frame's header (whatever its channels).
// Its fields, big-endian: "VBRI", version (1), delay, quality, the stream's bytes and frames (2, 2,
// 2, 4, 4 bytes), then the table's entries, their scale, an entry's bytes (1-4) and the frames an
// entry covers (2 bytes each), then the entries: the bytes each stretch of frames takes, over the
// scale. The stretches start with the frame after the header's own (which FFmpeg does not decode).
std::optional<Mp3Toc> read_vbri_toc(std::string_view file, std::size_t start, const Mp3FrameHeader& header) {
    std::size_t at = start + 4 + 32;
    constexpr std::size_t kFieldsBytes = 26;
    if (file.size() < at + kFieldsBytes || file.substr(at, 4) != "VBRI" || big_endian(file, at + 4, 2) != 1 ||
        header.bytes == 0)
        return std::nullopt;
    const std::uint32_t frames = big_endian(file, at + 14);
    const std::uint32_t entries = big_endian(file, at + 18, 2);
    const std::uint32_t scale = big_endian(file, at + 20, 2);
    const std::uint32_t entry_bytes = big_endian(file, at + 22, 2);
    const std::uint32_t frames_per_entry = big_endian(file, at + 24, 2);
    at += kFieldsBytes;
    if (frames == 0 || entries == 0 || scale == 0 || entry_bytes < 1 || entry_bytes > 4 ||
        frames_per_entry == 0 || file.size() < at + static_cast<std::size_t>(entries) * entry_bytes)
        return std::nullopt;
    Mp3Toc toc;
    toc.is_variable_rate = true;
    toc.points_on_frames = true;
    double byte = static_cast<double>(start + header.bytes);
    toc.points.push_back({byte, 0.0});
    for (std::uint32_t k = 0; k < entries; ++k) {
        byte += static_cast<double>(big_endian(file, at + k * entry_bytes, entry_bytes)) * scale;
        // The last entry may cover fewer frames than the others.
        const double frames_before = std::min<double>(static_cast<double>(k + 1) * frames_per_entry, frames);
        toc.points.push_back({byte, frames_before * static_cast<double>(header.samples)});
    }
    if (toc.points.back().byte <= toc.points.front().byte) return std::nullopt;
    return toc;
}

}  // namespace

std::optional<Mp3FrameHeader> read_mp3_frame_header(std::string_view bytes) {
    if (bytes.size() < 4) return std::nullopt;
    const auto first = static_cast<unsigned char>(bytes[0]);
    const auto second = static_cast<unsigned char>(bytes[1]);
    const auto third = static_cast<unsigned char>(bytes[2]);
    if (first != 0xFF || (second & 0xE0) != 0xE0) return std::nullopt;
    Mp3FrameHeader header;
    header.version = (second >> 3) & 3;
    const int layer = (second >> 1) & 3;  // 1 Layer III
    const int bitrate_index = third >> 4;
    const int rate_index = (third >> 2) & 3;
    if (header.version == 1 || layer != 1 || bitrate_index == 15 || rate_index == 3) return std::nullopt;
    header.is_mono = ((static_cast<unsigned char>(bytes[3]) >> 6) & 3) == 3;
    header.has_crc = (second & 1) == 0;
    const bool is_mpeg1 = header.version == 3;
    header.samples = is_mpeg1 ? 1152 : 576;
    constexpr std::array<int, 15> kMpeg1Kbps{0,   32,  40,  48,  56,  64,  80, 96,
                                             112, 128, 160, 192, 224, 256, 320};
    constexpr std::array<int, 15> kMpeg2Kbps{0, 8, 16, 24, 32, 40, 48, 56, 64, 80, 96, 112, 128, 144, 160};
    constexpr std::array<int, 3> kMpeg1Hz{44100, 48000, 32000};
    header.rate_hz = kMpeg1Hz[static_cast<std::size_t>(rate_index)] >> (is_mpeg1              ? 0
                                                                        : header.version == 2 ? 1
                                                                                              : 2);
    const int kbps = (is_mpeg1 ? kMpeg1Kbps : kMpeg2Kbps)[static_cast<std::size_t>(bitrate_index)];
    // A slot is a byte in Layer III: 144 of them a kb/s per kHz in MPEG-1, 72 in MPEG-2 and 2.5.
    const int padding = (third >> 1) & 1;
    if (kbps > 0)
        header.bytes =
            static_cast<std::size_t>((is_mpeg1 ? 144 : 72) * kbps * 1000 / header.rate_hz + padding);
    return header;
}

std::size_t mp3_side_info_bytes(const Mp3FrameHeader& header) {
    return header.version == 3 ? (header.is_mono ? 17 : 32) : (header.is_mono ? 9 : 17);
}

double Mp3Toc::sample_at(std::int64_t file_byte) const {
    if (points.empty()) return 0.0;
    const auto byte = static_cast<double>(file_byte);
    // The last point at or before the byte (the first if none is), and the one after it.
    const auto after = std::upper_bound(points.begin() + 1, points.end(), byte,
                                        [](double value, const Point& point) { return value < point.byte; });
    if (after == points.end()) return points.back().sample;
    const Point& low = *(after - 1);
    const Point& high = *after;
    const double within =
        high.byte > low.byte ? std::clamp((byte - low.byte) / (high.byte - low.byte), 0.0, 1.0) : 0.0;
    return low.sample + within * (high.sample - low.sample);
}

std::size_t mp3_xing_tag_at(const Mp3FrameHeader& header) {
    return 4 + mp3_side_info_bytes(header);
}

namespace {

bool is_xing_tag_at(std::string_view frame, std::size_t at) {
    const std::string_view tag = frame.substr(std::min(at, frame.size()), 4);
    return tag == "Xing" || tag == "Info";
}

}  // namespace

bool is_mp3_tag_frame(std::string_view frame, const Mp3FrameHeader& header) {
    constexpr std::size_t kVbriAt = 4 + 32;  // a VBRI tag follows the header 32 bytes on
    return is_xing_tag_at(frame, mp3_xing_tag_at(header)) ||
           frame.substr(std::min(kVbriAt, frame.size()), 4) == "VBRI";
}

std::size_t mp3_start_skip_frames(std::string_view frame, const Mp3FrameHeader& header) {
    constexpr std::size_t kDecoderDelayFrames = 529;
    std::size_t at = mp3_xing_tag_at(header);
    if (!is_xing_tag_at(frame, at) || frame.size() < at + 8) return kUntaggedMp3DelayFrames;
    // The Xing fields that follow its flags (frames, bytes, table, quality), each there if its flag is.
    const std::uint32_t flags = big_endian(frame, at + 4);
    at += 8;
    for (const auto& [flag, bytes] :
         {std::pair{1U, 4U}, std::pair{2U, 4U}, std::pair{4U, 100U}, std::pair{8U, 4U}})
        if ((flags & flag) != 0) at += bytes;
    // LAME's extension: the encoder's name (9 bytes), then 12 bytes of settings and gains, then the
    // delay and the end's padding in 12 bits each.
    constexpr std::size_t kDelayAt = 9 + 12;
    if (frame.size() < at + kDelayAt + 3) return kUntaggedMp3DelayFrames;
    const std::string_view name = frame.substr(at, 4);
    if (name != "LAME" && name != "Lavf" && name != "Lavc") return kUntaggedMp3DelayFrames;
    return (big_endian(frame, at + kDelayAt, 3) >> 12) + kDecoderDelayFrames;
}

std::size_t after_id3(std::string_view file) {
    if (file.size() < 10 || file.substr(0, 3) != "ID3") return 0;
    std::size_t size = 0;
    for (std::size_t k = 6; k < 10; ++k) size = size << 7 | (static_cast<unsigned char>(file[k]) & 0x7F);
    const bool has_footer = (static_cast<unsigned char>(file[5]) & 0x10) != 0;
    return 10 + size + (has_footer ? 10 : 0);
}

std::optional<Mp3Toc> read_mp3_toc(std::string_view file, std::int64_t file_size) {
    constexpr std::size_t kSyncSearchBytes =
        4096;  // junk an encoder or a tag may leave before the first frame
    std::size_t start = after_id3(file);
    const std::size_t search_end = std::min(file.size(), start + kSyncSearchBytes);
    while (start + 4 <= search_end && !(static_cast<unsigned char>(file[start]) == 0xFF &&
                                        (static_cast<unsigned char>(file[start + 1]) & 0xE0) == 0xE0))
        ++start;
    if (start + 4 > search_end) return std::nullopt;
    const std::optional<Mp3FrameHeader> header = read_mp3_frame_header(file.substr(start, 4));
    if (!header) return std::nullopt;
    if (auto xing = read_xing_toc(file, file_size, start, *header, start + mp3_xing_tag_at(*header)))
        return xing;
    return read_vbri_toc(file, start, *header);
}

std::optional<Mp3Toc> read_mp3_toc_file(const std::string& path) {
    constexpr std::size_t kHeadBytes = 8192;  // past the tag: the first frame, and junk before it
    std::ifstream in(path, std::ios::binary | std::ios::ate);
    if (!in) return std::nullopt;
    const std::int64_t file_size = in.tellg();
    std::string head(10, '\0');
    in.seekg(0);
    if (!in.read(head.data(), static_cast<std::streamsize>(head.size()))) return std::nullopt;
    head.resize(after_id3(head) + kHeadBytes);
    in.seekg(0);
    in.read(head.data(), static_cast<std::streamsize>(head.size()));
    head.resize(static_cast<std::size_t>(in.gcount()));
    return read_mp3_toc(head, file_size);
}

}  // namespace talkface::detail

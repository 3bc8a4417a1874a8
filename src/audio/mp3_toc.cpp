#include "audio/mp3_toc.hpp"

#include <algorithm>
#include <fstream>

namespace talkface::detail {

namespace {

std::uint32_t big_endian(std::string_view bytes, std::size_t at) {
    std::uint32_t value = 0;
    for (std::size_t k = 0; k < 4; ++k) value = value << 8 | static_cast<unsigned char>(bytes[at + k]);
    return value;
}

// Where the first frame starts: past an ID3v2 tag (its size is 4 bytes of 7 bits each).
std::size_t after_id3(std::string_view file) {
    if (file.size() < 10 || file.substr(0, 3) != "ID3") return 0;
    std::size_t size = 0;
    for (std::size_t k = 6; k < 10; ++k) size = size << 7 | (static_cast<unsigned char>(file[k]) & 0x7F);
    const bool has_footer = (static_cast<unsigned char>(file[5]) & 0x10) != 0;
    return 10 + size + (has_footer ? 10 : 0);
}

}  // namespace

double Mp3Toc::sample_at(std::int64_t file_byte) const {
    const double at = static_cast<double>(file_byte - first_byte) * 256.0 / static_cast<double>(stream_bytes);
    std::size_t entry = 0;
    while (entry + 1 < entries.size() && entries[entry + 1] <= at) ++entry;
    const double low = entries[entry];
    const double high = entry + 1 < entries.size() ? entries[entry + 1] : 256.0;
    const double within = high > low ? std::clamp((at - low) / (high - low), 0.0, 1.0) : 0.0;
    return (static_cast<double>(entry) + within) / 100.0 * samples;
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
    const auto second = static_cast<unsigned char>(file[start + 1]);
    const int version = (second >> 3) & 3;  // 3 MPEG-1, 2 MPEG-2, 0 MPEG-2.5
    const int layer = (second >> 1) & 3;    // 1 Layer III
    if (version == 1 || layer != 1) return std::nullopt;
    const bool is_mono = ((static_cast<unsigned char>(file[start + 3]) >> 6) & 3) == 3;
    // The header follows the frame's header and its side information, whose size these decide.
    const std::size_t side_info = version == 3 ? (is_mono ? 17 : 32) : (is_mono ? 9 : 17);
    std::size_t at = start + 4 + side_info;
    if (file.size() < at + 8 || (file.substr(at, 4) != "Xing" && file.substr(at, 4) != "Info"))
        return std::nullopt;
    const std::uint32_t flags = big_endian(file, at + 4);
    constexpr std::uint32_t kFrames = 1;
    constexpr std::uint32_t kBytes = 2;
    constexpr std::uint32_t kTable = 4;
    if ((flags & kFrames) == 0 || (flags & kTable) == 0) return std::nullopt;
    at += 8;
    Mp3Toc toc;
    toc.first_byte = static_cast<std::int64_t>(start);
    toc.is_variable_rate = file.substr(at - 8, 4) == "Xing";
    const std::size_t samples_per_frame = version == 3 ? 1152 : 576;
    if (file.size() < at + 4) return std::nullopt;
    toc.samples = static_cast<double>(big_endian(file, at)) * static_cast<double>(samples_per_frame);
    at += 4;
    toc.stream_bytes = file_size - toc.first_byte;
    if ((flags & kBytes) != 0) {
        if (file.size() < at + 4) return std::nullopt;
        toc.stream_bytes = big_endian(file, at);
        at += 4;
    }
    if (file.size() < at + toc.entries.size() || toc.samples <= 0.0 || toc.stream_bytes <= 0)
        return std::nullopt;
    for (std::size_t k = 0; k < toc.entries.size(); ++k)
        toc.entries[k] = static_cast<unsigned char>(file[at + k]);
    if (!std::is_sorted(toc.entries.begin(), toc.entries.end())) return std::nullopt;
    return toc;
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

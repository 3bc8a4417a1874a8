#include "audio/chained_stream.hpp"

#include <algorithm>
#include <array>
#include <fstream>
#include <string_view>

#include "audio/file_blocks.hpp"

namespace talkface::detail {

namespace {

constexpr std::string_view kEbmlHeaderId("\x1a\x45\xdf\xa3", 4);
constexpr std::string_view kSegmentId("\x18\x53\x80\x67", 4);
constexpr std::uint64_t kEbmlHeaderElement = 0x1A45DFA3;

std::uint64_t little_endian(const unsigned char* bytes, std::size_t count) {
    std::uint64_t value = 0;
    for (std::size_t k = count; k-- > 0;) value = value << 8 | bytes[k];
    return value;
}

// The first stream's rate and the samples its decoder drops from its start (Opus's pre-skip), from
// its first page's packet: Vorbis's identification header or OpusHead; a rate of 0 for other codecs.
struct StreamClock {
    double rate_hz = 0.0;
    std::uint64_t pre_skip = 0;
};

StreamClock clock_of(std::string_view packet) {
    const auto* bytes = reinterpret_cast<const unsigned char*>(packet.data());
    if (packet.size() >= 16 && packet.substr(0, 7) == std::string_view("\x01vorbis", 7))
        return {static_cast<double>(little_endian(bytes + 12, 4)), 0};
    constexpr double kOpusGranuleRateHz = 48000.0;  // Opus counts its granules at 48 kHz, whatever its input
    if (packet.size() >= 12 && packet.substr(0, 8) == "OpusHead")
        return {kOpusGranuleRateHz, little_endian(bytes + 10, 2)};
    return {};
}

// An Ogg file's pages walked by their headers (27 bytes and the segment table), to the first page
// that begins a logical stream after a page that does not.
std::optional<ChainedStream> chained_ogg_stream(std::ifstream& in) {
    constexpr unsigned char kBeginsStream = 0x02;
    constexpr std::uint64_t kNoGranule = ~std::uint64_t{0};
    std::uint64_t at = 0;
    bool is_past_first_pages = false;
    std::uint64_t first_serial = 0;
    std::uint64_t last_granule = 0;
    StreamClock clock;
    std::array<unsigned char, 27 + 255> header{};
    while (in.seekg(static_cast<std::streamoff>(at)) && in.read(reinterpret_cast<char*>(header.data()), 27) &&
           std::string_view(reinterpret_cast<const char*>(header.data()), 4) == "OggS") {
        const std::size_t segments = header[26];
        if (!in.read(reinterpret_cast<char*>(header.data() + 27), static_cast<std::streamsize>(segments)))
            return std::nullopt;
        std::size_t body = 0;
        for (std::size_t k = 0; k < segments; ++k) body += header[27 + k];
        const bool begins_stream = (header[5] & kBeginsStream) != 0;
        const std::uint64_t serial = little_endian(header.data() + 14, 4);
        if (begins_stream && is_past_first_pages) {
            ChainedStream chained{ChainedStream::Container::ogg, at, 0.0};
            if (clock.rate_hz > 0.0 && last_granule > clock.pre_skip)
                chained.first_seconds = static_cast<double>(last_granule - clock.pre_skip) / clock.rate_hz;
            return chained;
        }
        if (at == 0) {
            first_serial = serial;
            std::array<char, 19> packet{};
            in.read(packet.data(), static_cast<std::streamsize>(std::min(body, packet.size())));
            clock = clock_of(std::string_view(packet.data(), static_cast<std::size_t>(in.gcount())));
        }
        const std::uint64_t granule = little_endian(header.data() + 6, 8);
        if (serial == first_serial && granule != kNoGranule) last_granule = granule;
        is_past_first_pages = is_past_first_pages || !begins_stream;
        at += 27 + segments + body;
    }
    return std::nullopt;
}

// An EBML element's ID or size at `at`: a variable-length integer of 1-8 bytes (an ID of 1-4), its
// length told by its first byte's leading zeros; an ID keeps its length's marker bit, a size does
// not. A size of all ones is unknown: a live recording's Segment or Cluster, written before its end
// was known (a browser's MediaRecorder writes both so).
struct Vint {
    std::uint64_t value = 0;
    std::size_t length = 0;
    bool is_unknown = false;
};

std::optional<Vint> read_vint(FileBlocks& file, std::uint64_t at, bool keeps_marker) {
    const std::string_view bytes = file.at(at, 8);
    if (bytes.empty() || bytes[0] == 0) return std::nullopt;
    const auto first = static_cast<unsigned char>(bytes[0]);
    Vint vint;
    vint.length = 1;
    while ((first & (0x80U >> (vint.length - 1))) == 0) ++vint.length;
    if (bytes.size() < vint.length) return std::nullopt;
    const unsigned value_bits = 0xFFU >> vint.length;
    vint.value = keeps_marker ? first : first & value_bits;
    vint.is_unknown = (first & value_bits) == value_bits;
    for (std::size_t k = 1; k < vint.length; ++k) {
        const auto next = static_cast<unsigned char>(bytes[k]);
        vint.value = vint.value << 8 | next;
        vint.is_unknown = vint.is_unknown && next == 0xFF;
    }
    return vint;
}

// The Segment's children (Matroska's level 1: SeekHead, Info, Tracks, Cluster, Cues, Attachments,
// Chapters, Tags, and Void and CRC-32 anywhere), and a Cluster's (Timestamp, SilentTracks, Position,
// PrevSize, SimpleBlock, BlockGroup, EncryptedBlock): an element of unknown size ends at the first
// element that is none of its children.
constexpr std::uint64_t kClusterId = 0x1F43B675;
bool is_segment_child(std::uint64_t id) {
    for (const std::uint64_t child : {0x114D9B74U, 0x1549A966U, 0x1654AE6BU, 0x1F43B675U, 0x1C53BB6BU,
                                      0x1941A469U, 0x1043A770U, 0x1254C367U, 0xECU, 0xBFU})
        if (id == child) return true;
    return false;
}
bool is_cluster_child(std::uint64_t id) {
    for (const std::uint64_t child : {0xE7U, 0x5854U, 0xA7U, 0xABU, 0xA3U, 0xA0U, 0xAFU, 0xECU, 0xBFU})
        if (id == child) return true;
    return false;
}

// Where a Segment of unknown size, its children from `at` on, is followed by a second EBML header:
// its children walked by their IDs and sizes, a Cluster of unknown size by its own children. Reads
// their headers only; nullopt at the file's end, or at bytes that are no element the Segment holds.
std::optional<std::uint64_t> after_unknown_segment(FileBlocks& file, std::uint64_t at) {
    bool is_in_cluster = false;
    while (true) {
        const auto id = read_vint(file, at, true);
        if (!id || id->length > 4) return std::nullopt;
        if (id->value == kEbmlHeaderElement) return at;
        is_in_cluster = is_in_cluster && is_cluster_child(id->value);
        if (!is_in_cluster && !is_segment_child(id->value)) return std::nullopt;
        const auto size = read_vint(file, at + id->length, false);
        if (!size) return std::nullopt;
        at += id->length + size->length;
        if (size->is_unknown) {
            if (id->value != kClusterId) return std::nullopt;
            is_in_cluster = true;
        } else {
            at += size->value;
        }
    }
}

// A Matroska file's first Segment ending where a second EBML header begins: at its stated size, or,
// a live recording's Segment of unknown size, after its last child.
std::optional<ChainedStream> second_matroska_segment(FileBlocks& file) {
    const auto header_size = read_vint(file, kEbmlHeaderId.size(), false);
    if (!header_size || header_size->is_unknown) return std::nullopt;
    std::uint64_t at = kEbmlHeaderId.size() + header_size->length + header_size->value;
    if (file.at(at, kSegmentId.size()) != kSegmentId) return std::nullopt;
    at += kSegmentId.size();
    const auto segment_size = read_vint(file, at, false);
    if (!segment_size) return std::nullopt;
    at += segment_size->length;
    if (segment_size->is_unknown) {
        const auto end = after_unknown_segment(file, at);
        if (!end) return std::nullopt;
        return ChainedStream{ChainedStream::Container::matroska, *end, 0.0, true};
    }
    const std::uint64_t end = at + segment_size->value;
    if (file.at(end, kEbmlHeaderId.size()) != kEbmlHeaderId) return std::nullopt;
    return ChainedStream{ChainedStream::Container::matroska, end, 0.0};
}

}  // namespace

std::optional<ChainedStream> chained_stream(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::array<char, 4> start{};
    if (!in.read(start.data(), start.size())) return std::nullopt;
    const std::string_view opening(start.data(), start.size());
    if (opening == "OggS") return chained_ogg_stream(in);
    if (opening == kEbmlHeaderId) {
        FileBlocks file(path);
        return second_matroska_segment(file);
    }
    return std::nullopt;
}

}  // namespace talkface::detail

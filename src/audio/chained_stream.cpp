#include "audio/chained_stream.hpp"

#include <algorithm>
#include <array>
#include <fstream>
#include <string_view>

namespace talkface::detail {

namespace {

constexpr std::string_view kEbmlHeaderId("\x1a\x45\xdf\xa3", 4);
constexpr std::string_view kSegmentId("\x18\x53\x80\x67", 4);

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

// An EBML element's size at `at` in `in`, `at` moved past it: a variable-length integer of 1-8 bytes,
// its length told by its first byte's leading zeros; nullopt where the bytes are none, and for a size
// of all ones (unknown: a live recording's Segment, written before its end was known).
std::optional<std::uint64_t> read_size(std::ifstream& in, std::uint64_t& at) {
    unsigned char first = 0;
    in.seekg(static_cast<std::streamoff>(at));
    if (!in.read(reinterpret_cast<char*>(&first), 1) || first == 0) return std::nullopt;
    std::size_t length = 1;
    while ((first & (0x80U >> (length - 1))) == 0) ++length;
    std::uint64_t value = first & (0xFFU >> length);
    bool is_all_ones = value == (0xFFU >> length);
    for (std::size_t k = 1; k < length; ++k) {
        unsigned char next = 0;
        if (!in.read(reinterpret_cast<char*>(&next), 1)) return std::nullopt;
        value = value << 8 | next;
        is_all_ones = is_all_ones && next == 0xFF;
    }
    at += length;
    if (is_all_ones) return std::nullopt;
    return value;
}

// A Matroska file's first Segment, its size stated, ending where a second EBML header begins.
std::optional<ChainedStream> second_matroska_segment(std::ifstream& in) {
    std::uint64_t at = kEbmlHeaderId.size();
    const auto header_size = read_size(in, at);
    if (!header_size) return std::nullopt;
    at += *header_size;
    std::array<char, 4> id{};
    in.seekg(static_cast<std::streamoff>(at));
    if (!in.read(id.data(), id.size()) || std::string_view(id.data(), id.size()) != kSegmentId)
        return std::nullopt;
    at += id.size();
    const auto segment_size = read_size(in, at);
    if (!segment_size) return std::nullopt;
    const std::uint64_t end = at + *segment_size;
    in.seekg(static_cast<std::streamoff>(end));
    if (!in.read(id.data(), id.size()) || std::string_view(id.data(), id.size()) != kEbmlHeaderId)
        return std::nullopt;
    return ChainedStream{ChainedStream::Container::matroska, end, 0.0};
}

}  // namespace

std::optional<ChainedStream> chained_stream(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::array<char, 4> start{};
    if (!in.read(start.data(), start.size())) return std::nullopt;
    const std::string_view opening(start.data(), start.size());
    if (opening == "OggS") return chained_ogg_stream(in);
    if (opening == kEbmlHeaderId) return second_matroska_segment(in);
    return std::nullopt;
}

}  // namespace talkface::detail

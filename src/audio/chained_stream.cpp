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

// An element's ID, the size of its data (nullopt: unknown) and where its data starts.
struct Element {
    std::uint64_t id = 0;
    std::optional<std::uint64_t> size;
    std::uint64_t data = 0;
};

std::optional<Element> read_element(FileBlocks& file, std::uint64_t at) {
    const auto id = read_vint(file, at, true);
    if (!id || id->length > 4) return std::nullopt;
    const auto size = read_vint(file, at + id->length, false);
    if (!size) return std::nullopt;
    return Element{id->value, size->is_unknown ? std::nullopt : std::optional<std::uint64_t>(size->value),
                   at + id->length + size->length};
}

// An element's data as an unsigned or signed integer (0-8 bytes, most significant first).
std::uint64_t unsigned_data(FileBlocks& file, const Element& element) {
    const std::string_view bytes =
        file.at(element.data, static_cast<std::size_t>(std::min<std::uint64_t>(*element.size, 8)));
    std::uint64_t value = 0;
    for (const char byte : bytes) value = value << 8 | static_cast<unsigned char>(byte);
    return value;
}
std::int64_t signed_data(FileBlocks& file, const Element& element) {
    const std::uint64_t value = unsigned_data(file, element);
    const unsigned bits = static_cast<unsigned>(std::min<std::uint64_t>(*element.size, 8)) * 8;
    if (bits == 0 || bits == 64 || (value >> (bits - 1)) == 0) return static_cast<std::int64_t>(value);
    return static_cast<std::int64_t>(value) - (std::int64_t{1} << bits);
}

// The children of the element of known size `parent`, each given to `each`.
template <typename Each>
void for_each_child(FileBlocks& file, const Element& parent, Each each) {
    const std::uint64_t end = parent.data + *parent.size;
    for (std::uint64_t at = parent.data; at < end;) {
        const auto child = read_element(file, at);
        if (!child || !child->size) return;
        each(*child);
        at = child->data + *child->size;
    }
}

// The Matroska elements SegmentSound reads: the Segment's Info (its TimestampScale) and Tracks (each
// TrackEntry's number, type, CodecDelay and CodecPrivate), and a Cluster's Timestamp and blocks (a
// SimpleBlock, or a BlockGroup's Block, BlockDuration and DiscardPadding).
constexpr std::uint64_t kInfoId = 0x1549A966;
constexpr std::uint64_t kTimestampScaleId = 0x2AD7B1;
constexpr std::uint64_t kTracksId = 0x1654AE6B;
constexpr std::uint64_t kClusterTimestampId = 0xE7;
constexpr std::uint64_t kSimpleBlockId = 0xA3;
constexpr std::uint64_t kBlockGroupId = 0xA0;
constexpr std::uint64_t kTrackEntryId = 0xAE;
constexpr std::uint64_t kTrackNumberId = 0xD7;
constexpr std::uint64_t kTrackTypeId = 0x83;
constexpr std::uint64_t kCodecDelayId = 0x56AA;
constexpr std::uint64_t kCodecPrivateId = 0x63A2;
constexpr std::uint64_t kBlockId = 0xA1;
constexpr std::uint64_t kBlockDurationId = 0x9B;
constexpr std::uint64_t kDiscardPaddingId = 0x75A2;

// Where the first Segment's sound ends as the file decodes: its sound track's last block's time and
// length (a BlockGroup's BlockDuration, or the step from the block before: a codec's frames are of one
// length), less the end the encoder pads out (DiscardPadding) and the start the decoder drops (Opus's
// pre-skip, or the track's CodecDelay), on the Segment's clock (TimestampScale, ns a tick).
class SegmentSound {
public:
    // Reads what the clock and the sound track's blocks say from a child of the Segment, or of a Cluster.
    void read(FileBlocks& file, const Element& element) {
        if (!element.size) return;
        if (element.id == kInfoId) {
            for_each_child(file, element, [&](const Element& child) {
                if (child.id == kTimestampScaleId) tick_ns_ = unsigned_data(file, child);
            });
        } else if (element.id == kTracksId) {
            read_tracks(file, element);
        } else if (element.id == kClusterTimestampId) {
            cluster_ticks_ = signed_data(file, element);
        } else if (element.id == kSimpleBlockId) {
            read_block(file, element, std::nullopt, 0);
        } else if (element.id == kBlockGroupId) {
            read_block_group(file, element);
        }
    }

    // The end in seconds of the decoded sound; 0 where no block of the sound track was read.
    double end_seconds() const {
        if (!last_ticks_) return 0.0;
        std::optional<std::int64_t> length = last_length_ticks_;
        if (!length && before_last_ticks_) length = *last_ticks_ - *before_last_ticks_;
        if (!length) return 0.0;
        const double end_ns = static_cast<double>(*last_ticks_ + *length) * static_cast<double>(tick_ns_) -
                              static_cast<double>(last_discard_ns_) - codec_delay_ns_;
        return std::max(0.0, end_ns / 1e9);
    }

private:
    // The first sound track's number and the start its decoder drops (TrackEntry: TrackNumber, TrackType
    // 2, CodecDelay, CodecPrivate). An Opus track's is its OpusHead's pre-skip, which the decoder drops:
    // FFmpeg's muxer states the CodecDelay of Opus encoded from 16 kHz as 104 samples of 48 kHz (2.2 ms),
    // the encoder's lookahead counted at its input's rate, where the pre-skip is 312 (6.5 ms).
    void read_tracks(FileBlocks& file, const Element& tracks) {
        constexpr std::uint64_t kSoundTrackType = 2;
        constexpr std::size_t kOpusHeadBytes = 19;
        for_each_child(file, tracks, [&](const Element& entry) {
            if (entry.id != kTrackEntryId || sound_track_) return;
            std::uint64_t number = 0;
            std::uint64_t type = 0;
            std::uint64_t delay_ns = 0;
            std::optional<double> pre_skip_ns;
            for_each_child(file, entry, [&](const Element& field) {
                if (field.id == kTrackNumberId) number = unsigned_data(file, field);
                if (field.id == kTrackTypeId) type = unsigned_data(file, field);
                if (field.id == kCodecDelayId) delay_ns = unsigned_data(file, field);
                if (field.id == kCodecPrivateId) {
                    const StreamClock clock = clock_of(file.at(
                        field.data,
                        static_cast<std::size_t>(std::min<std::uint64_t>(*field.size, kOpusHeadBytes))));
                    if (clock.pre_skip > 0)
                        pre_skip_ns = static_cast<double>(clock.pre_skip) / clock.rate_hz * 1e9;
                }
            });
            if (type != kSoundTrackType) return;
            sound_track_ = number;
            codec_delay_ns_ = pre_skip_ns.value_or(static_cast<double>(delay_ns));
        });
    }

    // A BlockGroup: its Block, and the BlockDuration and DiscardPadding beside it.
    void read_block_group(FileBlocks& file, const Element& group) {
        std::optional<Element> block;
        std::optional<std::int64_t> length;
        std::int64_t discard_ns = 0;
        for_each_child(file, group, [&](const Element& child) {
            if (child.id == kBlockId) block = child;
            if (child.id == kBlockDurationId) length = static_cast<std::int64_t>(unsigned_data(file, child));
            if (child.id == kDiscardPaddingId) discard_ns = signed_data(file, child);
        });
        if (block) read_block(file, *block, length, discard_ns);
    }

    // A block's track number (a size-like integer) and its time, 2 bytes signed, from its Cluster's.
    void read_block(FileBlocks& file, const Element& block, std::optional<std::int64_t> length,
                    std::int64_t discard_ns) {
        const auto track = read_vint(file, block.data, false);
        if (!track || !sound_track_ || track->value != *sound_track_) return;
        const std::string_view time = file.at(block.data + track->length, 2);
        if (time.size() < 2) return;
        const auto relative = static_cast<std::int16_t>(static_cast<unsigned char>(time[0]) << 8 |
                                                        static_cast<unsigned char>(time[1]));
        before_last_ticks_ = last_ticks_;
        last_ticks_ = cluster_ticks_ + relative;
        last_length_ticks_ = length;
        last_discard_ns_ = discard_ns;
    }

    std::uint64_t tick_ns_ = 1000000;  // Matroska's default: a millisecond
    std::optional<std::uint64_t> sound_track_;
    double codec_delay_ns_ = 0.0;
    std::int64_t cluster_ticks_ = 0;
    std::optional<std::int64_t> last_ticks_;
    std::optional<std::int64_t> before_last_ticks_;
    std::optional<std::int64_t> last_length_ticks_;
    std::int64_t last_discard_ns_ = 0;
};

// The first Segment's children from `at` on, walked by their IDs and sizes, a Cluster's by its own
// children, each read into `sound`: to `end` (a Segment of known size), or, a Segment of unknown size,
// to a second EBML header. Reads their headers, and the few fields SegmentSound reads; where the walk
// ends, or nullopt at the file's end, or at bytes that are no element the Segment holds.
std::optional<std::uint64_t> walk_segment(FileBlocks& file, std::uint64_t at,
                                          std::optional<std::uint64_t> end, SegmentSound& sound) {
    bool is_in_cluster = false;
    while (!end || at < *end) {
        const auto id = read_vint(file, at, true);
        if (!id || id->length > 4) return std::nullopt;
        if (!end && id->value == kEbmlHeaderElement) return at;
        const auto element = read_element(file, at);
        if (!element) return std::nullopt;
        is_in_cluster = is_in_cluster && is_cluster_child(element->id);
        if (!is_in_cluster && !is_segment_child(element->id)) return std::nullopt;
        sound.read(file, *element);
        at = element->data;
        if (element->id == kClusterId) {
            is_in_cluster = true;
        } else if (element->size) {
            at += *element->size;
        } else {
            return std::nullopt;
        }
    }
    return at;
}

// A Matroska file's first Segment ending where a second EBML header begins: at its stated size, or,
// a live recording's Segment of unknown size, after its last child; with the time its sound ends.
std::optional<ChainedStream> second_matroska_segment(FileBlocks& file) {
    const auto header_size = read_vint(file, kEbmlHeaderId.size(), false);
    if (!header_size || header_size->is_unknown) return std::nullopt;
    std::uint64_t at = kEbmlHeaderId.size() + header_size->length + header_size->value;
    if (file.at(at, kSegmentId.size()) != kSegmentId) return std::nullopt;
    const auto segment = read_element(file, at);
    if (!segment) return std::nullopt;
    SegmentSound sound;
    if (segment->size) {
        const std::uint64_t end = segment->data + *segment->size;
        if (file.at(end, kEbmlHeaderId.size()) != kEbmlHeaderId) return std::nullopt;
        // Walked only once a second file is found past it: a single file's walk would read every
        // block's header of a long recording for nothing.
        const bool is_walked = walk_segment(file, segment->data, end, sound).has_value();
        return ChainedStream{ChainedStream::Container::matroska, end, is_walked ? sound.end_seconds() : 0.0};
    }
    const auto end = walk_segment(file, segment->data, std::nullopt, sound);
    if (!end) return std::nullopt;
    return ChainedStream{ChainedStream::Container::matroska, *end, sound.end_seconds(), true};
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

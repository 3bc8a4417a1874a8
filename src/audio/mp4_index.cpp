#include "audio/mp4_index.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <fstream>

namespace talkface::detail {

namespace {

std::uint64_t big_endian(const unsigned char* bytes, int count) {
    std::uint64_t value = 0;
    for (int i = 0; i < count; ++i) value = (value << 8U) | bytes[i];
    return value;
}

// The boxes of an index that hold only boxes (ISO/IEC 14496-12: moov, trak, edts, mdia, minf, dinf,
// stbl, mvex); the others hold data, or a version before their boxes (meta), and are not entered.
bool holds_boxes(const std::string& type) {
    for (const char* container : {"moov", "trak", "edts", "mdia", "minf", "dinf", "stbl", "mvex"})
        if (type == container) return true;
    return false;
}

// A box type: four printable characters (Apple's metadata types begin with the byte 0xA9, "(c)").
bool is_box_type(const unsigned char* type) {
    for (int i = 0; i < 4; ++i)
        if (!(type[i] == 0xA9 || (type[i] >= 0x20 && type[i] < 0x7F))) return false;
    return true;
}

// The first byte in [start, end) of `file` where the boxes stop tiling the range exactly, or
// nullopt if they tile it; boxes that hold boxes are walked into, and `edit_list` set where an
// "elst" is among them. Reads box headers only.
std::optional<std::uint64_t> first_broken_box(std::ifstream& file, std::uint64_t start, std::uint64_t end,
                                              bool& edit_list) {
    std::uint64_t position = start;
    while (position < end) {
        std::array<unsigned char, 16> header{};
        if (end - position < 8) return position;
        file.seekg(static_cast<std::streamoff>(position));
        if (!file.read(reinterpret_cast<char*>(header.data()), 8) || !is_box_type(header.data() + 4)) return position;
        std::uint64_t size = big_endian(header.data(), 4);
        std::uint64_t header_size = 8;
        if (size == 1) {
            if (end - position < 16 || !file.read(reinterpret_cast<char*>(header.data() + 8), 8)) return position;
            size = big_endian(header.data() + 8, 8);
            header_size = 16;
        }
        if (size < header_size || size > end - position) return position;
        const std::string type(reinterpret_cast<const char*>(header.data() + 4), 4);
        edit_list |= type == "elst";
        if (holds_boxes(type))
            if (const auto broken =
                    first_broken_box(file, position + header_size, position + size, edit_list))
                return broken;
        position += size;
    }
    return std::nullopt;
}

// How a walk over a file's top-level boxes ends: at the index (its box's start and size, the
// size "to the end of the file" made explicit), or without one in a file of boxes that opens with
// "ftyp" (an MP4 without its index), or at bytes that are no such file.
struct TopLevelWalk {
    enum class Outcome { index_found, no_index, not_mp4 } outcome = Outcome::not_mp4;
    std::uint64_t index_start = 0;
    std::uint64_t index_size = 0;
    std::uint64_t index_header_size = 8;
};

TopLevelWalk walk_top_level(std::ifstream& file, std::uint64_t file_size) {
    using Outcome = TopLevelWalk::Outcome;
    std::uint64_t position = 0;
    // ISO/IEC 14496-12 4.2: a box is a 32-bit size and a 4-character type; size 1 puts a 64-bit
    // size after the type, size 0 means "to the end of the file".
    while (position + 8 <= file_size) {
        std::array<unsigned char, 16> header{};
        file.seekg(static_cast<std::streamoff>(position));
        file.read(reinterpret_cast<char*>(header.data()), 8);
        if (!file) return {};
        const std::string type(reinterpret_cast<const char*>(header.data() + 4), 4);
        if (position == 0 && type != "ftyp") return {};
        std::uint64_t size = big_endian(header.data(), 4);
        std::uint64_t header_size = 8;
        if (size == 1) {
            file.read(reinterpret_cast<char*>(header.data() + 8), 8);
            // Cut inside a box's header: an index cut there runs to the end of the file.
            if (!file) return type == "moov" ? TopLevelWalk{Outcome::index_found, position, file_size - position, 16}
                                             : TopLevelWalk{Outcome::no_index};
            size = big_endian(header.data() + 8, 8);
            header_size = 16;
        }
        if (size == 0) size = file_size - position;
        if (type == "moov") return {Outcome::index_found, position, size, header_size};
        if (size < header_size) return {};  // not a box structure: another damage, said by FFmpeg
        if (size > file_size - position) return {Outcome::no_index};  // a box cut off before its end
        position += size;
    }
    return {Outcome::no_index};
}

}  // namespace

std::optional<Mp4Index> find_mp4_index(const std::string& path) {
    std::ifstream file(path, std::ios::binary | std::ios::ate);
    if (!file) return std::nullopt;
    const auto file_size = static_cast<std::uint64_t>(file.tellg());
    const TopLevelWalk walk = walk_top_level(file, file_size);
    if (walk.outcome != TopLevelWalk::Outcome::index_found) return std::nullopt;
    // An index that runs past the end of the file is walked to the file's end (cut off, or its
    // size is what broke); a size too small to hold its own header breaks at its start.
    const std::uint64_t end = std::min(walk.index_start + std::max(walk.index_size, walk.index_header_size), file_size);
    Mp4Index index{walk.index_start, end, std::nullopt};
    index.broken_at_byte =
        walk.index_size < walk.index_header_size
            ? std::optional<std::uint64_t>(walk.index_start)
            : first_broken_box(file, walk.index_start + walk.index_header_size, end, index.has_edit_list);
    return index;
}

std::optional<std::uint64_t> second_file_byte(const std::string& path) {
    std::ifstream file(path, std::ios::binary | std::ios::ate);
    if (!file) return std::nullopt;
    const auto file_size = static_cast<std::uint64_t>(file.tellg());
    for (std::uint64_t position = 0; position + 8 <= file_size;) {
        std::array<unsigned char, 16> header{};
        file.seekg(static_cast<std::streamoff>(position));
        if (!file.read(reinterpret_cast<char*>(header.data()), 8) || !is_box_type(header.data() + 4))
            return std::nullopt;
        const std::string type(reinterpret_cast<const char*>(header.data() + 4), 4);
        if (position == 0 && type != "ftyp") return std::nullopt;
        if (position > 0 && type == "ftyp") return position;
        std::uint64_t size = big_endian(header.data(), 4);
        std::uint64_t header_size = 8;
        if (size == 1) {
            if (!file.read(reinterpret_cast<char*>(header.data() + 8), 8)) return std::nullopt;
            size = big_endian(header.data() + 8, 8);
            header_size = 16;
        }
        if (size < header_size || size > file_size - position) return std::nullopt;
        position += size;
    }
    return std::nullopt;
}

bool is_mp4_without_index(const std::string& path) {
    std::ifstream file(path, std::ios::binary | std::ios::ate);
    if (!file) return false;
    return walk_top_level(file, static_cast<std::uint64_t>(file.tellg())).outcome == TopLevelWalk::Outcome::no_index;
}

}  // namespace talkface::detail

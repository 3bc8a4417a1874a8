#include "audio/mp4_index.hpp"

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

}  // namespace

bool is_mp4_without_index(const std::string& path) {
    std::ifstream file(path, std::ios::binary | std::ios::ate);
    if (!file) return false;
    const auto file_size = static_cast<std::uint64_t>(file.tellg());
    std::uint64_t position = 0;
    // ISO/IEC 14496-12 4.2: a box is a 32-bit size and a 4-character type; size 1 puts a 64-bit
    // size after the type, size 0 means "to the end of the file".
    while (position + 8 <= file_size) {
        std::array<unsigned char, 16> header{};
        file.seekg(static_cast<std::streamoff>(position));
        file.read(reinterpret_cast<char*>(header.data()), 8);
        if (!file) return false;
        const std::string type(reinterpret_cast<const char*>(header.data() + 4), 4);
        if (position == 0 && type != "ftyp") return false;
        if (type == "moov") return false;
        std::uint64_t size = big_endian(header.data(), 4);
        std::uint64_t header_size = 8;
        if (size == 1) {
            file.read(reinterpret_cast<char*>(header.data() + 8), 8);
            if (!file) return true;  // cut inside a box's header
            size = big_endian(header.data() + 8, 8);
            header_size = 16;
        }
        if (size == 0) return true;  // the last box runs to the end, and it is not the index
        if (size < header_size) return false;  // not a box structure: another damage, said by FFmpeg
        if (size > file_size - position) return true;  // a box cut off before its end
        position += size;
    }
    return true;
}

}  // namespace talkface::detail

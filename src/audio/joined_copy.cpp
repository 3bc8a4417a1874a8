#include "audio/joined_copy.hpp"

#include <algorithm>
#include <fstream>
#include <string_view>
#include <vector>

namespace talkface::detail {

std::optional<std::uint64_t> repeated_opening_byte(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::string opening(kOpeningBytes, '\0');
    if (!in.read(opening.data(), static_cast<std::streamsize>(opening.size()))) return std::nullopt;
    const std::string_view start(opening);
    if (start.substr(0, 4) != "fLaC" && start.substr(0, 4) != "OggS" &&
        start.substr(0, 4) != "\x1a\x45\xdf\xa3" && start.substr(0, 3) != "ID3")
        return std::nullopt;
    // Read a block at a time, each after the last kOpeningBytes - 1 bytes of the one before, so that
    // an opening across two blocks is found.
    constexpr std::size_t kBlockBytes = 1 << 20;
    std::vector<char> block(kBlockBytes + kOpeningBytes - 1);
    std::uint64_t block_start = kOpeningBytes;  // the file's byte at block[0]
    std::size_t carried = 0;
    while (in) {
        in.read(block.data() + carried, static_cast<std::streamsize>(kBlockBytes));
        const std::size_t held = carried + static_cast<std::size_t>(in.gcount());
        const auto end = block.begin() + static_cast<std::ptrdiff_t>(held);
        const auto found = std::search(block.begin(), end, opening.begin(), opening.end());
        if (found != end) return block_start + static_cast<std::uint64_t>(found - block.begin());
        if (held < kOpeningBytes) return std::nullopt;
        carried = kOpeningBytes - 1;
        std::copy(end - static_cast<std::ptrdiff_t>(carried), end, block.begin());
        block_start += held - carried;
    }
    return std::nullopt;
}

}  // namespace talkface::detail

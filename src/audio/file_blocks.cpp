#include "audio/file_blocks.hpp"

#include <algorithm>

namespace talkface::detail {

FileBlocks::FileBlocks(const std::string& path) : in_(path, std::ios::binary) {}

std::string_view FileBlocks::at(std::uint64_t at, std::size_t count) {
    constexpr std::size_t kBlockBytes = 1 << 16;
    if (at < start_ || at + count > start_ + block_.size()) {
        block_.resize(std::max(kBlockBytes, count));
        in_.clear();
        in_.seekg(static_cast<std::streamoff>(at));
        in_.read(block_.data(), static_cast<std::streamsize>(block_.size()));
        block_.resize(static_cast<std::size_t>(in_.gcount()));
        start_ = at;
    }
    return std::string_view(block_).substr(static_cast<std::size_t>(at - start_), count);
}

}  // namespace talkface::detail

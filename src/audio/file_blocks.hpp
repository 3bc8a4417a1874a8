// A file's bytes read a block at a time, for the walks from header to header that tell a joined
// recording (mp3_restart.cpp: every MP3 frame's; chained_stream.cpp: every block of a live WebM's
// clusters): each byte is read from the disk once, where a seek for every header of a frame of 20 ms
// read the file's buffer again for each.
#ifndef TALKFACE_AUDIO_FILE_BLOCKS_HPP
#define TALKFACE_AUDIO_FILE_BLOCKS_HPP

#include <cstddef>
#include <cstdint>
#include <fstream>
#include <string>
#include <string_view>

namespace talkface::detail {

class FileBlocks {
public:
    explicit FileBlocks(const std::string& path);

    // Up to `count` of the file's bytes from `at` on (fewer at its end), valid until the next call.
    std::string_view at(std::uint64_t at, std::size_t count);

private:
    std::ifstream in_;
    std::string block_;
    std::uint64_t start_ = 0;
};

}  // namespace talkface::detail

#endif

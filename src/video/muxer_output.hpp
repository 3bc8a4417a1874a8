// Where a muxer's bytes go: a temporary file beside the target, renamed over it only when the file
// is whole (a failure, a cancel or a thrown exception leaves no partial output), or memory.
#ifndef TALKFACE_VIDEO_MUXER_OUTPUT_HPP
#define TALKFACE_VIDEO_MUXER_OUTPUT_HPP

#include <memory>
#include <string>

#include "video/ffmpeg_support.hpp"

namespace talkface::detail {

// A memory output's bytes and write position (the muxer seeks back to patch sizes).
struct MemoryBuffer {
    std::string bytes;
    std::size_t position = 0;
};

class MuxerOutput {
public:
    // A container of FFmpeg muxer `muxer_name` ("mp4", "webm", "ogg", "webp") for `path`.
    // \throws talkface::FileError if the temporary file cannot be created.
    static MuxerOutput to_file(const std::string& path, const char* muxer_name);
    // The same in memory; take_bytes() after finish(). Seekable, so every muxer works; an MP4
    // keeps its index at the end (faststart needs to reopen the output by name).
    static MuxerOutput to_memory(const char* muxer_name);

    MuxerOutput(MuxerOutput&& other) noexcept;
    MuxerOutput& operator=(MuxerOutput&&) = delete;
    MuxerOutput(const MuxerOutput&) = delete;
    MuxerOutput& operator=(const MuxerOutput&) = delete;
    // Unfinished: closes and removes the temporary file, leaving the target as it was.
    ~MuxerOutput();

    AVFormatContext* context() const { return context_; }
    bool is_file() const { return !path_.empty(); }
    const std::string& path() const { return path_; }

    // Writes the header with the muxer options `options` (consumed; may be nullptr).
    // Streams must have been added.
    void write_header(AVDictionary** options);
    // Hands `packet` (in its stream's time base) to the muxer, which interleaves the streams.
    void write_packet(AVPacket* packet);
    // Writes the trailer and closes; a file is then renamed over its target.
    // \throws talkface::FileError if the file cannot be written or renamed.
    void finish();
    // The bytes of a memory output after finish().
    std::string take_bytes();

private:
    MuxerOutput() = default;
    void close_io() noexcept;

    AVFormatContext* context_ = nullptr;
    std::string path_;       // the target, empty for memory
    std::string temp_path_;  // the file being written
    bool is_header_written_ = false;
    bool is_finished_ = false;
    std::unique_ptr<MemoryBuffer> memory_;
};

}  // namespace talkface::detail

#endif

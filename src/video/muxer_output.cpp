#include "video/muxer_output.hpp"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <new>
#include <utility>

#include <sys/stat.h>
#include <unistd.h>

#include "talkface/errors.hpp"

namespace talkface::detail {

namespace {

constexpr int kMemoryBlockBytes = 64 * 1024;

// The muxer's writes and seeks on a MuxerOutput's MemoryBuffer (`opaque`). A template, because
// the write callback's data became const in FFmpeg 6.1: the pointer type is deduced from
// avio_alloc_context's parameter.
template <typename Byte>
int write_to_memory(void* opaque, Byte* data, int size) {
    auto& [bytes, position] = *static_cast<MemoryBuffer*>(opaque);
    const auto count = static_cast<std::size_t>(size);
    if (bytes.size() < position + count) bytes.resize(position + count);
    std::memcpy(bytes.data() + position, data, count);
    position += count;
    return size;
}

std::int64_t seek_in_memory(void* opaque, std::int64_t offset, int whence) {
    auto& [bytes, position] = *static_cast<MemoryBuffer*>(opaque);
    std::int64_t target = 0;
    switch (whence & ~AVSEEK_FORCE) {
        case AVSEEK_SIZE: return static_cast<std::int64_t>(bytes.size());
        case SEEK_SET: target = offset; break;
        case SEEK_CUR: target = static_cast<std::int64_t>(position) + offset; break;
        case SEEK_END: target = static_cast<std::int64_t>(bytes.size()) + offset; break;
        default: return AVERROR(EINVAL);
    }
    if (target < 0) return AVERROR(EINVAL);
    position = static_cast<std::size_t>(target);
    return target;
}

AVFormatContext* allocate_context(const char* muxer_name, const std::string& url) {
    quiet_ffmpeg_log();
    AVFormatContext* context = nullptr;
    check_ffmpeg(avformat_alloc_output_context2(&context, nullptr, muxer_name, url.empty() ? nullptr : url.c_str()),
                 muxer_name);
    // The same input gives the same bytes: no random stream serial (Ogg) or segment id (WebM), no
    // library version in the file.
    context->flags |= AVFMT_FLAG_BITEXACT;
    if (std::strcmp(muxer_name, "webm") == 0) {
        // Left to the default, the generic layer shifts every stream by Opus's negative first
        // time (its pre-skip), and the video would start 7 ms after the sound; the audio stream
        // moves its own packets instead (audio_stream_encoder.cpp).
        context->avoid_negative_ts = AVFMT_AVOID_NEG_TS_DISABLED;
    }
    return context;
}

}  // namespace

MuxerOutput MuxerOutput::to_file(const std::string& path, const char* muxer_name) {
    MuxerOutput output;
    output.path_ = path;
    // mkstemp in the target's own folder, so the final rename never crosses file systems.
    std::string temp_path = path + ".tmp-XXXXXX";
    const int fd = ::mkstemp(temp_path.data());
    if (fd < 0) throw FileError(path, std::string("cannot create a temporary file beside it: ") + std::strerror(errno));
    ::close(fd);
    output.temp_path_ = temp_path;
    // "file:" keeps a path with a colon in it from being read as another protocol; the MP4 muxer
    // reopens this URL to move its index to the front (faststart).
    const std::string url = "file:" + temp_path;
    output.context_ = allocate_context(muxer_name, url);
    return output;
}

MuxerOutput MuxerOutput::to_memory(const char* muxer_name) {
    MuxerOutput output;
    output.memory_ = std::make_unique<MemoryBuffer>();
    output.context_ = allocate_context(muxer_name, "");
    return output;
}

MuxerOutput::MuxerOutput(MuxerOutput&& other) noexcept
    : context_(std::exchange(other.context_, nullptr)),
      path_(std::move(other.path_)),
      temp_path_(std::move(other.temp_path_)),
      is_header_written_(other.is_header_written_),
      is_finished_(other.is_finished_),
      memory_(std::move(other.memory_)) {
    other.temp_path_.clear();
}

MuxerOutput::~MuxerOutput() {
    close_io();
    if (!temp_path_.empty() && !is_finished_) ::unlink(temp_path_.c_str());
}

void MuxerOutput::close_io() noexcept {
    if (context_ == nullptr) return;
    if (memory_) {
        if (context_->pb != nullptr) {
            av_freep(&context_->pb->buffer);
            avio_context_free(&context_->pb);
        }
    } else if (context_->pb != nullptr) {
        avio_closep(&context_->pb);
    }
    avformat_free_context(context_);
    context_ = nullptr;
}

void MuxerOutput::write_header(AVDictionary** options) {
    if (memory_) {
        auto* buffer = static_cast<std::uint8_t*>(av_malloc(kMemoryBlockBytes));
        if (buffer == nullptr) throw std::bad_alloc();
        context_->pb = avio_alloc_context(buffer, kMemoryBlockBytes, 1, memory_.get(), nullptr, write_to_memory,
                                          seek_in_memory);
        if (context_->pb == nullptr) {
            av_free(buffer);
            throw std::bad_alloc();
        }
    } else {
        const int opened = avio_open(&context_->pb, context_->url, AVIO_FLAG_WRITE);
        if (opened < 0) throw FileError(path_, "cannot write: " + ffmpeg_error_text(opened));
    }
    const int written = avformat_write_header(context_, options);
    if (written < 0) {
        if (is_file()) throw FileError(path_, "cannot write the container's header: " + ffmpeg_error_text(written));
        check_ffmpeg(written, "the container's header");
    }
    is_header_written_ = true;
}

void MuxerOutput::write_packet(AVPacket* packet) {
    const int written = av_interleaved_write_frame(context_, packet);
    if (written < 0) {
        if (is_file()) throw FileError(path_, "cannot write: " + ffmpeg_error_text(written));
        check_ffmpeg(written, "a packet");
    }
}

void MuxerOutput::finish() {
    const int trailer = av_write_trailer(context_);
    const int io_error = context_->pb != nullptr ? context_->pb->error : 0;
    if (memory_) {
        check_ffmpeg(trailer, "the container's trailer");
        close_io();
        is_finished_ = true;
        return;
    }
    const int closed = avio_closep(&context_->pb);
    const int failure = trailer < 0 ? trailer : io_error < 0 ? io_error : closed;
    if (failure < 0) throw FileError(path_, "cannot write: " + ffmpeg_error_text(failure));
    close_io();
    // mkstemp creates 0600. Keep the mode of the file being replaced, else the usual 0644 (as
    // common/atomic_file.cpp does).
    struct stat existing {};
    ::chmod(temp_path_.c_str(), ::stat(path_.c_str(), &existing) == 0 ? (existing.st_mode & 07777) : 0644);
    if (std::rename(temp_path_.c_str(), path_.c_str()) != 0) {
        throw FileError(path_, std::string("cannot replace: ") + std::strerror(errno));
    }
    is_finished_ = true;
}

std::string MuxerOutput::take_bytes() { return memory_ ? std::move(memory_->bytes) : std::string(); }

}  // namespace talkface::detail

#include "video/ffmpeg_support.hpp"

#include <cstring>
#include <new>

extern "C" {
#include <libavutil/error.h>
}

#include "common/internal_error.hpp"
#include "talkface/errors.hpp"

namespace talkface::detail {

void check_ffmpeg(int code, const char* what) {
    if (code == AVERROR(ENOMEM)) throw std::bad_alloc();
    if (code < 0) {
        throw internal_error(std::string("FFmpeg refused ") + what + ": " + ffmpeg_error_text(code));
    }
}

const AVCodec& find_encoder(const char* encoder_name, const std::string& purpose, const std::string& parameter) {
    quiet_ffmpeg_log();
    const AVCodec* codec = avcodec_find_encoder_by_name(encoder_name);
    if (codec == nullptr) {
        const unsigned version = avcodec_version();
        const std::string loaded = std::to_string(AV_VERSION_MAJOR(version)) + "." +
                                   std::to_string(AV_VERSION_MINOR(version)) + "." +
                                   std::to_string(AV_VERSION_MICRO(version));
        throw InvalidArgument(parameter, "this system's FFmpeg (libavcodec " + loaded + ") has no encoder \"" +
                                             std::string(encoder_name) + "\" for " + purpose +
                                             "; install an FFmpeg built with it (`ffmpeg -encoders` lists them) "
                                             "or choose another format");
    }
    return *codec;
}

FramePtr make_video_frame(AVPixelFormat format, int width, int height) {
    FramePtr frame(av_frame_alloc());
    if (!frame) throw std::bad_alloc();
    frame->format = format;
    frame->width = width;
    frame->height = height;
    check_ffmpeg(av_frame_get_buffer(frame.get(), 0), "a video frame's buffers");
    // Zeroed, padding included: encoders may read the padding past a row's end, and bytes left
    // from earlier allocations would make the same frames encode differently.
    for (AVBufferRef* buffer : frame->buf) {
        if (buffer != nullptr) std::memset(buffer->data, 0, buffer->size);
    }
    return frame;
}

PacketPtr make_packet() {
    PacketPtr packet(av_packet_alloc());
    if (!packet) throw std::bad_alloc();
    return packet;
}

}  // namespace talkface::detail

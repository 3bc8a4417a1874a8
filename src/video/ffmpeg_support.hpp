// What every part of the video stage needs from FFmpeg's libraries: owning handles, FFmpeg's
// messages (audio/ffmpeg_messages.hpp), and encoders looked up by name.
#ifndef TALKFACE_VIDEO_FFMPEG_SUPPORT_HPP
#define TALKFACE_VIDEO_FFMPEG_SUPPORT_HPP

#include <memory>
#include <string>

#include "audio/ffmpeg_messages.hpp"

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavutil/frame.h>
#include <libswresample/swresample.h>
#include <libswscale/swscale.h>
}

namespace talkface::detail {

struct CodecContextDeleter {
    void operator()(AVCodecContext* context) const { avcodec_free_context(&context); }
};
struct FrameDeleter {
    void operator()(AVFrame* frame) const { av_frame_free(&frame); }
};
struct PacketDeleter {
    void operator()(AVPacket* packet) const { av_packet_free(&packet); }
};
struct ScaleContextDeleter {
    void operator()(SwsContext* context) const { sws_freeContext(context); }
};
struct ResampleContextDeleter {
    void operator()(SwrContext* context) const { swr_free(&context); }
};

using CodecContextPtr = std::unique_ptr<AVCodecContext, CodecContextDeleter>;
using FramePtr = std::unique_ptr<AVFrame, FrameDeleter>;
using PacketPtr = std::unique_ptr<AVPacket, PacketDeleter>;
using ScaleContextPtr = std::unique_ptr<SwsContext, ScaleContextDeleter>;
using ResampleContextPtr = std::unique_ptr<SwrContext, ResampleContextDeleter>;

// Throws talkface::Error ("internal error (a bug in talkface)") if `code` < 0 — for calls that
// fail only when talkface passes them something wrong — naming `what` and FFmpeg's reason.
void check_ffmpeg(int code, const char* what);

// The encoder called `encoder_name` in the FFmpeg this process loaded. Found by name at run time,
// not linked: Debian's libavcodec carries libx264 (GPL-2+), another build may not.
// \throws talkface::InvalidArgument naming `parameter` (the output file), the encoder, what it is
//         for (`purpose`, e.g. "H.264 video for .mp4") and what to do.
const AVCodec& find_encoder(const char* encoder_name, const std::string& purpose, const std::string& parameter);

// A frame of `format`, `width` x `height`, with its buffers allocated.
FramePtr make_video_frame(AVPixelFormat format, int width, int height);

// A packet, or std::bad_alloc.
PacketPtr make_packet();

}  // namespace talkface::detail

#endif

// One video stream: RGBA frames in, converted to the encoder's pixel format (Yuv420Converter,
// libswscale for RGB formats, GifFrames' one palette for GIF) and encoded; packets go to a muxer,
// or to a callback (a PNG sequence writes each to its own file).
#ifndef TALKFACE_VIDEO_VIDEO_STREAM_ENCODER_HPP
#define TALKFACE_VIDEO_VIDEO_STREAM_ENCODER_HPP

#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>

#include "talkface/video_writer.hpp"
#include "video/ffmpeg_support.hpp"
#include "video/gif_frames.hpp"
#include "video/yuv420_converter.hpp"

namespace talkface::detail {

class VideoStreamEncoder {
public:
    using PacketSink = std::function<void(AVPacket* packet, AVRational time_base)>;

    // Opens the encoder of `format` for `options` (checked already). `global_header`: the
    // container wants codec headers out of band (MP4, WebM). `parameter` names the output in
    // errors (an encoder missing).
    VideoStreamEncoder(VideoFormat format, const VideoOptions& options, bool global_header,
                       const std::string& parameter);

    AVCodecContext* context() const { return encoder_.get(); }

    // Converts and encodes the next frame (its pts is the frame's index); packets go to `sink`.
    void encode(const std::uint8_t* rgba, std::size_t stride_bytes, const PacketSink& sink);
    // Drains the encoder into `sink`.
    void finish(const PacketSink& sink);

    std::int64_t frame_count() const { return next_pts_; }

private:
    void send(AVFrame* frame, const PacketSink& sink);

    CodecContextPtr encoder_;
    std::optional<Yuv420Converter> yuv_converter_;  // H.264 and VP9
    ScaleContextPtr converter_;                      // WebP and PNG: libswscale
    std::optional<GifFrames> gif_frames_;            // GIF: one palette from the first frames
    FramePtr frame_;
    PacketPtr packet_;
    std::int64_t next_pts_ = 0;
};

// The frame rate as a fraction (30000/1001 for 29.97).
AVRational frame_rate_of(double fps);

}  // namespace talkface::detail

#endif

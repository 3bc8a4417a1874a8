#include "video/video_stream_encoder.hpp"

#include <new>
#include <string>

extern "C" {
#include <libavutil/cpu.h>
#include <libavutil/opt.h>
}

#include "talkface/errors.hpp"

namespace talkface::detail {

namespace {

// x264 on flat cartoon frames: "animation" tuning (more reference frames, deblocking for flat
// areas) keeps edges clean at a low rate; the preset is "superfast". x264's macroblock tree
// (mbtree, with a lookahead) made files 0.4 as large in the same time, but by spending less on
// what changes, the moving mouth (53 dB PSNR instead of 59): left off (bench/README.md, "Video").
constexpr const char* kX264Preset = "superfast";
constexpr const char* kX264Tune = "animation";
constexpr int kX264DefaultCrf = 20;
// libvpx-vp9: constant quality (b=0 + crf); the "realtime" deadline with cpu-used 8 is the
// setting fast enough to keep up with the face at 720p on one core.
constexpr int kVp9DefaultCrf = 32;
constexpr int kWebpQuality = 80;

struct FormatEncoder {
    const char* encoder_name;
    const char* purpose;
    AVPixelFormat pixel_format;
};

FormatEncoder encoder_for(VideoFormat format, bool transparent) {
    switch (format) {
        case VideoFormat::mp4: return {"libx264", "H.264 video (.mp4)", AV_PIX_FMT_YUV420P};
        case VideoFormat::webm:
            return {"libvpx-vp9", "VP9 video (.webm)", transparent ? AV_PIX_FMT_YUVA420P : AV_PIX_FMT_YUV420P};
        // libwebp takes ARGB words (BGRA bytes on little-endian machines) as they are, alpha and all.
        case VideoFormat::webp: return {"libwebp_anim", "animated WebP (.webp)", AV_PIX_FMT_RGB32};
        case VideoFormat::png_sequence:
            return {"png", "PNG images (.png)", transparent ? AV_PIX_FMT_RGBA : AV_PIX_FMT_RGB24};
        // GifFrames maps the frames to one palette.
        case VideoFormat::gif: return {"gif", "animated GIF (.gif)", AV_PIX_FMT_PAL8};
    }
    throw InvalidArgument("format", "unknown video format");
}

// x264's instruction sets, capped at AVX2: with x264's AVX-512 code the same frames, encoded
// twice in one process, came out different (by one level, in the right-hand column of
// macroblocks) depending on what the heap held before, on this project's AVX-512 build machine;
// with AVX2 and below, or no assembly, they give the same bytes every time (tests/video, "the
// same frames and sound give the same bytes"). The level comes from FFmpeg's detection of the
// same CPU; elsewhere than x86 x264 keeps its own.
const char* x264_asm_level() {
#if defined(__x86_64__) || defined(__i386__)
    const int flags = av_get_cpu_flags();
    if ((flags & AV_CPU_FLAG_AVX2) && (flags & AV_CPU_FLAG_FMA3) && (flags & AV_CPU_FLAG_BMI2)) return "AVX2";
    if (flags & AV_CPU_FLAG_AVX) return "AVX";
    if (flags & AV_CPU_FLAG_SSE42) return "SSE4.2";
    if (flags & AV_CPU_FLAG_SSSE3) return "SSSE3";
    if (flags & AV_CPU_FLAG_SSE2) return "SSE2";
#endif
    return nullptr;
}

void set_option(AVCodecContext* encoder, const char* key, const std::string& value) {
    check_ffmpeg(av_opt_set(encoder->priv_data, key, value.c_str(), 0), key);
}

}  // namespace

AVRational frame_rate_of(double fps) { return av_d2q(fps, 1001000); }

VideoStreamEncoder::VideoStreamEncoder(VideoFormat format, const VideoOptions& options, bool global_header,
                                       const std::string& parameter) {
    const FormatEncoder chosen = encoder_for(format, options.transparent);
    const AVCodec& codec = find_encoder(chosen.encoder_name, chosen.purpose, parameter);
    encoder_.reset(avcodec_alloc_context3(&codec));
    if (!encoder_) throw std::bad_alloc();
    AVCodecContext* encoder = encoder_.get();
    const AVRational frame_rate = frame_rate_of(options.fps);
    encoder->width = options.width_px;
    encoder->height = options.height_px;
    encoder->pix_fmt = chosen.pixel_format;
    encoder->time_base = av_inv_q(frame_rate);
    encoder->framerate = frame_rate;
    encoder->sample_aspect_ratio = AVRational{1, 1};
    if (global_header) encoder->flags |= AV_CODEC_FLAG_GLOBAL_HEADER;
    const bool is_yuv = chosen.pixel_format == AV_PIX_FMT_YUV420P || chosen.pixel_format == AV_PIX_FMT_YUVA420P;
    if (is_yuv) {
        // Tagged as what Yuv420Converter does (BT.709, limited range), so players convert
        // back the same way: untagged HD video is read as BT.709 by some players and BT.601 by others.
        encoder->colorspace = AVCOL_SPC_BT709;
        encoder->color_primaries = AVCOL_PRI_BT709;
        encoder->color_trc = AVCOL_TRC_BT709;
        encoder->color_range = AVCOL_RANGE_MPEG;
    }
    switch (format) {
        case VideoFormat::mp4:
            set_option(encoder, "preset", kX264Preset);
            set_option(encoder, "tune", kX264Tune);
            if (const char* asm_level = x264_asm_level()) set_option(encoder, "x264-params", std::string("asm=") + asm_level);
            set_option(encoder, "crf", std::to_string(options.crf >= 0 ? options.crf : kX264DefaultCrf));
            encoder->profile = FF_PROFILE_H264_HIGH;
            // One thread: with x264's frame threads the same frames gave different bytes from run
            // to run here (tests/video, "the same frames and sound give the same bytes"), and the
            // face is cheap enough to encode on one core (bench/README.md).
            encoder->thread_count = 1;
            break;
        case VideoFormat::webm:
            encoder->bit_rate = 0;
            set_option(encoder, "crf", std::to_string(options.crf >= 0 ? options.crf : kVp9DefaultCrf));
            set_option(encoder, "deadline", "realtime");
            set_option(encoder, "cpu-used", "8");
            encoder->thread_count = 1;  // as for H.264: the same frames, the same bytes
            break;
        case VideoFormat::webp:
            encoder->global_quality = kWebpQuality * FF_QP2LAMBDA;
            encoder->flags |= AV_CODEC_FLAG_QSCALE;
            break;
        case VideoFormat::png_sequence: break;
        case VideoFormat::gif: break;
    }
    check_ffmpeg(avcodec_open2(encoder, &codec, nullptr), chosen.encoder_name);

    packet_ = make_packet();
    if (format == VideoFormat::gif) {
        gif_frames_.emplace(options.width_px, options.height_px, options.transparent, parameter);
        return;
    }
    if (is_yuv) {
        yuv_converter_.emplace(options.width_px, options.height_px, chosen.pixel_format == AV_PIX_FMT_YUVA420P);
    } else {
        converter_.reset(sws_getContext(options.width_px, options.height_px, AV_PIX_FMT_RGBA, options.width_px,
                                        options.height_px, chosen.pixel_format, SWS_BILINEAR | SWS_ACCURATE_RND | SWS_BITEXACT,
                                        nullptr, nullptr, nullptr));
        if (!converter_) throw std::bad_alloc();
    }
    frame_ = make_video_frame(chosen.pixel_format, options.width_px, options.height_px);
}

void VideoStreamEncoder::encode(const std::uint8_t* rgba, std::size_t stride_bytes, const PacketSink& sink) {
    if (gif_frames_) {
        gif_frames_->add(rgba, stride_bytes, [&](AVFrame* frame) { send(frame, sink); });
        ++next_pts_;
        return;
    }
    // The encoder may still hold the previous frame's buffers (reference counted): write into
    // fresh ones if so (which copies the picture: the YUV converter updates it where it changed).
    check_ffmpeg(av_frame_make_writable(frame_.get()), "a video frame");
    if (yuv_converter_) {
        Yuv420Planes planes;
        for (int plane = 0; plane < 4; ++plane) {
            planes.data[plane] = frame_->data[plane];
            planes.linesize[plane] = frame_->linesize[plane];
        }
        yuv_converter_->convert(rgba, stride_bytes, planes);
    } else {
        const std::uint8_t* source[1] = {rgba};
        const int source_stride[1] = {static_cast<int>(stride_bytes)};
        sws_scale(converter_.get(), source, source_stride, 0, encoder_->height, frame_->data, frame_->linesize);
    }
    frame_->pts = next_pts_++;
    send(frame_.get(), sink);
}

void VideoStreamEncoder::finish(const PacketSink& sink) {
    if (gif_frames_) gif_frames_->finish([&](AVFrame* frame) { send(frame, sink); });
    send(nullptr, sink);
}

void VideoStreamEncoder::send(AVFrame* frame, const PacketSink& sink) {
    check_ffmpeg(avcodec_send_frame(encoder_.get(), frame), "a video frame");
    for (;;) {
        const int received = avcodec_receive_packet(encoder_.get(), packet_.get());
        if (received == AVERROR(EAGAIN) || received == AVERROR_EOF) return;
        check_ffmpeg(received, "the video encoder's output");
        sink(packet_.get(), encoder_->time_base);
        av_packet_unref(packet_.get());
    }
}

}  // namespace talkface::detail

#include "media_probe.hpp"

#include <fstream>
#include <memory>
#include <stdexcept>

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavutil/pixdesc.h>
#include <libswscale/swscale.h>
}

namespace talkface_test {

namespace {

struct InputCloser {
    void operator()(AVFormatContext* context) const { avformat_close_input(&context); }
};
using InputPtr = std::unique_ptr<AVFormatContext, InputCloser>;

InputPtr open_input(const std::string& path) {
    AVFormatContext* context = nullptr;
    if (avformat_open_input(&context, path.c_str(), nullptr, nullptr) < 0) {
        throw std::runtime_error("cannot open " + path);
    }
    InputPtr input(context);
    if (avformat_find_stream_info(context, nullptr) < 0) throw std::runtime_error("no stream info in " + path);
    return input;
}

}  // namespace

const StreamInfo* MediaInfo::video() const {
    for (const StreamInfo& stream : streams) {
        if (stream.is_video) return &stream;
    }
    return nullptr;
}

const StreamInfo* MediaInfo::audio() const {
    for (const StreamInfo& stream : streams) {
        if (!stream.is_video) return &stream;
    }
    return nullptr;
}

MediaInfo probe_media(const std::string& path) {
    InputPtr input = open_input(path);
    MediaInfo info;
    info.container = input->iformat->name;
    info.duration_s = input->duration == AV_NOPTS_VALUE ? 0.0 : static_cast<double>(input->duration) / AV_TIME_BASE;
    std::vector<std::int64_t> first_pts(input->nb_streams, AV_NOPTS_VALUE);
    std::vector<std::int64_t> end_pts(input->nb_streams, AV_NOPTS_VALUE);
    for (unsigned i = 0; i < input->nb_streams; ++i) {
        const AVStream* stream = input->streams[i];
        StreamInfo s;
        s.codec = avcodec_get_name(stream->codecpar->codec_id);
        s.is_video = stream->codecpar->codec_type == AVMEDIA_TYPE_VIDEO;
        s.width = stream->codecpar->width;
        s.height = stream->codecpar->height;
        if (s.is_video) {
            const char* name = av_get_pix_fmt_name(static_cast<AVPixelFormat>(stream->codecpar->format));
            s.pixel_format = name != nullptr ? name : "";
        }
        s.sample_rate_hz = stream->codecpar->sample_rate;
        // Matroska reports Opus's pre-skip as a negative start; MP4 (edit list) and Ogg already skip it.
        if (s.sample_rate_hz > 0 && std::string(input->iformat->name).find("matroska") != std::string::npos) {
            s.priming_s = static_cast<double>(stream->codecpar->initial_padding) / s.sample_rate_hz;
        }
        info.streams.push_back(s);
    }
    AVPacket* packet = av_packet_alloc();
    while (av_read_frame(input.get(), packet) >= 0) {
        const unsigned index = static_cast<unsigned>(packet->stream_index);
        StreamInfo& s = info.streams[index];
        ++s.frame_count;
        if (packet->pts != AV_NOPTS_VALUE) {
            if (first_pts[index] == AV_NOPTS_VALUE || packet->pts < first_pts[index]) first_pts[index] = packet->pts;
            const std::int64_t end = packet->pts + packet->duration;
            if (end_pts[index] == AV_NOPTS_VALUE || end > end_pts[index]) end_pts[index] = end;
        }
        av_packet_unref(packet);
    }
    av_packet_free(&packet);
    for (unsigned i = 0; i < input->nb_streams; ++i) {
        const AVStream* stream = input->streams[i];
        const double unit = av_q2d(stream->time_base);
        StreamInfo& s = info.streams[i];
        // Skipped priming samples (AAC's 1024, Opus's pre-skip) come before time 0.
        std::int64_t start = stream->start_time != AV_NOPTS_VALUE ? stream->start_time : first_pts[i];
        if (start == AV_NOPTS_VALUE) start = 0;
        s.start_s = static_cast<double>(start) * unit;
        if (end_pts[i] != AV_NOPTS_VALUE) s.duration_s = static_cast<double>(end_pts[i] - start) * unit;
    }
    return info;
}

std::vector<std::uint8_t> decode_video_frame_rgba(const std::string& path, long index, int* width, int* height) {
    InputPtr input = open_input(path);
    const int stream_index = av_find_best_stream(input.get(), AVMEDIA_TYPE_VIDEO, -1, -1, nullptr, 0);
    if (stream_index < 0) throw std::runtime_error("no video in " + path);
    const AVStream* stream = input->streams[stream_index];
    const AVCodec* codec = avcodec_find_decoder(stream->codecpar->codec_id);
    // libvpx's decoder reads VP9's alpha channel; FFmpeg's native one drops it.
    if (stream->codecpar->codec_id == AV_CODEC_ID_VP9) {
        if (const AVCodec* vpx = avcodec_find_decoder_by_name("libvpx-vp9")) codec = vpx;
    }
    AVCodecContext* decoder = avcodec_alloc_context3(codec);
    avcodec_parameters_to_context(decoder, stream->codecpar);
    if (avcodec_open2(decoder, codec, nullptr) < 0) throw std::runtime_error("cannot open the decoder");
    AVPacket* packet = av_packet_alloc();
    AVFrame* frame = av_frame_alloc();
    std::vector<std::uint8_t> rgba;
    long seen = 0;
    bool is_done = false;
    auto take_frames = [&] {
        while (!is_done && avcodec_receive_frame(decoder, frame) >= 0) {
            if (seen++ == index) {
                *width = frame->width;
                *height = frame->height;
                SwsContext* scale = sws_getContext(frame->width, frame->height, static_cast<AVPixelFormat>(frame->format),
                                                   frame->width, frame->height, AV_PIX_FMT_RGBA, SWS_POINT, nullptr,
                                                   nullptr, nullptr);
                // As a player does: the coefficients and range the stream is tagged with.
                const int* coefficients = sws_getCoefficients(
                    frame->colorspace == AVCOL_SPC_BT709 ? SWS_CS_ITU709 : SWS_CS_DEFAULT);
                sws_setColorspaceDetails(scale, coefficients, frame->color_range == AVCOL_RANGE_JPEG ? 1 : 0,
                                         coefficients, 1, 0, 1 << 16, 1 << 16);
                rgba.resize(static_cast<std::size_t>(frame->width) * frame->height * 4);
                std::uint8_t* planes[1] = {rgba.data()};
                const int strides[1] = {frame->width * 4};
                sws_scale(scale, frame->data, frame->linesize, 0, frame->height, planes, strides);
                sws_freeContext(scale);
                is_done = true;
            }
            av_frame_unref(frame);
        }
    };
    while (!is_done && av_read_frame(input.get(), packet) >= 0) {
        if (packet->stream_index == stream_index) {
            avcodec_send_packet(decoder, packet);
            take_frames();
        }
        av_packet_unref(packet);
    }
    if (!is_done) {
        avcodec_send_packet(decoder, nullptr);
        take_frames();
    }
    av_frame_free(&frame);
    av_packet_free(&packet);
    avcodec_free_context(&decoder);
    if (!is_done) throw std::runtime_error("frame " + std::to_string(index) + " not found in " + path);
    return rgba;
}

void write_bytes(const std::string& path, const std::string& bytes) {
    std::ofstream out(path, std::ios::binary);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

}  // namespace talkface_test

#include "video/image_decoder.hpp"

#include <memory>

#include "talkface/errors.hpp"
#include "video/ffmpeg_support.hpp"

namespace talkface::detail {

namespace {

constexpr std::int64_t kMaxPixels = 100'000'000;

struct InputCloser {
    void operator()(AVFormatContext* context) const { avformat_close_input(&context); }
};

}  // namespace

RgbaImage decode_image_file(const std::string& path) {
    quiet_ffmpeg_log();
    AVFormatContext* opened = nullptr;
    // "file:" so that a name with a colon is not taken for another protocol.
    const int open_result = avformat_open_input(&opened, ("file:" + path).c_str(), nullptr, nullptr);
    if (open_result < 0) throw FileError(path, "cannot open the image: " + ffmpeg_error_text(open_result));
    const std::unique_ptr<AVFormatContext, InputCloser> input(opened);
    if (avformat_find_stream_info(input.get(), nullptr) < 0) throw FileError(path, "not a picture FFmpeg reads");
    const int stream_index = av_find_best_stream(input.get(), AVMEDIA_TYPE_VIDEO, -1, -1, nullptr, 0);
    if (stream_index < 0) throw FileError(path, "not a picture (no image stream in it)");
    const AVCodecParameters* parameters = input->streams[stream_index]->codecpar;
    const AVCodec* codec = avcodec_find_decoder(parameters->codec_id);
    if (codec == nullptr) {
        throw FileError(path, std::string("this system's FFmpeg has no decoder for its format (") +
                                  avcodec_get_name(parameters->codec_id) + ")");
    }
    CodecContextPtr decoder(avcodec_alloc_context3(codec));
    if (!decoder) throw std::bad_alloc();
    check_ffmpeg(avcodec_parameters_to_context(decoder.get(), parameters), "the image's parameters");
    if (avcodec_open2(decoder.get(), codec, nullptr) < 0) throw FileError(path, "cannot decode the image");

    PacketPtr packet = make_packet();
    FramePtr frame(av_frame_alloc());
    if (!frame) throw std::bad_alloc();
    bool has_frame = false;
    while (!has_frame && av_read_frame(input.get(), packet.get()) >= 0) {
        if (packet->stream_index == stream_index && avcodec_send_packet(decoder.get(), packet.get()) >= 0) {
            has_frame = avcodec_receive_frame(decoder.get(), frame.get()) >= 0;
        }
        av_packet_unref(packet.get());
    }
    if (!has_frame) {
        avcodec_send_packet(decoder.get(), nullptr);
        has_frame = avcodec_receive_frame(decoder.get(), frame.get()) >= 0;
    }
    if (!has_frame) throw FileError(path, "the image holds no picture FFmpeg could decode");
    if (static_cast<std::int64_t>(frame->width) * frame->height > kMaxPixels) {
        throw FileError(path, "the image is " + std::to_string(frame->width) + "x" + std::to_string(frame->height) +
                                  ", over 100 megapixels");
    }

    RgbaImage image;
    image.width = frame->width;
    image.height = frame->height;
    image.pixels.resize(static_cast<std::size_t>(image.width) * image.height * 4);
    const ScaleContextPtr converter(sws_getContext(image.width, image.height, static_cast<AVPixelFormat>(frame->format),
                                                   image.width, image.height, AV_PIX_FMT_RGBA,
                                                   SWS_BILINEAR | SWS_ACCURATE_RND, nullptr, nullptr, nullptr));
    if (!converter) throw FileError(path, "cannot convert the image's pixel format to RGBA");
    std::uint8_t* planes[1] = {image.pixels.data()};
    const int strides[1] = {image.width * 4};
    sws_scale(converter.get(), frame->data, frame->linesize, 0, image.height, planes, strides);
    return image;
}

}  // namespace talkface::detail

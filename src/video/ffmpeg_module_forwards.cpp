// libtalkface's side of the FFmpeg module (src/audio/ffmpeg_module.hpp): what the other stages and
// the public API call of src/video/'s FFmpeg files, forwarded to the module, which holds those
// files. VideoWriter::Impl here is the module's VideoWriter: video_writer.cpp's own Impl is in the
// module (and in the unit tests, which link the FFmpeg files and not this one).
#include <utility>

#include "audio/ffmpeg_module.hpp"
#include "talkface/video_writer.hpp"
#include "video/audio_encoder.hpp"
#include "video/image_decoder.hpp"

namespace talkface {
namespace detail {

std::string encode_audio_file(const std::string& audio_path, const AudioEncodeOptions& options) {
    return ffmpeg_module_calls().encode_audio_file(audio_path, options);
}

RgbaImage decode_image_file(const std::string& path) { return ffmpeg_module_calls().decode_image_file(path); }

}  // namespace detail

inline namespace v0 {

struct VideoWriter::Impl {
    const detail::FfmpegModuleCalls& calls;
    VideoWriter* in_module;
    VideoFormat format;
    VideoOptions options;

    Impl(const detail::FfmpegModuleCalls& module_calls, std::string path, VideoOptions video_options)
        : calls(module_calls),
          in_module(module_calls.open_video_writer(path, video_options)),
          format(video_format_from_path(path)),
          options(video_options) {}
    Impl(const Impl&) = delete;
    Impl& operator=(const Impl&) = delete;
    ~Impl() { calls.close_video_writer(in_module); }
};

VideoWriter::VideoWriter(std::string path, VideoOptions options)
    : impl_(std::make_unique<Impl>(detail::ffmpeg_module_calls(), std::move(path), options)) {}

VideoWriter::~VideoWriter() = default;
VideoWriter::VideoWriter(VideoWriter&&) noexcept = default;
VideoWriter& VideoWriter::operator=(VideoWriter&&) noexcept = default;

VideoFormat VideoWriter::format() const { return impl_->format; }
const VideoOptions& VideoWriter::options() const { return impl_->options; }
std::size_t VideoWriter::frame_count() const { return impl_->calls.frame_count(*impl_->in_module); }

void VideoWriter::add_audio(const AudioView& audio) { impl_->calls.add_audio(*impl_->in_module, audio); }

void VideoWriter::add_audio_file(const std::string& audio_path) {
    impl_->calls.add_audio_file(*impl_->in_module, audio_path);
}

void VideoWriter::write_frame(const std::uint8_t* rgba, std::size_t stride_bytes) {
    impl_->calls.write_frame(*impl_->in_module, rgba, stride_bytes);
}

void VideoWriter::finish() { impl_->calls.finish(*impl_->in_module); }

}  // namespace v0
}  // namespace talkface

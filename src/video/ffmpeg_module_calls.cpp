// The FFmpeg module's table (src/audio/ffmpeg_module.hpp): the functions themselves, as this module
// holds them.
#include "audio/ffmpeg_module.hpp"

#include <utility>

#include "talkface/version.h"
#include "video/audio_encoder.hpp"
#include "video/image_decoder.hpp"

namespace talkface::detail {

namespace {

VideoWriter* open_video_writer(std::string path, VideoOptions options) {
    return new VideoWriter(std::move(path), options);
}

void close_video_writer(VideoWriter* writer) { delete writer; }

std::size_t frame_count(const VideoWriter& writer) { return writer.frame_count(); }

void add_audio(VideoWriter& writer, const AudioView& audio) { writer.add_audio(audio); }

void add_audio_file(VideoWriter& writer, const std::string& audio_path) { writer.add_audio_file(audio_path); }

void write_frame(VideoWriter& writer, const std::uint8_t* rgba, std::size_t stride_bytes) {
    writer.write_frame(rgba, stride_bytes);
}

void finish(VideoWriter& writer) { writer.finish(); }

constexpr FfmpegModuleCalls kCalls{
    TALKFACE_VERSION_STRING, &open_ffmpeg_file, &encode_audio_file, &decode_image_file, &open_video_writer,
    &close_video_writer,     &frame_count,      &add_audio,         &add_audio_file,    &write_frame,
    &finish,
};

}  // namespace

}  // namespace talkface::detail

// Exported (the one symbol ffmpeg_module.map lets out): the library finds it with dlsym().
extern "C" __attribute__((visibility("default"))) const talkface::detail::FfmpegModuleCalls*
talkface_ffmpeg_module_calls() {
    return &talkface::detail::kCalls;
}

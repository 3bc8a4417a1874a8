// FFmpeg's work as a module that libtalkface opens on first use. Linking libavformat, libavcodec,
// libswscale and libswresample cost every program about 90 M instructions at start (the loader's
// relocations), most of a `talkface syllables`, though only MP3/M4A/Opus input, the pages' audio
// and video output use them. So src/audio/ffmpeg_source.cpp and src/video/'s FFmpeg files build
// LIBDIR/talkface/talkface_ffmpeg.so, with the earlier stages' code they call linked in, and
// libtalkface calls it through this table (src/audio/ffmpeg_module.cpp: the same functions,
// forwarding). Here, in the first stage that uses FFmpeg, with the later stage's types declared
// only: no header of src/video/ is included.
//
// The table is private to one build: the module and the library come from the same sources, and a
// module of another version is refused. Its calls throw talkface's errors as the functions do.
#ifndef TALKFACE_AUDIO_FFMPEG_MODULE_HPP
#define TALKFACE_AUDIO_FFMPEG_MODULE_HPP

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>

#include "audio/audio_source.hpp"
#include "audio/ffmpeg_source.hpp"
#include "talkface/video_writer.hpp"

namespace talkface::detail {

struct AudioEncodeOptions;
struct RgbaImage;

// The entries libtalkface calls: what the earlier stages' code calls of the FFmpeg files (checked
// by linking: libtalkface is linked without them) and VideoWriter's members.
struct FfmpegModuleCalls {
    // TALKFACE_VERSION_STRING of the build that made the module.
    const char* version;
    std::unique_ptr<AudioSource> (*open_ffmpeg_file)(const std::string& path, const FfmpegReading& reading);
    std::string (*encode_audio_file)(const std::string& audio_path, const AudioEncodeOptions& options);
    RgbaImage (*decode_image_file)(const std::string& path);
    // A VideoWriter made inside the module, which the library's VideoWriter holds and forwards to.
    VideoWriter* (*open_video_writer)(std::string path, VideoOptions options);
    void (*close_video_writer)(VideoWriter* writer);
    std::size_t (*frame_count)(const VideoWriter& writer);
    void (*add_audio)(VideoWriter& writer, const AudioView& audio);
    void (*add_audio_file)(VideoWriter& writer, const std::string& audio_path);
    void (*write_frame)(VideoWriter& writer, const std::uint8_t* rgba, std::size_t stride_bytes);
    void (*finish)(VideoWriter& writer);
};

// libtalkface's side: the module's table, the module opened on the first call (and kept open).
// \throws talkface::FileError naming the module's path if it is missing, cannot be loaded (a library
//         it links, FFmpeg's, is missing) or comes from another version of talkface.
const FfmpegModuleCalls& ffmpeg_module_calls();

}  // namespace talkface::detail

// The module's one exported symbol (src/audio/ffmpeg_module.map).
extern "C" const talkface::detail::FfmpegModuleCalls* talkface_ffmpeg_module_calls();

#endif

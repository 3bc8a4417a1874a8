// talkface: VideoWriter, which encodes frames of RGBA pixels and a speech into a video file through
// FFmpeg's libraries (issue #16): MP4 (H.264 + AAC) for video sites, phones and presentations,
// WebM (VP9 + Opus, with an alpha channel if asked) for compositing, animated WebP or GIF for
// chats, and a numbered PNG sequence for editors.
//
//   talkface::VideoOptions options;              // 1280x720, 30 fps
//   talkface::VideoWriter video("talk.mp4", options);
//   video.add_audio_file("speech.wav");
//   std::vector<std::uint8_t> rgba(1280 * 720 * 4, 0xff);  // a white frame, R G B A per pixel
//   for (int k = 0; k < 5 * options.fps; ++k)   // 5 s of frames; frame k is shown at k / fps
//       video.write_frame(rgba.data(), 1280 * 4);
//   video.finish();                              // renamed into place only now
//
// Which encoder is used is decided at run time by name from the FFmpeg the process loaded
// (libx264, libvpx-vp9, libwebp_anim, png, gif; aac, libopus), so a system FFmpeg without one of them is
// refused with its name, not at link time. Thread safety: one writer is used by one thread at a
// time; different writers may run on different threads.
#ifndef TALKFACE_VIDEO_WRITER_HPP
#define TALKFACE_VIDEO_WRITER_HPP

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <string_view>

#include "talkface/export.h"
#include "talkface/speech_aligner.hpp"

namespace talkface {
inline namespace v0 {

/// The kind of file, told by the output's extension. The numeric values are stable within a
/// major version.
enum class VideoFormat : int {
    mp4 = 0,           ///< .mp4: H.264 (yuv420p, BT.709) + AAC, index in front; browsers, phones, video sites
    webm = 1,          ///< .webm: VP9 + Opus; transparent: yuva420p, an alpha channel editors and Chromium read
    webp = 2,          ///< .webp: animated WebP, no sound; chats
    png_sequence = 3,  ///< .png: OUT-000000.png, OUT-000001.png, ... (frame k at k / fps), no sound
    /// .gif: animated GIF, looping, no sound; chats. One palette of 255 colours, made from the
    /// first frames (all of a short GIF; 32 MB of them kept compressed, 25 s of a talking face at
    /// 720p), the rest written as they come, so memory stays bounded; 1..50 fps, as players show
    /// a frame for whole hundredths of a second and take shorter than 0.02 s as 0.1 s;
    /// transparent: alpha under half is GIF's transparent colour.
    gif = 4,
};

/// "mp4", "webm", "webp", "png", "gif".
TALKFACE_API const char* video_format_name(VideoFormat format);
/// The format of an output path by its extension (either case).
/// \throws talkface::InvalidArgument naming the path and its extension and listing the known ones.
TALKFACE_API VideoFormat video_format_from_path(std::string_view path);

/// How a video is encoded.
struct VideoOptions {
    int width_px = 1280;  ///< 2..7680 (the longer side) by 2..4320 (the shorter); even for .mp4 and .webm
    int height_px = 720;
    double fps = 30.0;    ///< frames per second, 1..120
    /// Constant quality, lower is better and larger: H.264 0..51 (default 20), VP9 0..63 (default
    /// 32); -1 picks the default. WebP, GIF and PNG ignore it.
    int crf = -1;
    /// Keep the frames' alpha channel: .webm (yuva420p), .webp, .gif and .png only. Otherwise alpha is
    /// ignored and frames should be opaque.
    bool transparent = false;
};

/// Checks `options` for an output at `path`, as VideoWriter's constructor does, without creating
/// anything. \throws talkface::InvalidArgument naming the option (width_px, height_px, fps, crf,
/// transparent) or the extension, with what was expected; H.264 and VP9 (4:2:0) need even sides.
TALKFACE_API void check_video_options(std::string_view path, const VideoOptions& options);

/// Encodes frames into a video file. Everything is written to a temporary file (or folder, for a
/// PNG sequence) beside the output and renamed into place by finish(): a writer destroyed before
/// finish() (an exception, a cancel) leaves no output and nothing else behind.
///
/// Movable, not copyable.
class TALKFACE_API VideoWriter {
public:
    /// Opens the output. \throws talkface::InvalidArgument as check_video_options(), or if the
    /// system's FFmpeg lacks the format's encoder (naming it); talkface::FileError if the
    /// temporary file cannot be created beside `path`.
    VideoWriter(std::string path, VideoOptions options = {});
    ~VideoWriter();
    VideoWriter(VideoWriter&&) noexcept;
    VideoWriter& operator=(VideoWriter&&) noexcept;
    VideoWriter(const VideoWriter&) = delete;
    VideoWriter& operator=(const VideoWriter&) = delete;

    VideoFormat format() const;            ///< from the output's extension
    const VideoOptions& options() const;   ///< as given
    std::size_t frame_count() const;       ///< frames written so far

    /// The sound, starting with frame 0: `audio`'s samples (mixed down to mono), read while frames
    /// are written, so they must stay valid until finish(). .webp, .gif and .png have no sound and ignore
    /// it. At most one audio per writer, before the first frame.
    /// \throws talkface::InvalidArgument if audio was added already, a frame was written, or
    ///         `audio` is malformed.
    void add_audio(const AudioView& audio);
    /// The same from an audio file (WAV, FLAC, OGG, ... as SpeechAligner::align_file reads it).
    /// \throws talkface::FileError / ParseError if it cannot be read, and as add_audio().
    void add_audio_file(const std::string& audio_path);

    /// Appends one frame of width_px x height_px pixels, 8-bit R, G, B, A per pixel (straight, not
    /// premultiplied alpha), row y at rgba + y * stride_bytes.
    /// \throws talkface::InvalidArgument if rgba is null or stride_bytes < 4 * width_px;
    ///         talkface::FileError if the output cannot be written.
    void write_frame(const std::uint8_t* rgba, std::size_t stride_bytes);

    /// Encodes the rest of the sound, closes the file and renames it into place. The file lasts
    /// frame_count() / fps, or the sound's length if that is longer. Call once; later calls
    /// throw. \throws talkface::InvalidArgument if no frame was written; talkface::FileError.
    void finish();

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace v0
}  // namespace talkface

#endif

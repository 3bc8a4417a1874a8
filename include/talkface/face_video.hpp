// talkface: render_video, the talking face as a video file: an animation drawn frame by frame by
// FrameRenderer (the announcer layout by default) and encoded with the speech by VideoWriter.
//
//   talkface::FaceVideoOptions options;                    // 1280x720, 30 fps, the announcer
//   talkface::render_video("talk.mp4", face, animation, "speech.wav", options, progress);
#ifndef TALKFACE_FACE_VIDEO_HPP
#define TALKFACE_FACE_VIDEO_HPP

#include <string>

#include "talkface/animation.hpp"
#include "talkface/export.h"
#include "talkface/face_model.hpp"
#include "talkface/frame_renderer.hpp"
#include "talkface/speech_aligner.hpp"
#include "talkface/video_writer.hpp"

namespace talkface {
inline namespace v0 {

/// How the face becomes a video.
struct FaceVideoOptions {
    /// Size, frame rate, quality, transparency (its size is the frames' size).
    VideoOptions video;
    /// Layout, background colour, clothes and the face's placement; width_px and height_px are
    /// taken from `video`. A transparent video has no background colour.
    FrameOptions frame;
    /// A picture drawn over the background colour, covering the frame (PNG, JPEG, WebP, BMP, SVG,
    /// as the system's FFmpeg decodes them); empty for none.
    std::string background_image_path;
};

/// Writes a video of `face` playing `animation`, with the speech at `audio_path` (empty: silent).
/// The announcer layout with no placement given stands the face where the announcer page stands it
/// for the same animation (larger, if need be, so that its open mouth would clear the caption).
/// Frame k shows the animation at time k / fps (its nearest frame); the video has as many frames
/// as cover the speech (ceil(duration * fps)), or the animation's when silent, so the file lasts as
/// long as the speech within one frame. `progress` gets the fraction of frames done and "video";
/// returning false cancels. Written through a temporary file: a failure or a cancel leaves none.
/// \throws talkface::InvalidArgument as VideoWriter and FrameRenderer do (naming the option), or
///         if the animation has no frames; talkface::FileError if the audio, the background image
///         or the output cannot be read or written; talkface::Cancelled.
TALKFACE_API void render_video(const std::string& path, const FaceModel& face, const Animation& animation,
                               const std::string& audio_path, const FaceVideoOptions& options = {},
                               const ProgressCallback& progress = {});

}  // namespace v0
}  // namespace talkface

#endif

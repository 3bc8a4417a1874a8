// render_video: FrameRenderer's frames into VideoWriter, one at a time (a frame's RGBA buffer is
// the only picture held), the speech streamed beside them.
#include "talkface/face_video.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

#include "audio/audio_source.hpp"
#include "raster/frame_layout.hpp"
#include "talkface/errors.hpp"
#include "video/image_decoder.hpp"

namespace talkface {
inline namespace v0 {

namespace {

// Frames that cover `duration_s` at `fps`: the last starts before the speech ends.
std::size_t frames_covering(double duration_s, double fps) {
    return static_cast<std::size_t>(std::max(1.0, std::ceil(duration_s * fps - 1e-9)));
}

}  // namespace

void render_video(const std::string& path, const FaceModel& face, const Animation& animation,
                  const std::string& audio_path, const FaceVideoOptions& options, const ProgressCallback& progress) {
    if (animation.frames.empty()) throw InvalidArgument("animation", "has no frames");
    check_video_options(path, options.video);
    FrameOptions frame_options = options.frame;
    frame_options.width_px = options.video.width_px;
    frame_options.height_px = options.video.height_px;
    frame_options.alpha = AlphaMode::straight;
    // The announcer stands where the announcer page stands it for this animation (its mouth clear
    // of the page's lower third), so that the video and the page agree.
    frame_options = detail::with_announcer_placement(face, animation.frames, frame_options);
    if (options.video.transparent) frame_options.background.reset();
    FrameRenderer renderer(face, frame_options);
    if (!options.background_image_path.empty()) {
        const detail::RgbaImage image = detail::decode_image_file(options.background_image_path);
        renderer.set_background_image(image.pixels.data(), image.width, image.height,
                                      static_cast<std::size_t>(image.width) * 4);
    }

    std::size_t frame_count = 0;
    if (audio_path.empty()) {
        frame_count = frames_covering(static_cast<double>(animation.frames.size()) / animation.fps, options.video.fps);
    } else {
        const std::unique_ptr<detail::AudioSource> audio = detail::open_audio_file(audio_path);
        frame_count = frames_covering(static_cast<double>(audio->frame_count()) / audio->sample_rate_hz(),
                                      options.video.fps);
    }

    VideoWriter writer(path, options.video);
    if (!audio_path.empty()) writer.add_audio_file(audio_path);
    std::vector<std::uint8_t> pixels(renderer.height_px() * renderer.stride_bytes());
    for (std::size_t k = 0; k < frame_count; ++k) {
        if (progress && !progress(static_cast<double>(k) / static_cast<double>(frame_count), "video")) {
            throw Cancelled("video cancelled at frame " + std::to_string(k) + " of " + std::to_string(frame_count) +
                            "; nothing was written");
        }
        // SPEC: frame k shows the face at time k / fps.
        const double time_s = static_cast<double>(k) / options.video.fps;
        const auto index = std::min<std::size_t>(static_cast<std::size_t>(std::lround(time_s * animation.fps)),
                                                 animation.frames.size() - 1);
        renderer.render_frame_rgba(animation.frames[index], pixels.data(), renderer.stride_bytes());
        writer.write_frame(pixels.data(), renderer.stride_bytes());
    }
    writer.finish();
    if (progress) progress(1.0, "video");
}

}  // namespace v0
}  // namespace talkface

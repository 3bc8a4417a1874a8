// The animation editor (thesis 5.4, Figure 5.10): lips from the key frames, the rest of the face
// from the expression simulator, one FaceState per frame.
#include "talkface/animation.hpp"

#include <algorithm>
#include <cmath>

#include "animation/lip_sync_checks.hpp"

namespace talkface {
inline namespace v0 {

Animation animate(const FaceModel& neutral, const Timeline& timeline, const ExpressionSimulator& expressions,
                  const LipSyncOptions& options) {
    detail::check_lip_sync_options(options);
    Animation animation;
    animation.fps = options.fps;
    animation.duration_s = std::max(timeline_end_s(timeline), expressions.duration_s());
    animation.mouth_key_frames = mouth_key_frames(timeline, options);
    animation.events = expressions.events();
    // The small allowance keeps a duration that is a whole number of frames from losing its last
    // frame to rounding (3.0 s * 25 fps = 74.99999...).
    const auto frame_count =
        static_cast<std::size_t>(std::floor(animation.duration_s * options.fps + 1e-9)) + 1;
    const std::vector<MouthControls> mouths =
        mouth_frames(neutral, animation.mouth_key_frames, frame_count, options);
    animation.frames.reserve(frame_count);
    for (std::size_t i = 0; i < frame_count; ++i) {
        const double time_s = static_cast<double>(i) / options.fps;
        animation.frames.push_back(
            {expressions.pose_at(time_s), expressions.expression_at(time_s), mouths[i]});
    }
    return animation;
}

}  // namespace v0
}  // namespace talkface

// One frame of an Animation projected for drawing, as every animation encoding (SVG, Lottie) draws
// it: a state that cannot be drawn is an error naming the frame and its time; and the frames that
// only hold the one before, which every encoding draws once.
#ifndef TALKFACE_RENDER_ANIMATION_FRAME_HPP
#define TALKFACE_RENDER_ANIMATION_FRAME_HPP

#include <cstddef>

#include "talkface/animation.hpp"
#include "talkface/face_pose.hpp"

namespace talkface::detail {

// What every encoding asks of its input: frames, a finite fps > 0 and a finite tolerance_px > 0.
// \throws talkface::InvalidArgument naming the first that is not so.
void check_animation_input(const Animation& animation, double tolerance_px);

// project_face() of frame `frame` of `animation`.
// \throws talkface::InvalidArgument naming animation.frames[frame] and its time, with
//         project_face()'s error nested.
ProjectedFace project_animation_frame(const FaceModel& face, const Animation& animation, std::size_t frame);

// Holds (pauses, a held head) repeat a frame exactly: whether `state`, its head tilted by
// `angle_deg`, draws the same as the last frame drawn, `previous` (nullptr: none yet) tilted by
// `previous_angle_deg`.
bool is_held_frame(const FaceState& state, double angle_deg, const FaceState* previous, double previous_angle_deg);

}  // namespace talkface::detail

#endif

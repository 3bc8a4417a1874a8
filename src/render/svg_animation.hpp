// The temporal half of SvgAnimator (thesis 6.3.2): an Animation as one SVG document, in either
// encoding, on the canvas the spatial half draws single faces on.
#ifndef TALKFACE_RENDER_SVG_ANIMATION_HPP
#define TALKFACE_RENDER_SVG_ANIMATION_HPP

#include <string>

#include "render/svg_document.hpp"
#include "talkface/animation.hpp"
#include "talkface/svg_animator.hpp"

namespace talkface::detail {

// The animation as one SVG document on `canvas` (SvgAnimator::render_animation_svg()).
std::string render_animation(const FaceModel& face, const SvgOptions& svg_options, const SvgCanvas& canvas,
                             const Animation& animation, const SvgAnimationOptions& options,
                             const ProgressCallback& progress);

// The animation (keyframes encoding) drawn with its head at rest (every pose at 0), and what the
// pose adds carried apart: the head groups' tilt and, in each element the turn and nod move, an
// additive animation, all of class "tf-pose". Without them the document is render_animation() of
// the frames with the head at rest, byte for byte; with them every frame is within the tolerance of
// the animation as drawn. A page shows the head still (reduced motion) by taking them out.
std::string render_animation_with_pose_apart(const FaceModel& face, const SvgOptions& svg_options,
                                             const SvgCanvas& canvas, const Animation& animation,
                                             const SvgAnimationOptions& options,
                                             const ProgressCallback& progress);

}  // namespace talkface::detail

#endif

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

}  // namespace talkface::detail

#endif

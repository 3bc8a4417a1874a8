// An Animation as one Lottie document (SvgAnimator::render_animation_lottie()): every frame drawn
// as the drawing model (layers.hpp), each layer encoded by a LottieLayerEncoder, the layers
// stacked on the canvas the SVG documents use.
#ifndef TALKFACE_RENDER_LOTTIE_ANIMATION_HPP
#define TALKFACE_RENDER_LOTTIE_ANIMATION_HPP

#include <string>

#include "render/svg_document.hpp"
#include "talkface/animation.hpp"
#include "talkface/svg_animator.hpp"

namespace talkface::detail {

std::string render_lottie(const FaceModel& face, const SvgOptions& svg_options, const SvgCanvas& canvas,
                          const Animation& animation, const LottieOptions& options, const ProgressCallback& progress);

}  // namespace talkface::detail

#endif

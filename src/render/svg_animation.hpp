// The temporal half of SvgAnimator (thesis 6.3.2): an Animation as one SVG document, in either
// encoding, on the canvas the spatial half draws single faces on.
#ifndef TALKFACE_RENDER_SVG_ANIMATION_HPP
#define TALKFACE_RENDER_SVG_ANIMATION_HPP

#include <optional>
#include <string>

#include "render/layers.hpp"
#include "talkface/animation.hpp"
#include "talkface/svg_animator.hpp"

namespace talkface::detail {

// A face's canvas and the size the document asks to be shown at.
struct SvgCanvas {
    CanvasBox box;
    int width_px = 0;
    int height_px = 0;
};

// The root element's start tag (with a trailing newline); `class_name` may be empty.
std::string open_svg_root(const SvgCanvas& canvas, int decimals, const std::string& class_name);

// The background layer: a rectangle over the canvas, or an empty group for no colour.
std::string draw_background_layer(const SvgCanvas& canvas, const std::optional<Rgb>& colour, int decimals);

std::string render_animation(const FaceModel& face, const SvgOptions& svg_options, const SvgCanvas& canvas,
                             const Animation& animation, const SvgAnimationOptions& options,
                             const ProgressCallback& progress);

}  // namespace talkface::detail

#endif

// The parts of an SVG document around its layers: the root element on the face's canvas and the
// background layer. Shared by the single face (svg_animator.cpp) and the animation (svg_animation.cpp).
#ifndef TALKFACE_RENDER_SVG_DOCUMENT_HPP
#define TALKFACE_RENDER_SVG_DOCUMENT_HPP

#include <optional>
#include <string>

#include "render/layers.hpp"
#include "talkface/face_model.hpp"

namespace talkface::detail {

// A face's canvas and the size the document asks to be shown at.
struct SvgCanvas {
    CanvasBox box;
    int width_px = 0;
    int height_px = 0;
};

// The canvas that fits `face` at every pose (face_canvas.hpp), shown at `width_px` x `height_px`:
// 0 for both is the canvas's own size, 0 for one keeps the canvas's shape (SvgOptions).
SvgCanvas face_svg_canvas(const FaceModel& face, int width_px, int height_px);

// The XML declaration every document starts with.
inline constexpr const char* kXmlDeclaration = "<?xml version=\"1.0\" encoding=\"UTF-8\" standalone=\"no\"?>\n";

// The root element's start tag (with a trailing newline); `class_name` may be empty.
std::string open_svg_root(const SvgCanvas& canvas, int decimals, const std::string& class_name);

// The background layer as a group: a rectangle over the canvas, or an empty group for no colour.
std::string background_layer_svg(const SvgCanvas& canvas, const std::optional<Rgb>& colour, int decimals);

// `<g id="ID">`, the layer's content, `</g>`.
std::string layer_group_svg(const char* id, const Layer& layer, int decimals);

}  // namespace talkface::detail

#endif

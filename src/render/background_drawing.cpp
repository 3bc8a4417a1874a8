// The background layer (thesis 6.3.1): the canvas filled with one colour, under everything else.
#include <utility>

#include "render/layers.hpp"

namespace talkface::detail {

Layer draw_background_layer(const CanvasBox& canvas, const std::optional<Rgb>& colour) {
    Layer layer;
    if (!colour) return layer;
    Shape rect;
    rect.kind = ShapeKind::rect;
    rect.corner = {canvas.x, canvas.y};
    rect.width = canvas.width;
    rect.height = canvas.height;
    rect.paint.fill = Paint::of(*colour);
    layer.elements.push_back(std::move(rect));
    return layer;
}

}  // namespace talkface::detail

// The drawing model (render/drawing.hpp) drawn with cairo: every shape kind, paint, gradient and
// clip path, as an SVG renderer draws the same layer (fills nonzero, then strokes with round joins
// and caps; gradients in the shape's bounding box; clip paths by their outline).
#ifndef TALKFACE_RASTER_CAIRO_DRAWING_HPP
#define TALKFACE_RASTER_CAIRO_DRAWING_HPP

#include <cairo.h>

#include "render/drawing.hpp"
#include "render/layers.hpp"

namespace talkface::detail {

// Draws `layer` on `cairo` in its current user space (the drawing's units).
void draw_layer(cairo_t* cairo, const Layer& layer);

// A box around everything `layer` can paint, in the drawing's units: every point (a Bezier curve
// stays inside its control points), every circle and rectangle, widened by half the widest
// stroke. Empty (width 0) for an empty layer.
CanvasBox layer_extent(const Layer& layer);

}  // namespace talkface::detail

#endif

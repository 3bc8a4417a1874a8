// The drawing of each SVG layer (thesis 6.3.1) from a projected face. Each function returns the
// layer's content, to go inside its <g id="..."> group.
#ifndef TALKFACE_RENDER_LAYERS_HPP
#define TALKFACE_RENDER_LAYERS_HPP

#include <string>

#include "talkface/face_pose.hpp"
#include "talkface/types.hpp"

namespace talkface::detail {

// What every layer draws with.
struct LayerStyle {
    int decimals = 2;        // digits after the point in coordinates
    double stroke_px = 1.0;  // outline width
};

// The canvas in the face's image pixels (the SVG user space is the face's image space).
struct CanvasBox {
    double x = 0.0;
    double y = 0.0;
    double width = 0.0;
    double height = 0.0;
};

// The hair contour: the 23 hair points, corner-cut, filled with the hair colour.
std::string draw_hair_layer(const ProjectedFace& face, const LayerStyle& style);

// Neck and shoulders, placed from O and d of the face. They do not turn with the head.
std::string draw_clothes_layer(const ProjectedFace& face, const CanvasBox& canvas, Rgb clothes,
                               const LayerStyle& style);

// Ears, face contour, nose, eyebrows, eyes with clipped eyeballs, mouth (Algorithm 2.2), with the
// clip paths and gradients they use in a <defs> of their own. Ids start with "tf-".
std::string draw_face_layer(const ProjectedFace& face, const LayerStyle& style);

}  // namespace talkface::detail

#endif

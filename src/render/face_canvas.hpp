// The canvas every state of one face is drawn on: SVG documents (their viewBox) and raster frames
// (their placement) share it, so frames line up.
#ifndef TALKFACE_RENDER_FACE_CANVAS_HPP
#define TALKFACE_RENDER_FACE_CANVAS_HPP

#include "render/layers.hpp"
#include "talkface/face_model.hpp"

namespace talkface::detail {

// Every point of the face at the extreme poses (each angle -15, 0 or 15 degrees), with the mouth
// wide open and the brows raised, plus a margin, in the face's image pixels; centred on O so that
// the body below it is centred too, and wide and deep enough for the clothes. Whole pixels.
CanvasBox fit_face_canvas(const FaceModel& face);

}  // namespace talkface::detail

#endif

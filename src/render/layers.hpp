// The layers of thesis 6.3.1 built from a projected face, as the drawing model (drawing.hpp): what
// the SVG writers and the raster renderer draw. Each builder returns one layer's content.
#ifndef TALKFACE_RENDER_LAYERS_HPP
#define TALKFACE_RENDER_LAYERS_HPP

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "render/drawing.hpp"
#include "talkface/face_look.hpp"
#include "talkface/face_pose.hpp"
#include "talkface/types.hpp"

namespace talkface::detail {

// What every layer draws with.
struct LayerStyle {
    int decimals = 2;        // digits after the point when the layer is written as SVG
    double stroke_px = 1.0;  // outline width, in the drawing's units
    FaceLook look = FaceLook::outlined;
};

// The canvas in the face's image pixels (the SVG user space is the face's image space).
struct CanvasBox {
    double x = 0.0;
    double y = 0.0;
    double width = 0.0;
    double height = 0.0;
};

// Where the layers are drawn: image pixels p as scale * Rotation(-angle) (p - origin). A single
// frame is drawn in image pixels (the identity). The keyframes encoding draws the head in the
// frame of a group that its SVG turns by the tilt and scales by 1 / scale (head_tilt.hpp):
// the layers are drawn with points, so mapping the points maps the drawing (Catmull-Rom and
// corner cutting take affine combinations of them), and a rotation with a uniform scale keeps
// the eyeballs round.
class ViewMap {
public:
    ViewMap() = default;
    ViewMap(Point2 origin, double angle_deg, double scale);
    Point2 apply(Point2 image_xy) const;
    // A displacement in image pixels, in the drawing's units and directions.
    Point2 apply_to_offset(Point2 offset_px) const;
    double scale() const { return scale_; }

private:
    bool is_identity_ = true;
    Point2 origin_{0.0, 0.0};
    double scale_ = 1.0;
    double cos_ = 1.0, sin_ = 0.0;
};

// What every state of one face is drawn with: the style, the paints and gradients. An animation
// builds it once instead of once a frame, and sets its view per frame.
struct FacePaints {
    LayerStyle style;  // in the view's units
    ViewMap view;
    ShapePaint skin, ears, hair, nose, brows, eye_white, eye_outline, lips, mouth_opening;
    ShapePaint nose_shade;  // none: no shade
    ShapePaint eye_lid;     // the upper lids' band (its stroke width); none: no lid
    ShapePaint teeth, lower_teeth, tongue;   // inside the mouth, over mouth_opening's fill
    RadialGradient iris_gradient;            // of both irises
    // The point of `face` at `index` in the lifted order (lift/lifted_point_index.hpp), in the view.
    Point2 point(const ProjectedFace& face, std::size_t index) const;
};

// \throws talkface::InvalidArgument ("look") unless `look` is FaceLook::outlined or FaceLook::flat.
void check_face_look(FaceLook look);

// The flat look's shade of the skin, where an outline told two skins apart: the ears against the
// face, the neck against the chin.
Rgb flat_skin_shade(const FaceColors& colors);

// The paints of `face`, at any state of it.
FacePaints make_face_paints(const ProjectedFace& face, const LayerStyle& style);

// The points draw_hair_layer() draws from, in the view of `paints`: the hair polygon, then the ears'.
std::vector<Point2> hair_layer_points(const ProjectedFace& face, const FacePaints& paints);

// The background: a rectangle of `colour` over the canvas, or nothing.
Layer draw_background_layer(const CanvasBox& canvas, const std::optional<Rgb>& colour);

// The back of the head: the ears, then over them the hair contour (the 23 hair points, corner-cut:
// Path::corner_cut_closed, filled with the hair colour), which hides them where it reaches.
Layer draw_hair_layer(const ProjectedFace& face, const FacePaints& paints);

// Neck and shoulders, placed from O and d of the face, in image pixels. They do not turn with the
// head.
Layer draw_clothes_layer(const ProjectedFace& face, const CanvasBox& canvas, Rgb clothes, const LayerStyle& style);

// Face contour, nose, eyebrows, eyes with clipped eyeballs, mouth (Algorithm 2.2), with the
// clip paths and gradients they use among its definitions. Ids start with "tf-".
Layer draw_face_layer(const ProjectedFace& face, const FacePaints& paints);

}  // namespace talkface::detail

#endif

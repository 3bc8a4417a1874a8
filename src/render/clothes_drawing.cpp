// The clothes layer (thesis 6.3.1, Figures 6.7 and 6.8): a neck and shoulders under the head.
#include <algorithm>
#include <utility>

#include "render/curves.hpp"
#include "render/layers.hpp"
#include "render/svg_text.hpp"

namespace talkface::detail {

namespace {

// Body proportions in units of d, measured from the rotation origin O (the neck, thesis 2.3).
constexpr double kNeckTopInD = -0.35;       // above O: hidden under the face at every pose
constexpr double kNeckHalfWidthInD = 0.36;
constexpr double kCollarInD = 0.95;         // where the neck meets the shirt
constexpr double kCollarDipInD = 1.35;      // bottom of the V of the collar
constexpr double kShoulderHalfWidthInD = 2.0;
constexpr double kShoulderInD = 1.45;

}  // namespace

Layer draw_clothes_layer(const ProjectedFace& face, const CanvasBox& canvas, Rgb clothes, const LayerStyle& style) {
    // The body stays put while the head turns, so everything hangs from O and d alone.
    const Point2 o = face.origin;
    const double d = face.d;
    const double bottom = canvas.y + canvas.height;
    const double left_edge = std::max(canvas.x, o.x - kShoulderHalfWidthInD * d);
    const double right_edge = std::min(canvas.x + canvas.width, o.x + kShoulderHalfWidthInD * d);
    auto at = [&](double dx_in_d, double dy_in_d) { return Point2{o.x + dx_in_d * d, o.y + dy_in_d * d}; };
    const FaceColors& colors = face.face.colors();

    // The neck reaches below the V of the collar, so no background shows through the V.
    const double neck_bottom_in_d = kCollarDipInD + 0.1;
    Path neck;
    neck.move_to(at(-kNeckHalfWidthInD, kNeckTopInD))
        .arc({at(-kNeckHalfWidthInD, kNeckTopInD), at(-kNeckHalfWidthInD * 0.97, 0.5 * kCollarInD),
              at(-kNeckHalfWidthInD * 1.1, neck_bottom_in_d)})
        .line_to(at(kNeckHalfWidthInD * 1.1, neck_bottom_in_d))
        .arc({at(kNeckHalfWidthInD * 1.1, neck_bottom_in_d), at(kNeckHalfWidthInD * 0.97, 0.5 * kCollarInD),
              at(kNeckHalfWidthInD, kNeckTopInD)})
        .close();
    Layer layer;
    Shape neck_shape;
    neck_shape.name = "neck";
    neck_shape.path = std::move(neck);
    neck_shape.paint = {Paint::of(colors.skin), Paint::of(colors.outline), style.stroke_px};
    layer.elements.push_back(std::move(neck_shape));

    const Point2 left_shoulder{left_edge, o.y + kShoulderInD * d};
    const Point2 right_shoulder{right_edge, o.y + kShoulderInD * d};
    Path shirt;
    shirt.move_to({left_edge, bottom})
        .arc({{left_edge, bottom}, left_shoulder})
        .arc({left_shoulder, at(-0.8, kCollarInD + 0.12), at(-kNeckHalfWidthInD * 1.2, kCollarInD)})
        .arc({at(-kNeckHalfWidthInD * 1.2, kCollarInD), at(-0.18, 0.5 * (kCollarInD + kCollarDipInD) + 0.05),
              at(0.0, kCollarDipInD)})
        .arc({at(0.0, kCollarDipInD), at(0.18, 0.5 * (kCollarInD + kCollarDipInD) + 0.05),
              at(kNeckHalfWidthInD * 1.2, kCollarInD)})
        .arc({at(kNeckHalfWidthInD * 1.2, kCollarInD), at(0.8, kCollarInD + 0.12), right_shoulder})
        .arc({right_shoulder, {right_edge, bottom}})
        .close();
    Shape shirt_shape;
    shirt_shape.name = "shirt";
    shirt_shape.path = std::move(shirt);
    shirt_shape.paint = {Paint::of(clothes), Paint::of(blend(clothes, Rgb{}, 0.4)), style.stroke_px};
    layer.elements.push_back(std::move(shirt_shape));
    return layer;
}

}  // namespace talkface::detail

// The clothes layer (thesis 6.3.1, Figures 6.7 and 6.8): a neck and shoulders under the head.
#include <algorithm>
#include <utility>
#include <vector>

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
constexpr double kShoulderHalfWidthInD = 2.1;  // the canvas keeps 2.2 d each side (face_canvas.cpp)
constexpr double kShoulderInD = 1.45;            // the shoulders' top
constexpr double kArmInD = 2.0;                  // the upper arm's outer side, where it meets the bottom

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
    // Without outlines, the neck is a shade of the skin, so that the chin stands out against it.
    const bool is_flat = style.look == FaceLook::flat;
    neck_shape.paint = is_flat ? ShapePaint{Paint::of(flat_skin_shade(colors)), Paint{}, 0.0}
                               : ShapePaint{Paint::of(colors.skin), Paint::of(colors.outline), style.stroke_px};
    layer.elements.push_back(std::move(neck_shape));

    // A bust: the shoulders round over into the upper arms, which fall to the bottom edge inside
    // the canvas, so the body ends in curves, not in cuts at the canvas's sides.
    auto side = [&](double sign, double dx_in_d, double dy_in_d) {
        return Point2{std::clamp(o.x + sign * dx_in_d * d, left_edge, right_edge), o.y + dy_in_d * d};
    };
    auto arm = [&](double sign) {
        // The point half-way up the arm keeps the curve's control points above the bottom edge.
        const double bottom_in_d = (bottom - o.y) / d;
        return std::vector<Point2>{side(sign, kArmInD, bottom_in_d),
                                   side(sign, kArmInD - 0.03, 0.5 * (kShoulderInD + 0.12 + bottom_in_d)),
                                   side(sign, kArmInD - 0.12, kShoulderInD + 0.12),
                                   side(sign, kArmInD - 0.45, kShoulderInD - 0.04)};
    };
    const std::vector<Point2> left_arm = arm(-1.0);
    std::vector<Point2> right_arm = arm(1.0);
    std::reverse(right_arm.begin(), right_arm.end());
    Path shirt;
    shirt.move_to(left_arm.front())
        .arc(left_arm)
        .arc({left_arm.back(), at(-0.8, kCollarInD + 0.1), at(-kNeckHalfWidthInD * 1.2, kCollarInD)})
        .arc({at(-kNeckHalfWidthInD * 1.2, kCollarInD), at(-0.18, 0.5 * (kCollarInD + kCollarDipInD) + 0.05),
              at(0.0, kCollarDipInD)})
        .arc({at(0.0, kCollarDipInD), at(0.18, 0.5 * (kCollarInD + kCollarDipInD) + 0.05),
              at(kNeckHalfWidthInD * 1.2, kCollarInD)})
        .arc({at(kNeckHalfWidthInD * 1.2, kCollarInD), at(0.8, kCollarInD + 0.1), right_arm.front()})
        .arc(right_arm)
        .close();
    Shape shirt_shape;
    shirt_shape.name = "shirt";
    shirt_shape.path = std::move(shirt);
    shirt_shape.paint = is_flat ? ShapePaint{Paint::of(clothes), Paint{}, 0.0}
                                : ShapePaint{Paint::of(clothes), Paint::of(blend(clothes, Rgb{}, 0.4)), style.stroke_px};
    layer.elements.push_back(std::move(shirt_shape));
    return layer;
}

}  // namespace talkface::detail

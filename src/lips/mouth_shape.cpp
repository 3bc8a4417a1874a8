// The 12 basic mouth shapes of thesis 5.2.2 and their control points (SPEC "Mouth shapes"); the
// whole mouth the control points make is the pose stage's (pose/mouth_controls.cpp).
#include "talkface/mouth_shape.hpp"

#include <algorithm>
#include <string>

#include "talkface/errors.hpp"

namespace talkface {
inline namespace v0 {

namespace {

constexpr const char* kShapeNames[] = {"m", "f", "h'", "h", "r", "z", "a", "i", "u", "e", "o", "n"};

Point2 moved(Point2 p, double dx, double dy) {
    return Point2{p.x + dx, p.y + dy};
}

}  // namespace

const std::array<MouthShape, 12>& all_mouth_shapes() {
    static const std::array<MouthShape, 12> shapes = {
        MouthShape::m, MouthShape::f, MouthShape::h_prime, MouthShape::h, MouthShape::r, MouthShape::z,
        MouthShape::a, MouthShape::i, MouthShape::u,       MouthShape::e, MouthShape::o, MouthShape::n};
    return shapes;
}

const char* mouth_shape_name(MouthShape shape) {
    const auto index = static_cast<std::size_t>(shape);
    if (index >= all_mouth_shapes().size()) {
        throw InvalidArgument("mouth shape", "no shape has the value " + std::to_string(index));
    }
    return kShapeNames[index];
}

MouthShape mouth_shape_from_name(std::string_view name) {
    if (name == "h_prime") return MouthShape::h_prime;
    for (MouthShape shape : all_mouth_shapes()) {
        if (name == mouth_shape_name(shape)) return shape;
    }
    throw InvalidArgument("mouth shape \"" + std::string(name) + "\"",
                          "unknown name; expected one of m, f, h' (or h_prime), h, r, z, a, i, u, e, o, n");
}

MouthControls mouth_controls(const FaceModel& neutral, MouthShape shape) {
    const MouthControls rest = neutral_mouth_controls(neutral);
    const double mns0 = neutral.fapu("MNS0");
    const double mw0 = neutral.fapu("MW0");
    const double upper_lip_h = neutral.fapu("UpperLipH");
    const double lower_lip_h = neutral.fapu("LowerLipH");

    // Every shape below is thesis 5.2.2 term by term: up = 8.9, dn = 8.2, lf = 8.4, rt = 8.3 of the
    // neutral face moved by FAPU multiples (image y grows downwards, so "- MNS0" raises a point).
    const auto opened = [&](double up_mns0, double down_mns0) {
        return MouthControls{moved(rest.up, 0.0, -up_mns0 * mns0), moved(rest.down, 0.0, down_mns0 * mns0),
                             rest.left, rest.right};
    };
    switch (shape) {
        case MouthShape::m:
            return rest;
        case MouthShape::f: {
            // 5.2.1: the lower lip tucks under the upper one.
            MouthControls c = rest;
            c.down = moved(rest.down, 0.0, -0.5 * lower_lip_h);
            return c;
        }
        case MouthShape::h_prime: {
            MouthControls c = opened(0.25, 0.3);
            c.left = moved(rest.left, 0.0, -0.1 * mns0);
            c.right = moved(rest.right, 0.0, -0.1 * mns0);
            return c;
        }
        case MouthShape::h: {
            MouthControls c = opened(0.25, 0.5);
            c.left = moved(rest.left, mw0 / 12.0, 0.1 * mns0);
            c.right = moved(rest.right, -mw0 / 12.0, 0.1 * mns0);
            return c;
        }
        case MouthShape::r: {
            MouthControls c = opened(0.25, 0.25);
            c.left = moved(rest.left, 0.15 * mw0, 0.0);
            c.right = moved(rest.right, -0.15 * mw0, 0.0);
            return c;
        }
        case MouthShape::z:
            return opened(0.15, 0.15);
        case MouthShape::a: {
            // SPEC fix: the corners move inward by MW0/8 as in 5.2.1; 5.2.2's 0.8 MW0 would cross them.
            MouthControls c = opened(0.3, 0.8);
            const double corner_y = (c.up.y + c.down.y) / 2.0 - upper_lip_h / 3.0;
            c.left = Point2{rest.left.x + mw0 / 8.0, corner_y};
            c.right = Point2{rest.right.x - mw0 / 8.0, corner_y};
            return c;
        }
        case MouthShape::i: {
            MouthControls c = opened(0.0, 1.0 / 6.0);
            c.left = moved(rest.left, -mw0 / 12.0, -upper_lip_h / 2.0);
            c.right = moved(rest.right, mw0 / 12.0, -upper_lip_h / 2.0);
            return c;
        }
        case MouthShape::u: {
            MouthControls c = opened(0.3, 0.3);
            c.left = moved(rest.left, 0.2 * mw0, 0.0);
            c.right = moved(rest.right, -0.2 * mw0, 0.0);
            return c;
        }
        case MouthShape::e: {
            MouthControls c = opened(0.0, 0.5);
            c.left = moved(rest.left, -mw0 / 12.0, -0.5 * upper_lip_h);
            c.right = moved(rest.right, mw0 / 12.0, -0.5 * upper_lip_h);
            return c;
        }
        case MouthShape::o: {
            MouthControls c = opened(0.25, 0.65);
            const double corner_y = (c.up.y + c.down.y) / 2.0;
            c.left = Point2{rest.left.x + 0.2 * mw0, corner_y};
            c.right = Point2{rest.right.x - 0.2 * mw0, corner_y};
            return c;
        }
        case MouthShape::n: {
            MouthControls c = opened(0.3, 0.4);
            c.left = moved(rest.left, 0.0, -upper_lip_h / 3.0);
            c.right = moved(rest.right, 0.0, -upper_lip_h / 3.0);
            return c;
        }
    }
    throw InvalidArgument("mouth shape", "no shape has the value " + std::to_string(static_cast<int>(shape)));
}

}  // namespace v0
}  // namespace talkface

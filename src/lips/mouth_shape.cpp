// The 12 basic mouth shapes of thesis 5.2.2 and the mouth they make (SPEC "Mouth shapes").
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

Point2 offset(Point2 to, Point2 from) {
    return Point2{to.x - from.x, to.y - from.y};
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

MouthControls neutral_mouth_controls(const FaceModel& neutral) {
    return MouthControls{neutral.point("8.9"), neutral.point("8.2"), neutral.point("8.4"),
                         neutral.point("8.3")};
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

FaceModel apply_mouth(const FaceModel& neutral, const MouthControls& controls) {
    const MouthControls rest = neutral_mouth_controls(neutral);
    FaceModel face = neutral;
    face.set_point("8.9", controls.up);
    face.set_point("8.2", controls.down);
    face.set_point("8.4", controls.left);
    face.set_point("8.3", controls.right);

    // The thesis draws the upper lip as arc(8.1, 8.9, 8.4) and arc(8.3, 8.10, 8.1) but moves only 8.9
    // (2.2: the control points "by which other mouth feature points are computed", not saying how).
    // Moving 8.1 and 8.10 rigidly with 8.9 keeps the upper lip's thickness (UpperLipH) and its two peaks
    // level.
    const Point2 up_offset = offset(controls.up, rest.up);
    for (const char* id : {"8.1", "8.10"}) {
        face.set_point(id, moved(neutral.point(id), up_offset.x, up_offset.y));
    }

    // The inner lips (thesis silent): the upper one rides on the upper lip, the lower one on the lower
    // lip, so each lip keeps its thickness; both stay on the mouth's centre line between the corners.
    // Shape f lifts 8.2 by half the lower lip, which would put 2.3 above 2.2: the lower lip then tucks
    // behind the upper one, so the lips stay closed (2.3 = 2.2) instead of passing through each other.
    const double centre_dx = (controls.left.x + controls.right.x) / 2.0 - (rest.left.x + rest.right.x) / 2.0;
    const Point2 inner_upper = moved(neutral.point("2.2"), centre_dx, up_offset.y);
    const Point2 inner_lower_free = moved(neutral.point("2.3"), centre_dx, controls.down.y - rest.down.y);
    face.set_point("2.2", inner_upper);
    face.set_point("2.3", Point2{inner_lower_free.x, std::max(inner_lower_free.y, inner_upper.y)});

    // Thesis 5.2.2: the jaw point moves with 8.2.
    face.set_point("2.1", Point2{controls.down.x, controls.down.y + neutral.fapu("JawH")});
    return face;
}

}  // namespace v0
}  // namespace talkface

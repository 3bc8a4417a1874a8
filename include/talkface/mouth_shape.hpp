// talkface: the 12 basic mouth shapes of thesis 5.2.2 (SPEC "Mouth shapes").
#ifndef TALKFACE_MOUTH_SHAPE_HPP
#define TALKFACE_MOUTH_SHAPE_HPP

#include <array>
#include <cstddef>
#include <string_view>

#include "talkface/export.h"
#include "talkface/face_model.hpp"
#include "talkface/types.hpp"

namespace talkface {
inline namespace v0 {

/// The 12 basic mouth shapes. Six for initials (m, f, h', h, r, z), six for finals (a, i, u, e, o, n).
/// The numeric values are stable within a major version (the C ABI uses them).
enum class MouthShape : int { m = 0, f, h_prime, h, r, z, a, i, u, e, o, n };

/// All 12 shapes, in enum order.
TALKFACE_API const std::array<MouthShape, 12>& all_mouth_shapes();
/// The thesis's name: "m", "f", "h'", "h", "r", "z", "a", "i", "u", "e", "o", "n".
TALKFACE_API const char* mouth_shape_name(MouthShape shape);
/// Parses a name as mouth_shape_name() writes it ("h_prime" is accepted for "h'").
/// \throws talkface::InvalidArgument listing the valid names.
TALKFACE_API MouthShape mouth_shape_from_name(std::string_view name);

/// The four mouth control points: up = 8.9, down = 8.2, left = 8.4, right = 8.3 (image pixels).
/// Key frames interpolate these; apply_mouth() turns them into a whole mouth.
struct MouthControls {
    Point2 up;
    Point2 down;
    Point2 left;
    Point2 right;
    friend bool operator==(const MouthControls& a, const MouthControls& b) {
        return a.up == b.up && a.down == b.down && a.left == b.left && a.right == b.right;
    }
    friend bool operator!=(const MouthControls& a, const MouthControls& b) { return !(a == b); }
};

/// The control points of the neutral face (shape m is this).
TALKFACE_API MouthControls neutral_mouth_controls(const FaceModel& neutral);

/// A shape's control points: thesis 5.2.2's formulas in FAPU multiples of the neutral face (SPEC fix:
/// shape a moves its corners inward by MW0/8). A pure function.
TALKFACE_API MouthControls mouth_controls(const FaceModel& neutral, MouthShape shape);

/// The face with its mouth set to `controls`: 8.9, 8.2, 8.4, 8.3 placed; 8.1 and 8.10 follow 8.9,
/// the inner lips 2.2 and 2.3 follow the upper and lower lip (never passing through each other);
/// the jaw 2.1 = (8.2.x, 8.2.y + JawH) (thesis 5.2.2). A pure function.
TALKFACE_API FaceModel apply_mouth(const FaceModel& neutral, const MouthControls& controls);

}  // namespace v0
}  // namespace talkface

#endif

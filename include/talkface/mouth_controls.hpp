// talkface: the mouth's four control points and the whole mouth they make (thesis 5.2.2; SPEC
// "Mouth shapes"). The pose stage draws a face from them; the 12 shapes (mouth_shape.hpp) set them.
#ifndef TALKFACE_MOUTH_CONTROLS_HPP
#define TALKFACE_MOUTH_CONTROLS_HPP

#include "talkface/export.h"
#include "talkface/face_model.hpp"
#include "talkface/types.hpp"

namespace talkface {
inline namespace v0 {

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

/// The face with its mouth set to `controls`: 8.9, 8.2, 8.4, 8.3 placed; 8.1 and 8.10 follow 8.9,
/// the inner lips 2.2 and 2.3 follow the upper and lower lip (never passing through each other);
/// the jaw 2.1 = (8.2.x, 8.2.y + JawH) (thesis 5.2.2). A pure function.
TALKFACE_API FaceModel apply_mouth(const FaceModel& neutral, const MouthControls& controls);

}  // namespace v0
}  // namespace talkface

#endif

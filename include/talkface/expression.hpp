// talkface: the basic facial expressions of thesis 2.4.2: blink, smile with squint, eyebrow raise.
#ifndef TALKFACE_EXPRESSION_HPP
#define TALKFACE_EXPRESSION_HPP

#include "talkface/export.h"
#include "talkface/face_model.hpp"

namespace talkface {
inline namespace v0 {

/// Amounts in 0..1, combinable. 0 everywhere is the neutral face.
struct Expression {
    double blink_left = 0.0;   ///< image-left eye (3.2, 3.4): 1 = closed
    double blink_right = 0.0;  ///< image-right eye (3.1, 3.3): 1 = closed
    double smile = 0.0;        ///< mouth corners up by UpperLipH, lower lids up (squint)
    double brows = 0.0;        ///< eyebrows up by EyebrowH
    friend bool operator==(const Expression& a, const Expression& b) {
        return a.blink_left == b.blink_left && a.blink_right == b.blink_right && a.smile == b.smile &&
               a.brows == b.brows;
    }
    friend bool operator!=(const Expression& a, const Expression& b) { return !(a == b); }
};

/// The face with the expression applied (a pure function of the face and the amounts).
/// \throws talkface::InvalidArgument naming the amount if one is outside 0..1 or not finite.
TALKFACE_API FaceModel apply_expression(const FaceModel& face, const Expression& expression);

}  // namespace v0
}  // namespace talkface

#endif

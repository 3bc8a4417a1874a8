// talkface: the 12 basic mouth shapes of thesis 5.2.2 (SPEC "Mouth shapes").
#ifndef TALKFACE_MOUTH_SHAPE_HPP
#define TALKFACE_MOUTH_SHAPE_HPP

#include <array>
#include <cstddef>
#include <string_view>

#include "talkface/export.h"
#include "talkface/face_model.hpp"
#include "talkface/mouth_controls.hpp"

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

/// A shape's control points: thesis 5.2.2's formulas in FAPU multiples of the neutral face (SPEC fix:
/// shape a moves its corners inward by MW0/8). A pure function.
TALKFACE_API MouthControls mouth_controls(const FaceModel& neutral, MouthShape shape);

}  // namespace v0
}  // namespace talkface

#endif

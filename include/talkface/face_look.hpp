// talkface: FaceLook, the drawing style of a face (the same points, shapes and motion, drawn two ways).
#ifndef TALKFACE_FACE_LOOK_HPP
#define TALKFACE_FACE_LOOK_HPP

#include <string_view>

#include "talkface/export.h"

namespace talkface {
inline namespace v0 {

/// How a face's shapes are painted. The numeric values are stable within a major version (the C ABI
/// uses them).
enum class FaceLook : int {
    /// The thesis's cartoon (Figure 2.10): filled shapes with dark outlines. The default.
    outlined = 0,
    /// No outlines: flat fills told apart by colour, a soft shade down the nose, darker ears and neck
    /// so that they stand apart from the face, and a flat iris.
    flat = 1,
};

/// "outlined" or "flat".
TALKFACE_API const char* face_look_name(FaceLook look);
/// Parses a name as face_look_name() writes it.
/// \throws talkface::InvalidArgument listing the valid names.
TALKFACE_API FaceLook face_look_from_name(std::string_view name);

}  // namespace v0
}  // namespace talkface

#endif

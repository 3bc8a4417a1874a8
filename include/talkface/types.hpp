// talkface: small value types that cross the public API.
//
// Geometry crosses as these plain types (not Eigen), so a caller's compiler flags never reach our
// ABI. Image coordinates are pixels with y pointing down; "left" is the left of the image (the
// subject's right).
#ifndef TALKFACE_TYPES_HPP
#define TALKFACE_TYPES_HPP

#include <cstdint>
#include <string>
#include <string_view>

#include "talkface/export.h"

namespace talkface {
inline namespace v0 {

/// A point in the image plane, pixels, y down.
struct Point2 {
    double x = 0.0;
    double y = 0.0;
    friend bool operator==(const Point2& a, const Point2& b) { return a.x == b.x && a.y == b.y; }
    friend bool operator!=(const Point2& a, const Point2& b) { return !(a == b); }
};

/// A point in a face's local 3D frame (thesis 2.3): pixels, x towards the image left, y up, z out of
/// the screen towards the viewer, origin at the rotation origin O (the neck).
struct Point3 {
    double x = 0.0;
    double y = 0.0;
    double z = 0.0;
    friend bool operator==(const Point3& a, const Point3& b) {
        return a.x == b.x && a.y == b.y && a.z == b.z;
    }
    friend bool operator!=(const Point3& a, const Point3& b) { return !(a == b); }
};

/// An sRGB colour.
struct Rgb {
    std::uint8_t r = 0;
    std::uint8_t g = 0;
    std::uint8_t b = 0;
    friend bool operator==(const Rgb& a, const Rgb& c) { return a.r == c.r && a.g == c.g && a.b == c.b; }
    friend bool operator!=(const Rgb& a, const Rgb& c) { return !(a == c); }
};

/// "#rrggbb" (lower case) for a colour.
TALKFACE_API std::string to_hex(Rgb colour);
/// Parses "#rrggbb" or "#rgb" (either case).
/// \throws talkface::InvalidArgument naming `parameter` if the text is not such a colour.
TALKFACE_API Rgb rgb_from_hex(std::string_view text, const std::string& parameter = "colour");

}  // namespace v0
}  // namespace talkface

#endif

// The ease every movement of the face uses: the expression events' envelopes and the mouth's frames.
#ifndef TALKFACE_COMMON_EASING_HPP
#define TALKFACE_COMMON_EASING_HPP

#include <algorithm>
#include <cmath>

namespace talkface::detail {

// Cosine ease in and out: 0 at 0, 1 at 1, zero slope at both ends, so a movement starts and stops
// without a jerk; clamped outside [0, 1].
inline double ease_in_out(double fraction) {
    const double u = std::clamp(fraction, 0.0, 1.0);
    return 0.5 - 0.5 * std::cos(u * 3.14159265358979323846);
}

}  // namespace talkface::detail

#endif

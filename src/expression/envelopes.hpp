// How an event's amount rises and falls over its span (documented with ExpressionEvent).
#ifndef TALKFACE_EXPRESSION_ENVELOPES_HPP
#define TALKFACE_EXPRESSION_ENVELOPES_HPP

#include "common/easing.hpp"

namespace talkface::detail {

// Blink lids over the event, 0..1: closing in the first 30%, reopening over the other 70% (the
// lid falls faster than it rises: VanderWerf et al. 2003).
inline double blink_envelope(double fraction) {
    constexpr double kClosing = 0.3;
    if (fraction <= 0.0 || fraction >= 1.0) return 0.0;
    if (fraction < kClosing) return ease_in_out(fraction / kClosing);
    return 1.0 - ease_in_out((fraction - kClosing) / (1.0 - kClosing));
}

// Eyebrow raise over the event, 0..1: up in the first 30%, held, down in the last 30% (thesis 4.2
// counts the raise and the lowering inside one event).
inline double brows_envelope(double fraction) {
    constexpr double kEdge = 0.3;
    if (fraction <= 0.0 || fraction >= 1.0) return 0.0;
    if (fraction < kEdge) return ease_in_out(fraction / kEdge);
    if (fraction > 1.0 - kEdge) return ease_in_out((1.0 - fraction) / kEdge);
    return 1.0;
}

}  // namespace talkface::detail

#endif

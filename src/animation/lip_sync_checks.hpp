// Checks on LipSyncOptions shared by the lip-movement functions.
#ifndef TALKFACE_ANIMATION_LIP_SYNC_CHECKS_HPP
#define TALKFACE_ANIMATION_LIP_SYNC_CHECKS_HPP

#include "talkface/lip_sync.hpp"

namespace talkface::detail {

// Throws InvalidArgument naming the option that is not finite or out of range.
void check_lip_sync_options(const LipSyncOptions& options);

// Whether a shape shows closed lips: m (b p m, and the neutral mouth) or f.
inline bool is_closed_mouth(MouthShape shape) {
    return shape == MouthShape::m || shape == MouthShape::f;
}

}  // namespace talkface::detail

#endif

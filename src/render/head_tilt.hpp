// The head's tilt in the keyframes encoding: one SMIL rotate for the whole head instead of every
// point moving with it.
//
// SPEC "Pose": R = Rz(gamma) Rx(alpha) Ry(beta), then an orthographic projection onto the X-Y
// plane. The tilt comes last and turns about the view axis, so it turns the projected face about
// O as a whole (local and image coordinates differ by a half turn, x and y both negated, which
// commutes with it). The hair and face groups are turned by the tilt, and their layers are drawn
// turned back by it (layers.hpp: ViewMap): whatever moves only with the tilt holds still in its
// own path data. The pupils are the exception: the gaze holds a focus that does not turn with the
// head. Nothing relies on the exception being small: the layers' key frames are chosen from what
// is drawn in the group, at the angle the group shows at each frame, so every frame is matched
// within the tolerance whatever the group's rotation leaves over.
#ifndef TALKFACE_RENDER_HEAD_TILT_HPP
#define TALKFACE_RENDER_HEAD_TILT_HPP

#include <string>
#include <vector>

#include "render/key_frames.hpp"
#include "render/layers.hpp"
#include "talkface/animation.hpp"
#include "talkface/types.hpp"

namespace talkface::detail {

// The head's layers are drawn in tenths of a pixel under a scale(.1), so that their animated
// values are whole numbers: no decimal point to write.
inline constexpr double kHeadUnitsPerPx = 10.0;

struct HeadTilt {
    Point2 origin;                  // O in image pixels, as written (rounded)
    std::vector<double> angle_deg;  // per frame: the angle the groups show at that frame
    double held_angle_deg = 0.0;    // the angle of a tilt that never changes (a fixed rotate)
    std::string animation;          // the groups' <animateTransform>, empty when the tilt is held
    KeyFrames keys;                 // the angle's key frames (frames, degrees); none when held
};

// The tilt of every frame of `animation` as key frames of an angle, within `tolerance_px` of every
// frame at `reach_px` from O (the farthest a drawn point can be). What the interpolated angle
// leaves over is drawn, not lost: keep the share small so that rigid outlines hold still.
HeadTilt plan_head_tilt(const Animation& animation, Point2 origin, double reach_px, double tolerance_px);

// plan_head_tilt() for a head drawn on `canvas` (which holds the face at every pose: its farthest
// corner from O is the reach) taking its share of an animation's `tolerance_px`.
HeadTilt plan_head_tilt_on_canvas(const Animation& animation, Point2 origin, const CanvasBox& canvas,
                                  double tolerance_px);

// The start tag of a head group, `<g id="ID" transform="...">`, with the tilt's animation.
std::string open_head_group(const HeadTilt& tilt, const char* id);

}  // namespace talkface::detail

#endif

// Outlines that move as a whole, in the keyframes encoding.
//
// A turn or a nod moves each feature mostly as a whole: its points shift with their depth (SPEC
// "Pose": rotation and orthographic projection; the tilt is the head groups' own). So an outline can
// be written as its points about their mean, under an animated translate that carries the mean: two
// numbers a key frame for the motion, and the outline's own key frames only where its shape changes
// beyond its share of the tolerance (the jaw opens, a lid closes, a brow rises, the turn bends it).
// The encoder keeps this or the plain animation, whichever is shorter. (A full affine map per
// outline was tried before: its four transform animations, each with its own key times, cost more
// than they saved. One affine map for the whole head, the turn's and nod's linear part, saves
// nothing either: what is left is each point's own depth.)
#ifndef TALKFACE_RENDER_OUTLINE_MOTION_HPP
#define TALKFACE_RENDER_OUTLINE_MOTION_HPP

#include <cstddef>
#include <functional>
#include <string>

#include "render/attribute_animation.hpp"
#include "render/key_frames.hpp"

namespace talkface::detail {

struct MovedOutline {
    double centre_x = 0.0, centre_y = 0.0;  // the mean of the first frame's points
    Track offset;                           // the mean of each frame's points less the centre
    Track outline;                          // each frame's points less their mean
};

// A track of points (x, y, x, y ...) as its mean's motion and its shape about the mean.
MovedOutline split_motion(const Track& track, std::size_t frame_count);

// The outline of the first frame about its mean as the attribute's value, the static translate to
// the mean, and the animations of the translate and (where its shape changes) of the outline.
struct MovedText {
    std::string value;       // the attribute's value
    std::string attributes;  // ` transform="translate(X Y)"`, right after it
    std::string animations;  // inside the element
};

// `shown`, when not null, receives the points the element shows at each frame (the translate's
// numbers as written, the outline's before their rounding).
MovedText moved_outline_text(const MovedOutline& moved, const TrackForm& form, std::size_t frame_count,
                             double duration_s, double tolerance, Track* shown = nullptr);

// What a pose adds to an outline (`moved`: split_motion() of the addition) as two additive
// animations with `extra` attributes (` class="tf-pose" additive="sum"`): the addition about its
// mean, its values written by `values_of` (the commands of the value it is added to), and a
// translate carrying the mean. Within `tolerance` of every frame, the values' rounding left over.
std::string added_outline_text(const MovedOutline& moved, const TrackForm& form, const PathLayout& layout,
                               std::size_t frame_count, double duration_s, double tolerance,
                               const std::string& extra,
                               const std::function<std::string(const KeyFrames&)>& values_of);

}  // namespace talkface::detail

#endif

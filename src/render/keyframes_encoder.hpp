// The keyframes encoding of one layer (thesis 6.3.2, the default encoding): the first frame's layer
// written once, with an SMIL <animate> for every numeric attribute that changes, its key frames
// chosen from every frame's numbers (key_frames.hpp). The frames are drawing models (drawing.hpp)
// with the same elements and the same path verbs, only other numbers: the layers draw a fixed
// number of points at every pose (contour substitution changes which points, not how many). A frame
// that breaks this is a bug, reported as one.
#ifndef TALKFACE_RENDER_KEYFRAMES_ENCODER_HPP
#define TALKFACE_RENDER_KEYFRAMES_ENCODER_HPP

#include <cstddef>
#include <string>
#include <vector>

#include "render/drawing.hpp"
#include "render/key_frames.hpp"
#include "render/path_compaction.hpp"
#include "render/svg_writer.hpp"
#include "talkface/svg_animator.hpp"

namespace talkface::detail {

class KeyframesEncoder {
public:
    // `tolerance`: SvgAnimationOptions::tolerance_px in the drawing's units; `decimals`: the digits
    // the layer is written with, which its numbers are rounded to as the document shows them;
    // `expected_frames`: how many frames will come, so that each moving attribute's numbers are
    // allocated once instead of copied as they grow.
    KeyframesEncoder(double fps, double tolerance, int decimals, std::size_t expected_frames);

    // The next frame's layer. Only the numbers of attributes that change are kept.
    // \throws talkface::Error (internal) if it has other elements or path verbs than the first.
    void add(const Layer& layer);

    // The next frame is the same as the one before.
    void add_repeat();

    // The layer's content; progress goes from `from` to `to` as the attributes are written.
    std::string finish(const ProgressCallback& progress, double from, double to) const;

    // The layer's content as finish() writes it, this encoder having had the layers with the head
    // at rest, and in each element that `posed` (the same frames with the head's pose) draws
    // otherwise, an additive animation (class "tf-pose") of what the pose adds to what the element
    // shows: with those animations the element is within the tolerance of `posed`'s frames, without
    // them it is what finish() shows. (Chromium, Firefox and WebKit add path data whose commands
    // match, as these do.)
    // \throws talkface::Error (internal) if `posed` had other frames, elements or path verbs.
    std::string finish_with_pose(const KeyframesEncoder& posed, const ProgressCallback& progress, double from,
                                 double to) const;

private:
    struct Slot {
        std::vector<PathVerb> verbs;  // path data: the first frame's
        TrackRecorder numbers;        // as written
    };

    // An attribute as written, and what it shows at each frame.
    struct WrittenAttribute {
        AttributeOverride text;
        Track shown;               // every frame, once `want_shown`
        bool is_relative = false;  // path data written relative, with `layout`; else as the model writes it
        PathLayout layout;
        double rounding = 0.0;  // how far the values as written may stray from `shown`
    };
    WrittenAttribute write_attribute(std::size_t slot, double duration_s, bool want_shown) const;
    // The additive animation of `added` (every frame) to attribute `slot` written as `written`.
    std::string pose_animation(std::size_t slot, const WrittenAttribute& written, const Track& added,
                               double duration_s) const;

    double fps_;
    double tolerance_;
    int decimals_;
    std::size_t expected_frames_;
    std::size_t frame_count_ = 0;
    Layer first_;
    std::vector<NumericAttribute> first_attributes_;
    std::vector<Slot> slots_;
    // Reused from frame to frame.
    std::vector<NumericAttribute> attributes_;
    std::vector<double> numbers_;
};

}  // namespace talkface::detail

#endif

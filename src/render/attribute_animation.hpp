// One numeric attribute's SMIL animation in the keyframes encoding: its key frames' values as
// text and the <animate> element that plays them.
#ifndef TALKFACE_RENDER_ATTRIBUTE_ANIMATION_HPP
#define TALKFACE_RENDER_ATTRIBUTE_ANIMATION_HPP

#include <cstddef>
#include <string>
#include <vector>

#include "render/drawing.hpp"
#include "render/key_frames.hpp"
#include "render/path_compaction.hpp"

namespace talkface::detail {

// What a track's numbers draw: the attribute and, for path data, the path's verbs.
struct TrackForm {
    AttributeKind kind = AttributeKind::number;
    const char* name = "";
    const std::vector<PathVerb>* verbs = nullptr;  // path_data
};

// The layout of a path track (path_compaction.hpp); empty for other attributes.
PathLayout layout_of(const TrackForm& form, const Track& track, std::size_t frame_count);

// The values of an attribute over its key frames, separated by ";": path data relative (with
// `layout`, which says which control points are left implicit), other numbers as they are.
std::string key_values(const TrackForm& form, const PathLayout& layout, const KeyFrames& keys);

// Key frames of `track` (drawn with `layout`) within `tolerance` (drawing units) of every one of
// `frame_count` frames, the layout's chain rounding taken from it.
KeyFrames attribute_key_frames(const Track& track, const PathLayout& layout, std::size_t frame_count,
                               double tolerance);

// The <animate> of `track` over `frame_count` frames lasting `duration_s`, its key frames within
// `tolerance` (drawing units) of every frame. `shown`, when not null, receives what it shows at each
// frame (before the values' rounding).
std::string animate_element(const TrackForm& form, const Track& track, std::size_t frame_count,
                            double duration_s, double tolerance, Track* shown = nullptr);

}  // namespace talkface::detail

#endif

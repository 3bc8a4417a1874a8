#include "render/attribute_animation.hpp"

#include "render/svg_text.hpp"

namespace talkface::detail {

PathLayout layout_of(const TrackForm& form, const Track& track, std::size_t frame_count) {
    return form.kind == AttributeKind::path_data ? path_layout(*form.verbs, track, frame_count) : PathLayout();
}

// The values of an attribute over its key frames: path data relative (with `layout`, which says
// which control points are left implicit), other point lists as they are.
std::string key_values(const TrackForm& form, const PathLayout& layout, const KeyFrames& keys) {
    const bool is_path = form.kind == AttributeKind::path_data;
    std::string values;
    for (std::size_t i = 0; i < keys.positions.size(); ++i) {
        if (i > 0) values += ';';
        values += is_path ? relative_path_value(keys.values, layout, i) : track_value(keys.values, i);
    }
    return values;
}

KeyFrames attribute_key_frames(const Track& track, const PathLayout& layout, std::size_t frame_count,
                               double tolerance) {
    return choose_key_frames(track, frame_count,
                             std::vector<double>(track.width, tolerance - chain_rounding(layout)));
}

std::string animate_element(const TrackForm& form, const Track& track, std::size_t frame_count,
                            double duration_s, double tolerance, Track* shown) {
    const PathLayout layout = layout_of(form, track, frame_count);
    const KeyFrames keys = attribute_key_frames(track, layout, frame_count, tolerance);
    if (shown != nullptr) *shown = interpolated(keys, frame_count);
    return "<animate attributeName=\"" + std::string(form.name) + "\"" +
           attribute("dur", clock_value(duration_s)) + attribute("values", key_values(form, layout, keys)) +
           attribute("keyTimes", key_times_of(keys, frame_count)) + " fill=\"freeze\"/>";
}

}  // namespace talkface::detail

// Path data of the keyframes encoding made short: relative commands between rounded coordinates,
// control points left to S and T commands where every frame has them as reflections, repeated
// command letters left out. The key frames' values of a path track are written this way.
#ifndef TALKFACE_RENDER_PATH_COMPACTION_HPP
#define TALKFACE_RENDER_PATH_COMPACTION_HPP

#include <cstddef>
#include <string>
#include <vector>

#include "render/drawing.hpp"
#include "render/head_tilt.hpp"
#include "render/key_frames.hpp"

namespace talkface::detail {

// The head's layers are drawn in tenths of a pixel (head_tilt.hpp), and animated values are written
// rounded to whole tenths: 0.05 px of rounding on top of the tolerance, far below what shows. Every
// length of the keyframes encoding is in these units.
inline constexpr double kUnitsPerPx = kHeadUnitsPerPx;

// Where each point of a path track stands: its command and its place in the command's segment.
struct PathPoint {
    char command = 'M';  // M, L, C or Q
    int place = 0;       // 0 .. 2 in a C segment (c1, c2, end), 0 .. 1 in a Q, else 0
    // The first control point of a segment that is the previous one's last control point reflected
    // through the pen, left to an S (after a C) or a T (after a Q).
    bool is_implied_control = false;
    bool closes_before = false;  // a close comes before this point
};

struct PathLayout {
    std::vector<PathPoint> points;
    bool ends_closed = false;  // the path ends with a close
};

// The layout of a path track drawn with `verbs`, with every control point that is the previous
// one reflected through the pen in every frame marked to be left implicit.
PathLayout path_layout(const std::vector<PathVerb>& verbs, const Track& track, std::size_t frame_count);

// What the layout's implied controls add to the rounding of its points (in drawing units).
double chain_rounding(const PathLayout& layout);

// Frame (or key) `frame` of `track` as relative path data ("M12 34c1 2 3 4 5 6s...z").
std::string relative_path_value(const Track& track, const PathLayout& layout, std::size_t frame);

// Frame `frame` of a track of other numbers, rounded to whole units: "12" or "1,2 3,4" (a polyline).
std::string track_value(const Track& track, std::size_t frame);

}  // namespace talkface::detail

#endif

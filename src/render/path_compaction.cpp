#include "render/path_compaction.hpp"

#include <cmath>
#include <string>
#include <vector>

namespace talkface::detail {

namespace {

void append_whole(std::string& text, long value) {
    // A minus sign separates numbers by itself in SVG's number lists and path data.
    if (!text.empty() && value >= 0) {
        const char last = text.back();
        if (last >= '0' && last <= '9') text += ' ';
    }
    text += std::to_string(value);
}

std::vector<long> rounded_values(const Track& track, std::size_t frame) {
    std::vector<long> values(track.width);
    for (std::size_t k = 0; k < track.width; ++k) {
        values[k] = std::lround(static_cast<double>(track.numbers[frame * track.width + k]));
    }
    return values;
}

int points_per_segment(char command) {
    return command == 'C' ? 3 : command == 'Q' ? 2 : 1;
}

char command_letter(PathVerb verb) {
    switch (verb) {
        case PathVerb::move: return 'M';
        case PathVerb::line: return 'L';
        case PathVerb::cubic: return 'C';
        case PathVerb::quadratic: return 'Q';
        case PathVerb::close: return 'Z';
    }
    return 'M';
}

// The largest gap between a control point and the reflection of the previous one for which it is
// left to an S or T command: the frames' own rounding (three coordinates at 0.005 px), no more.
constexpr double kReflectionGap = 0.02 * kUnitsPerPx;

// A T's control point is the previous control reflected through the pen, and that one may be a T's
// too: rounding would add up along the chain. So the end point before a T is rounded to where it
// makes the T's control nearest to the frame's, which keeps that control within 0.1 px (a grid step)
// of the interpolated frame's, and the end point itself within 0.11 px: 0.06 px more than rounding to
// the nearest tenth, which the key frames of such a path leave over from the tolerance.
constexpr double kChainRounding = 0.06 * kUnitsPerPx;

}  // namespace

// The layout of a path track, with every control point that is the previous one reflected through
// the pen in every frame marked to be left implicit. The joins of a Catmull-Rom arc are such (S: a
// third fewer numbers), and so is every join of a corner-cut outline, the quadratic B-spline of a
// polygon (T: half the numbers): the pen is the middle of an edge, the controls its two corners.
PathLayout path_layout(const std::vector<PathVerb>& verbs, const Track& track, std::size_t frame_count) {
    PathLayout layout;
    layout.points.reserve(track.width / 2);
    bool is_closing = false;
    for (const PathVerb verb : verbs) {
        if (verb == PathVerb::close) {
            is_closing = true;
            continue;
        }
        for (int place = 0; place < points_of(verb); ++place) {
            PathPoint point;
            point.command = command_letter(verb);
            point.place = place;
            point.closes_before = is_closing;
            is_closing = false;
            layout.points.push_back(point);
        }
    }
    layout.ends_closed = is_closing;
    std::vector<PathPoint>& points = layout.points;
    for (std::size_t j = 2; j < points.size(); ++j) {
        const char segment_command = points[j].command;
        const bool is_curve = segment_command == 'C' || segment_command == 'Q';
        const bool follows_same_curve = points[j - 1].command == segment_command &&
                                        points[j - 1].place + 1 == points_per_segment(segment_command);
        if (!is_curve || points[j].place != 0 || !follows_same_curve || points[j].closes_before) continue;
        bool is_reflection = true;
        for (std::size_t frame = 0; frame < frame_count && is_reflection; ++frame) {
            const float* n = track.numbers.data() + frame * track.width;
            for (std::size_t axis = 0; axis < 2; ++axis) {
                const double reflected = 2.0 * n[2 * (j - 1) + axis] - n[2 * (j - 2) + axis];
                is_reflection = is_reflection && std::abs(n[2 * j + axis] - reflected) <= kReflectionGap;
            }
        }
        points[j].is_implied_control = is_reflection;
    }
    return layout;
}

double chain_rounding(const PathLayout& layout) {
    for (const PathPoint& point : layout.points) {
        if (point.is_implied_control && point.command == 'Q') return kChainRounding;
    }
    return 0.0;
}

// Path data with relative commands: the same shape in fewer bytes (small offsets instead of full
// coordinates), and interpolating offsets is interpolating coordinates, since the map between them
// is linear. Offsets are taken between rounded coordinates, so rounding never accumulates along the
// path. A c1 left to an S is interpolated as the reflection of interpolated points, which is the
// interpolated reflection: it strays no further than the points it is made of (three of them, so
// three times their rounding), or for a T, than the chain's rounding allows (kChainRounding).
std::string relative_path_value(const Track& track, const PathLayout& path, std::size_t frame) {
    const std::vector<PathPoint>& layout = path.points;
    std::vector<long> rounded = rounded_values(track, frame);
    const float* exact = track.numbers.data() + frame * track.width;
    std::string text;
    long current_x = 0, current_y = 0, start_x = 0, start_y = 0;
    long reference_x = 0, reference_y = 0;
    long control_x = 0, control_y = 0;  // the last quadratic control point, as drawn
    // SVG repeats a command for as many numbers as follow it: a letter like the one before (other
    // than a move, whose repeats draw lines) is left out.
    char last_command = 'z';
    auto write_command = [&](char command) {
        if (command != last_command || command == 'M' || command == 'm' || command == 'z') text += command;
        last_command = command;
    };
    for (std::size_t j = 0; j < layout.size(); ++j) {
        const PathPoint& point = layout[j];
        if (point.closes_before) {
            write_command('z');
            current_x = start_x;
            current_y = start_y;
        }
        if (point.is_implied_control) {
            write_command(point.command == 'C' ? 's' : 't');
            control_x = 2 * current_x - control_x;
            control_y = 2 * current_y - control_y;
            continue;
        }
        const bool starts_command = point.place == 0 && !(j > 0 && layout[j - 1].is_implied_control);
        if (starts_command) write_command(j == 0 ? 'M' : static_cast<char>(point.command - 'A' + 'a'));
        // Every point of a curve segment is relative to where the segment starts (SVG "c", "s", "q", "t").
        if (point.place == 0 || (point.place == 1 && layout[j - 1].is_implied_control)) {
            reference_x = j == 0 ? 0 : current_x;
            reference_y = j == 0 ? 0 : current_y;
        }
        if (point.command == 'Q' && point.place == 0) {
            control_x = rounded[2 * j];
            control_y = rounded[2 * j + 1];
        }
        if (point.command == 'Q' && point.place == 1 && j + 1 < layout.size() &&
            layout[j + 1].is_implied_control) {
            rounded[2 * j] = std::lround((static_cast<double>(control_x) + exact[2 * j + 2]) / 2.0);
            rounded[2 * j + 1] = std::lround((static_cast<double>(control_y) + exact[2 * j + 3]) / 2.0);
        }
        const long x = rounded[2 * j];
        const long y = rounded[2 * j + 1];
        append_whole(text, x - reference_x);
        append_whole(text, y - reference_y);
        if (point.place + 1 == points_per_segment(point.command)) {
            current_x = x;
            current_y = y;
            if (point.command == 'M') {
                start_x = x;
                start_y = y;
            }
        }
    }
    if (path.ends_closed) text += 'z';
    return text;
}

std::string track_value(const Track& track, std::size_t frame) {
    const std::vector<long> values = rounded_values(track, frame);
    std::string text;
    for (std::size_t k = 0; k < track.width; ++k) {
        if (k > 0) text += k % 2 == 1 ? ',' : ' ';
        text += std::to_string(values[k]);
    }
    return text;
}

}  // namespace talkface::detail

#include "render/head_tilt.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>

#include "common/number_format.hpp"
#include "render/key_frames.hpp"
#include "render/svg_text.hpp"

namespace talkface::detail {

namespace {

constexpr double kDegreesPerRadian = 180.0 / 3.14159265358979323846;
// Angles are written with this many decimals: 0.0005 degrees is 0.003 px at 300 px from O.
constexpr int kAngleDecimals = 3;
constexpr int kOriginDecimals = 2;
// key_times_of() writes key times with 6 decimals: the groups turn at those times.
constexpr double kKeyTimeScale = 1e6;

}  // namespace

HeadTilt plan_head_tilt(const Animation& animation, Point2 origin, double reach_px, double tolerance_px) {
    const std::size_t frame_count = animation.frames.size();
    HeadTilt tilt;
    tilt.origin = {rounded(origin.x, kOriginDecimals), rounded(origin.y, kOriginDecimals)};
    Track angles;
    angles.width = 1;
    angles.numbers.reserve(frame_count);
    bool is_held = true;
    for (const FaceState& state : animation.frames) {
        angles.numbers.push_back(static_cast<float>(state.pose.gamma_deg));
        is_held = is_held && state.pose.gamma_deg == animation.frames.front().pose.gamma_deg;
    }
    if (is_held) {
        // Written as a fixed rotate, if any (open_head_group()).
        tilt.held_angle_deg = rounded(animation.frames.front().pose.gamma_deg, kAngleDecimals);
        tilt.angle_deg.assign(frame_count, tilt.held_angle_deg);
        return tilt;
    }
    tilt.angle_deg.assign(frame_count, 0.0);
    const double tolerance_deg = tolerance_px / reach_px * kDegreesPerRadian;
    // Each move of the head gets key frames of its own, from the frame it leaves a held angle to the
    // frame it holds the next, both keys: a held angle is then shown exactly, and the frames that
    // hold it draw the same, which the encoder takes as repeats instead of drawing them again.
    KeyFrames keys;
    keys.values.width = 1;
    auto add_key = [&](double position, float angle) {
        keys.positions.push_back(position);
        keys.values.numbers.push_back(angle);
    };
    add_key(0.0, angles.numbers.front());
    for (std::size_t move_start = 0; move_start + 1 < frame_count;) {
        if (angles.numbers[move_start + 1] == angles.numbers[move_start]) {
            ++move_start;
            continue;
        }
        std::size_t move_end = move_start + 1;
        while (move_end + 1 < frame_count && angles.numbers[move_end + 1] != angles.numbers[move_end])
            ++move_end;
        Track move;
        move.width = 1;
        move.numbers.assign(angles.numbers.begin() + static_cast<std::ptrdiff_t>(move_start),
                            angles.numbers.begin() + static_cast<std::ptrdiff_t>(move_end + 1));
        const KeyFrames move_keys = choose_key_frames(move, move.numbers.size(), {tolerance_deg});
        if (keys.positions.back() != static_cast<double>(move_start)) {
            add_key(static_cast<double>(move_start), angles.numbers[move_start]);
        }
        for (std::size_t i = 1; i < move_keys.positions.size(); ++i) {
            add_key(static_cast<double>(move_start) + move_keys.positions[i], move_keys.values.numbers[i]);
        }
        move_start = move_end;
    }
    if (keys.positions.back() != static_cast<double>(frame_count - 1)) {
        add_key(static_cast<double>(frame_count - 1), angles.numbers.back());
    }
    // The angles and key times as the browser reads them back: the groups show exactly these.
    const double last = static_cast<double>(frame_count - 1);
    std::string values;
    for (std::size_t i = 0; i < keys.positions.size(); ++i) {
        if (last > 0.0)
            keys.positions[i] = std::round(keys.positions[i] / last * kKeyTimeScale) / kKeyTimeScale * last;
        const double angle = rounded(static_cast<double>(keys.values.numbers[i]), kAngleDecimals);
        keys.values.numbers[i] = static_cast<float>(angle);
        if (i > 0) values += ';';
        values += format_fixed(angle, kAngleDecimals);
    }
    std::size_t segment = 0;
    for (std::size_t frame = 0; frame < frame_count; ++frame) {
        const double position = static_cast<double>(frame);
        while (segment + 2 < keys.positions.size() && keys.positions[segment + 1] <= position) ++segment;
        const double from = keys.positions[segment];
        const double to = segment + 1 < keys.positions.size() ? keys.positions[segment + 1] : from;
        const double a = keys.values.numbers[segment];
        const double b = segment + 1 < keys.positions.size() ? keys.values.numbers[segment + 1] : a;
        const double u = to > from ? std::min(1.0, std::max(0.0, (position - from) / (to - from))) : 0.0;
        tilt.angle_deg[frame] = a + u * (b - a);
    }
    tilt.keys = keys;
    tilt.animation = "<animateTransform attributeName=\"transform\" type=\"rotate\" additive=\"sum\"" +
                     attribute("dur", clock_value(last / animation.fps)) + attribute("values", values) +
                     attribute("keyTimes", key_times_of(keys, frame_count)) + " fill=\"freeze\"/>\n";
    return tilt;
}

HeadTilt plan_head_tilt_on_canvas(const Animation& animation, Point2 origin, const CanvasBox& canvas,
                                  double tolerance_px) {
    // The tilt's share of the tolerance at the farthest point from O: what its key frames leave
    // over is left to the layers' own key frames, so it is kept small enough that outlines which
    // only the tilt moves still hold still.
    constexpr double kTiltShare = 1.0 / 6.0;
    double reach = 0.0;
    for (const double x : {canvas.x, canvas.x + canvas.width}) {
        for (const double y : {canvas.y, canvas.y + canvas.height}) reach = std::max(reach, std::hypot(x - origin.x, y - origin.y));
    }
    return plan_head_tilt(animation, origin, reach, kTiltShare * tolerance_px);
}

std::string open_head_group(const HeadTilt& tilt, const char* id) {
    return "<g" + attribute("id", id) +
           attribute("transform",
                     "translate(" + format_fixed(tilt.origin.x, kOriginDecimals) + " " +
                         format_fixed(tilt.origin.y, kOriginDecimals) + ") scale(" +
                         format_shortest(1.0 / kHeadUnitsPerPx) + ")" +
                         (tilt.held_angle_deg != 0.0
                              ? " rotate(" + format_fixed(tilt.held_angle_deg, kAngleDecimals) + ")"
                              : std::string())) +
           ">\n" + tilt.animation;
}

}  // namespace talkface::detail

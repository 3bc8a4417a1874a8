// Key frames to the mouth of every frame: interpolation (thesis 5.4), then a speed limit that
// never loses a closure of the lips.
#include <algorithm>
#include <array>
#include <cmath>
#include <optional>

#include "animation/lip_sync_checks.hpp"
#include "common/easing.hpp"
#include "talkface/errors.hpp"
#include "talkface/lip_sync.hpp"

namespace talkface {
inline namespace v0 {

namespace {

using ControlPoints = std::array<Point2, 4>;  // 8.9, 8.2, 8.4, 8.3

ControlPoints points_of(const MouthControls& controls) {
    return {controls.up, controls.down, controls.left, controls.right};
}

MouthControls controls_of(const ControlPoints& points) {
    return {points[0], points[1], points[2], points[3]};
}

double distance(Point2 a, Point2 b) {
    return std::hypot(a.x - b.x, a.y - b.y);
}

// `from` moved towards `to` by at most `length`.
Point2 step_towards(Point2 from, Point2 to, double length) {
    const double gap = distance(from, to);
    if (gap <= length) return to;
    const double share = length / gap;
    return {from.x + (to.x - from.x) * share, from.y + (to.y - from.y) * share};
}

ControlPoints blend(const ControlPoints& a, const ControlPoints& b, double weight) {
    ControlPoints result;
    for (std::size_t k = 0; k < result.size(); ++k) {
        result[k] = {a[k].x + (b[k].x - a[k].x) * weight, a[k].y + (b[k].y - a[k].y) * weight};
    }
    return result;
}

}  // namespace

std::vector<MouthControls> mouth_frames(const FaceModel& neutral,
                                        const std::vector<MouthKeyFrame>& key_frames, std::size_t frame_count,
                                        const LipSyncOptions& options) {
    detail::check_lip_sync_options(options);
    for (std::size_t k = 0; k < key_frames.size(); ++k) {
        if (!std::isfinite(key_frames[k].time_s) ||
            (k > 0 && key_frames[k].time_s < key_frames[k - 1].time_s)) {
            throw InvalidArgument("key frame " + std::to_string(k),
                                  "key frames must have finite times in rising order");
        }
    }
    std::array<ControlPoints, 12> shape_points;
    for (const MouthShape shape : all_mouth_shapes()) {
        shape_points[static_cast<std::size_t>(shape)] = points_of(mouth_controls(neutral, shape));
    }
    auto points_of_key = [&](const MouthKeyFrame& key) -> const ControlPoints& {
        return shape_points[static_cast<std::size_t>(key.shape)];
    };
    const ControlPoints rest = shape_points[static_cast<std::size_t>(MouthShape::m)];

    // What the key frames ask for at each frame.
    std::vector<ControlPoints> wanted(frame_count, rest);
    for (std::size_t i = 0; i < frame_count && !key_frames.empty(); ++i) {
        const double time_s = static_cast<double>(i) / options.fps;
        const auto next = std::upper_bound(key_frames.begin(), key_frames.end(), time_s,
                                           [](double t, const MouthKeyFrame& key) { return t < key.time_s; });
        if (next == key_frames.begin()) {
            wanted[i] = points_of_key(key_frames.front());
        } else if (next == key_frames.end()) {
            wanted[i] = points_of_key(key_frames.back());
        } else {
            const MouthKeyFrame& before = *(next - 1);
            const double fraction = (time_s - before.time_s) / (next->time_s - before.time_s);
            const double weight = options.interpolation == MouthInterpolation::smooth
                                      ? detail::ease_in_out(fraction)
                                      : fraction;
            wanted[i] = blend(points_of_key(before), points_of_key(*next), weight);
        }
    }

    // Closed-lip key frames are pinned to their frames.
    std::vector<std::optional<ControlPoints>> pinned(frame_count);
    for (const MouthKeyFrame& key : key_frames) {
        const double frame = std::round(key.time_s * options.fps);
        if (detail::is_closed_mouth(key.shape) && frame >= 0.0 && frame < static_cast<double>(frame_count)) {
            pinned[static_cast<std::size_t>(frame)] = points_of_key(key);
        }
    }
    std::vector<std::size_t> next_pin(frame_count + 1, frame_count);
    for (std::size_t i = frame_count; i-- > 0;) next_pin[i] = pinned[i] ? i : next_pin[i + 1];

    // One pass forward. Each point moves at most max_step per frame, and never further from the
    // next pin than it can make up at that speed, so it is on the pin when the pin's frame comes:
    // the mouth starts closing early instead of skipping a b, p, m or f.
    const double max_step = options.max_speed_mns0_per_s * neutral.fapu("MNS0") / options.fps;
    constexpr double kRounding = 1e-9;
    std::vector<MouthControls> frames;
    frames.reserve(frame_count);
    ControlPoints current{};
    for (std::size_t i = 0; i < frame_count; ++i) {
        const std::size_t pin_frame = next_pin[i];
        ControlPoints placed = wanted[i];
        for (std::size_t k = 0; k < placed.size(); ++k) {
            const bool is_first = i == 0;
            if (pin_frame == i) {
                const Point2 pin = (*pinned[i])[k];
                const bool can_reach = is_first || distance(current[k], pin) <= max_step * (1.0 + kRounding);
                placed[k] = can_reach ? pin : step_towards(current[k], pin, max_step);
                continue;
            }
            Point2 candidate = wanted[i][k];
            if (pin_frame < frame_count) {
                const Point2 pin = (*pinned[pin_frame])[k];
                const double reach = static_cast<double>(pin_frame - i) * max_step;
                candidate = step_towards(pin, candidate, reach);
                if (!is_first) {
                    candidate = step_towards(current[k], candidate, max_step);
                    // The step may leave the pin's reach when it cuts across; heading straight
                    // for the pin never does.
                    if (distance(candidate, pin) > reach * (1.0 + kRounding)) {
                        candidate = step_towards(current[k], pin, max_step);
                    }
                }
            } else if (!is_first) {
                candidate = step_towards(current[k], candidate, max_step);
            }
            placed[k] = candidate;
        }
        current = placed;
        frames.push_back(controls_of(current));
    }
    return frames;
}

}  // namespace v0
}  // namespace talkface

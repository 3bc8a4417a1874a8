#include "render/key_frames.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "common/number_format.hpp"
#include "common/string_ends.hpp"

namespace talkface::detail {

namespace {

// Weights below this (drawing units per frame of change in slope) say nothing about where a bend lies.
constexpr double kBendWeightFloor = 1e-3;
// A key stays clear of the frame after it, which the next segment must still reach within the
// tolerance: at that frame itself the next segment would have no span to do it in.
constexpr double kLatestBend = 0.9;

}  // namespace

// Key frames for linear interpolation within `tolerances` of every frame, chosen greedily. For
// each number the admissible slopes from the segment's start form an interval that every frame
// inside the segment narrows; a frame can end the segment while its own slope stays inside every
// interval. When a frame cannot, the segment ends where the motion bent: lips move straight from
// one mouth key frame to the next, and a mouth key frame falls between two drawn frames. Each
// number's line so far and its line through the two frames after the bend cross there; one key
// at their weighted mean crossing stands for the two frames on either side of the bend, on the
// lines so far (the frames before it lie on those lines, as their slopes showed) moved towards the
// lines after it as far as the frames before it allow, which gives the next segment a start on its
// own line. Linear in the frames.
KeyFrames choose_key_frames(const Track& track, std::size_t frame_count,
                            const std::vector<double>& tolerances) {
    const std::size_t width = track.width;
    auto value = [&](std::size_t frame, std::size_t k) {
        return static_cast<double>(track.numbers[frame * width + k]);
    };
    KeyFrames keys;
    keys.values.width = width;
    double start = 0.0;
    std::vector<double> start_values(width);
    for (std::size_t k = 0; k < width; ++k) start_values[k] = value(0, k);
    auto add_key = [&] {
        keys.positions.push_back(start);
        for (const double number : start_values) keys.values.numbers.push_back(static_cast<float>(number));
    };
    add_key();
    std::vector<double> low(width);
    std::vector<double> high(width);
    std::vector<double> so_far(width);  // at a bend: each number's line so far, and after the bend
    std::vector<double> after(width);
    auto reset = [&] {
        std::fill(low.begin(), low.end(), -std::numeric_limits<double>::infinity());
        std::fill(high.begin(), high.end(), std::numeric_limits<double>::infinity());
    };
    reset();
    for (std::size_t frame = 1; frame < frame_count; ++frame) {
        bool fits = true;
        for (std::size_t k = 0; k < width && fits; ++k) {
            const double slope = (value(frame, k) - start_values[k]) / (static_cast<double>(frame) - start);
            fits = slope >= low[k] && slope <= high[k];
        }
        if (!fits) {
            const std::size_t before = frame - 1;
            const double span = static_cast<double>(before) - start;
            double bend = 0.0;  // after `before`, in frames
            if (frame + 1 < frame_count && span > 0.0) {
                double weighted = 0.0, weights = 0.0;
                for (std::size_t k = 0; k < width; ++k) {
                    const double slope_so_far = (value(before, k) - start_values[k]) / span;
                    const double slope_after = value(frame + 1, k) - value(frame, k);
                    const double weight = std::abs(slope_so_far - slope_after);
                    if (weight < kBendWeightFloor) continue;
                    const double crossing =
                        (value(frame, k) - value(before, k) - slope_after) / (slope_so_far - slope_after);
                    weighted += weight * std::clamp(crossing, 0.0, 1.0);
                    weights += weight;
                }
                if (weights > 0.0) bend = std::min(weighted / weights, kLatestBend);
            }
            // One share of the way to the lines after for every number, so that the key is the same
            // blend of frames for all of them (an S or T control stays the reflection it was).
            const double key = static_cast<double>(before) + bend;
            double share = frame + 1 < frame_count && key > start ? 1.0 : 0.0;
            for (std::size_t k = 0; k < width; ++k) {
                const double slope_so_far = span > 0.0 ? (value(before, k) - start_values[k]) / span : 0.0;
                so_far[k] = value(before, k) + slope_so_far * bend;
                if (share == 0.0) continue;
                after[k] = value(frame, k) - (value(frame + 1, k) - value(frame, k)) * (1.0 - bend);
                const double lowest = start_values[k] + low[k] * (key - start);
                const double highest = start_values[k] + high[k] * (key - start);
                const double move = after[k] - so_far[k];
                if (move > 0.0) share = std::min(share, std::max(0.0, (highest - so_far[k]) / move));
                if (move < 0.0) share = std::min(share, std::max(0.0, (lowest - so_far[k]) / move));
            }
            for (std::size_t k = 0; k < width; ++k) {
                start_values[k] = share > 0.0 ? so_far[k] + share * (after[k] - so_far[k]) : so_far[k];
            }
            start = key;
            add_key();
            reset();
        }
        const double span = static_cast<double>(frame) - start;
        for (std::size_t k = 0; k < width; ++k) {
            const double offset = value(frame, k) - start_values[k];
            low[k] = std::max(low[k], (offset - tolerances[k]) / span);
            high[k] = std::min(high[k], (offset + tolerances[k]) / span);
        }
    }
    const std::size_t last = frame_count - 1;
    if (keys.positions.back() != static_cast<double>(last)) {
        start = static_cast<double>(last);
        for (std::size_t k = 0; k < width; ++k) start_values[k] = value(last, k);
        add_key();
    }
    return keys;
}

void TrackRecorder::start(std::vector<double> first_numbers) {
    first_ = std::move(first_numbers);
    track_ = Track{};
}

void TrackRecorder::add(const std::vector<double>& numbers, std::size_t frame, std::size_t expected_frames) {
    if (!track_.varies) {
        if (numbers == first_) return;
        track_.varies = true;
        track_.width = first_.size();
        track_.numbers.reserve(expected_frames * track_.width);
        for (std::size_t earlier = 0; earlier < frame; ++earlier) {
            for (const double number : first_) track_.numbers.push_back(static_cast<float>(number));
        }
    }
    for (const double number : numbers) track_.numbers.push_back(static_cast<float>(number));
}

void TrackRecorder::repeat() {
    if (!track_.varies) return;
    const std::size_t last = track_.numbers.size() - track_.width;
    for (std::size_t k = 0; k < track_.width; ++k) track_.numbers.push_back(track_.numbers[last + k]);
}

Track interpolated(const KeyFrames& keys, std::size_t frame_count) {
    const std::size_t width = keys.values.width;
    Track shown;
    shown.width = width;
    shown.varies = keys.positions.size() > 1;
    shown.numbers.reserve(frame_count * width);
    std::size_t segment = 0;
    for (std::size_t frame = 0; frame < frame_count; ++frame) {
        const double position = static_cast<double>(frame);
        while (segment + 2 < keys.positions.size() && keys.positions[segment + 1] <= position) ++segment;
        const std::size_t next = std::min(segment + 1, keys.positions.size() - 1);
        const double from = keys.positions[segment];
        const double to = keys.positions[next];
        const double u = to > from ? std::clamp((position - from) / (to - from), 0.0, 1.0) : 0.0;
        for (std::size_t k = 0; k < width; ++k) {
            const double a = keys.values.numbers[segment * width + k];
            const double b = keys.values.numbers[next * width + k];
            shown.numbers.push_back(static_cast<float>(a + u * (b - a)));
        }
    }
    return shown;
}

std::string key_times_of(const KeyFrames& keys, std::size_t frame_count) {
    const double last = static_cast<double>(frame_count - 1);
    std::string key_times;
    for (std::size_t i = 0; i < keys.positions.size(); ++i) {
        if (i > 0) key_times += ';';
        // Six digits place a key time within 1 ms on an animation of 15 minutes. An SVG number may
        // start at its point: ".25" is a byte shorter than "0.25".
        const std::string key_time = format_fixed(keys.positions[i] / last, 6);
        key_times.append(key_time, starts_with(key_time, "0.") ? 1 : 0, std::string::npos);
    }
    return key_times;
}

std::string clock_value(double seconds) {
    return format_fixed(seconds, 3) + "s";
}

}  // namespace talkface::detail

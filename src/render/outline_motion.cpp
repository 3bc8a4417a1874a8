#include "render/outline_motion.hpp"

#include <cmath>
#include <cstddef>
#include <vector>

#include "common/number_format.hpp"
#include "render/svg_text.hpp"

namespace talkface::detail {

namespace {

// The translate's share of the tolerance; the outline has the rest, less the rounding of both.
constexpr double kOffsetShare = 1.0 / 3.0;
constexpr int kOffsetDecimals = 1;
constexpr double kOffsetRounding = 0.05;

// The translate's values over `keys`, which are left as written.
std::string translate_values(KeyFrames& keys) {
    std::string values;
    for (std::size_t i = 0; i < keys.positions.size(); ++i) {
        if (i > 0) values += ';';
        for (std::size_t k = 0; k < 2; ++k) {
            if (k > 0) values += ' ';
            float& number = keys.values.numbers[i * 2 + k];
            values += format_fixed(static_cast<double>(number), kOffsetDecimals);
            number = static_cast<float>(round_as_written(static_cast<double>(number), kOffsetDecimals));
        }
    }
    return values;
}

}  // namespace

MovedOutline split_motion(const Track& track, std::size_t frame_count) {
    const std::size_t points = track.width / 2;
    MovedOutline moved;
    moved.offset.width = 2;
    moved.offset.numbers.reserve(2 * frame_count);
    moved.outline.width = track.width;
    moved.outline.numbers.reserve(track.numbers.size());
    for (std::size_t frame = 0; frame < frame_count; ++frame) {
        const float* p = track.numbers.data() + frame * track.width;
        double mean_x = 0.0, mean_y = 0.0;
        for (std::size_t i = 0; i < points; ++i) {
            mean_x += static_cast<double>(p[2 * i]);
            mean_y += static_cast<double>(p[2 * i + 1]);
        }
        mean_x /= static_cast<double>(points);
        mean_y /= static_cast<double>(points);
        if (frame == 0) {
            moved.centre_x = mean_x;
            moved.centre_y = mean_y;
        }
        moved.offset.numbers.push_back(static_cast<float>(mean_x - moved.centre_x));
        moved.offset.numbers.push_back(static_cast<float>(mean_y - moved.centre_y));
        for (std::size_t i = 0; i < points; ++i) {
            moved.outline.numbers.push_back(static_cast<float>(static_cast<double>(p[2 * i]) - mean_x));
            moved.outline.numbers.push_back(static_cast<float>(static_cast<double>(p[2 * i + 1]) - mean_y));
        }
    }
    return moved;
}

MovedText moved_outline_text(const MovedOutline& moved, const TrackForm& form, std::size_t frame_count,
                             double duration_s, double tolerance, Track* shown) {
    const std::string dur = attribute("dur", clock_value(duration_s));
    KeyFrames first_frame;
    first_frame.positions = {0.0};
    first_frame.values.width = moved.outline.width;
    first_frame.values.numbers.assign(
        moved.outline.numbers.begin(),
        moved.outline.numbers.begin() + static_cast<std::ptrdiff_t>(moved.outline.width));
    MovedText text;
    const PathLayout layout = layout_of(form, moved.outline, frame_count);
    text.value = key_values(form, layout, first_frame);
    text.attributes = " transform=\"translate(" + format_fixed(moved.centre_x, kOffsetDecimals) + " " +
                      format_fixed(moved.centre_y, kOffsetDecimals) + ")\"";
    const double outline_tolerance = (1.0 - kOffsetShare) * tolerance - 0.5 - chain_rounding(layout);
    const KeyFrames outline_keys = choose_key_frames(
        moved.outline, frame_count, std::vector<double>(moved.outline.width, outline_tolerance));
    // Two key frames that agree within the tolerance: the outline holds its shape.
    bool is_reshaped = outline_keys.positions.size() > 2;
    for (std::size_t k = 0; k < moved.outline.width && !is_reshaped; ++k) {
        is_reshaped =
            std::abs(moved.outline.numbers[k] -
                     moved.outline.numbers[(frame_count - 1) * moved.outline.width + k]) > outline_tolerance;
    }
    if (is_reshaped) {
        text.animations += "<animate attributeName=\"" + std::string(form.name) + "\"" + dur +
                           attribute("values", key_values(form, layout, outline_keys)) +
                           attribute("keyTimes", key_times_of(outline_keys, frame_count)) +
                           " fill=\"freeze\"/>";
    }
    const double offset_tolerance = kOffsetShare * tolerance - kOffsetRounding;
    KeyFrames keys = choose_key_frames(moved.offset, frame_count, {offset_tolerance, offset_tolerance});
    const std::string values = translate_values(keys);
    if (shown != nullptr) {
        const Track outline = interpolated(is_reshaped ? outline_keys : first_frame, frame_count);
        const Track offset = interpolated(keys, frame_count);
        const double centre[] = {round_as_written(moved.centre_x, kOffsetDecimals),
                                 round_as_written(moved.centre_y, kOffsetDecimals)};
        *shown = outline;
        shown->varies = true;
        for (std::size_t frame = 0; frame < frame_count; ++frame) {
            for (std::size_t k = 0; k < outline.width; ++k) {
                const std::size_t axis = k % 2;
                shown->numbers[frame * outline.width + k] +=
                    static_cast<float>(centre[axis] + static_cast<double>(offset.numbers[frame * 2 + axis]));
            }
        }
    }
    text.animations += "<animateTransform attributeName=\"transform\" type=\"translate\" additive=\"sum\"" +
                       dur + attribute("values", values) +
                       attribute("keyTimes", key_times_of(keys, frame_count)) + " fill=\"freeze\"/>";
    return text;
}

std::string added_outline_text(const MovedOutline& moved, const TrackForm& form, const PathLayout& layout,
                               std::size_t frame_count, double duration_s, double tolerance,
                               const std::string& extra,
                               const std::function<std::string(const KeyFrames&)>& values_of) {
    const std::string dur = attribute("dur", clock_value(duration_s));
    const double outline_tolerance = (1.0 - kOffsetShare) * tolerance - 0.5 - chain_rounding(layout);
    const KeyFrames outline_keys = choose_key_frames(
        moved.outline, frame_count, std::vector<double>(moved.outline.width, outline_tolerance));
    std::string text = "<animate" + extra + " attributeName=\"" + std::string(form.name) + "\"" + dur +
                       attribute("values", values_of(outline_keys)) +
                       attribute("keyTimes", key_times_of(outline_keys, frame_count)) + " fill=\"freeze\"/>";
    Track mean = moved.offset;
    for (std::size_t frame = 0; frame < frame_count; ++frame) {
        mean.numbers[2 * frame] += static_cast<float>(moved.centre_x);
        mean.numbers[2 * frame + 1] += static_cast<float>(moved.centre_y);
    }
    const double offset_tolerance = kOffsetShare * tolerance - kOffsetRounding;
    KeyFrames keys = choose_key_frames(mean, frame_count, {offset_tolerance, offset_tolerance});
    const std::string values = translate_values(keys);
    return text + "<animateTransform" + extra + " attributeName=\"transform\" type=\"translate\"" + dur +
           attribute("values", values) + attribute("keyTimes", key_times_of(keys, frame_count)) +
           " fill=\"freeze\"/>";
}

}  // namespace talkface::detail

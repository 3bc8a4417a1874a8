#include "render/keyframes_encoder.hpp"

#include <cmath>
#include <optional>
#include <utility>

#include "common/internal_error.hpp"
#include "render/attribute_animation.hpp"
#include "render/outline_motion.hpp"
#include "render/svg_text.hpp"
#include "render/svg_writer.hpp"
#include "render/progress_report.hpp"
#include "talkface/errors.hpp"

namespace talkface::detail {

namespace {

// Half a unit: animated values are written in whole units (path_compaction.hpp).
constexpr double kAnimatedRounding = 0.5;

}  // namespace

KeyframesEncoder::KeyframesEncoder(double fps, double tolerance, int decimals, std::size_t expected_frames)
    : fps_(fps), tolerance_(tolerance), decimals_(decimals), expected_frames_(expected_frames) {}

void KeyframesEncoder::add(const Layer& layer) {
    if (frame_count_++ == 0) {
        first_ = layer;
        list_numeric_attributes(first_, first_attributes_);
        slots_.resize(first_attributes_.size());
        for (std::size_t i = 0; i < slots_.size(); ++i) {
            Slot& slot = slots_[i];
            const NumericAttribute& attribute = first_attributes_[i];
            if (attribute.kind == AttributeKind::path_data) slot.verbs = attribute.path->verbs;
            std::vector<double> first;
            append_numbers_as_written(attribute, decimals_, first);
            slot.numbers.start(std::move(first));
        }
        return;
    }
    const std::size_t frame = frame_count_ - 1;
    list_numeric_attributes(layer, attributes_);
    if (attributes_.size() != slots_.size()) {
        throw internal_error("frame " + std::to_string(frame) + " has " + std::to_string(attributes_.size()) +
                             " numeric attributes, frame 0 has " + std::to_string(slots_.size()));
    }
    for (std::size_t i = 0; i < slots_.size(); ++i) {
        Slot& slot = slots_[i];
        const NumericAttribute& attribute = attributes_[i];
        numbers_.clear();
        append_numbers_as_written(attribute, decimals_, numbers_);
        if (numbers_.size() != slot.numbers.width() ||
            (attribute.kind == AttributeKind::path_data && attribute.path->verbs != slot.verbs)) {
            throw internal_error("frame " + std::to_string(frame) + " draws attribute " + attribute.name +
                                 " with other path commands or another number of coordinates than frame 0");
        }
        slot.numbers.add(numbers_, frame, expected_frames_);
    }
}

void KeyframesEncoder::add_repeat() {
    if (frame_count_++ == 0) throw internal_error("no frame to repeat");
    for (Slot& slot : slots_) slot.numbers.repeat();
}

KeyframesEncoder::WrittenAttribute KeyframesEncoder::write_attribute(std::size_t slot_index,
                                                                     double duration_s,
                                                                     bool want_shown) const {
    WrittenAttribute written;
    const Slot& slot = slots_[slot_index];
    const Track& track = slot.numbers.track();
    const NumericAttribute& attribute = first_attributes_[slot_index];
    if (!track.varies) {
        if (want_shown) {
            written.shown.width = slot.numbers.width();
            for (std::size_t frame = 0; frame < frame_count_; ++frame) {
                for (const double number : slot.numbers.first())
                    written.shown.numbers.push_back(static_cast<float>(number));
            }
        }
        return written;
    }
    const TrackForm form{attribute.kind, attribute.name, &slot.verbs};
    Track* shown = want_shown ? &written.shown : nullptr;
    AttributeOverride& override = written.text;
    override.is_set = true;
    written.rounding = kAnimatedRounding;
    written.is_relative = attribute.kind == AttributeKind::path_data;
    const std::string animation = animate_element(form, track, frame_count_, duration_s, tolerance_, shown);
    // Outlines only: their numbers are points, and the element takes a transform.
    if (attribute.kind != AttributeKind::number && slot.numbers.width() % 2 == 0) {
        const MovedOutline split = split_motion(track, frame_count_);
        Track moved_shown;
        MovedText moved = moved_outline_text(split, form, frame_count_, duration_s, tolerance_,
                                             want_shown ? &moved_shown : nullptr);
        std::string plain;
        append_attribute_value(plain, attribute, decimals_);
        if (moved.value.size() + moved.attributes.size() + moved.animations.size() <
            plain.size() + animation.size()) {
            override.value = std::move(moved.value);
            override.attributes = std::move(moved.attributes);
            override.children = std::move(moved.animations);
            if (written.is_relative) written.layout = layout_of(form, split.outline, frame_count_);
            if (want_shown) written.shown = std::move(moved_shown);
            return written;
        }
        override.value = std::move(plain);
    } else {
        append_attribute_value(override.value, attribute, decimals_);
    }
    if (written.is_relative) written.layout = layout_of(form, track, frame_count_);
    override.children = animation;
    return written;
}

std::string KeyframesEncoder::pose_animation(std::size_t slot_index, const WrittenAttribute& written,
                                             const Track& added, double duration_s) const {
    const Slot& slot = slots_[slot_index];
    const NumericAttribute& numeric = first_attributes_[slot_index];
    const TrackForm form{numeric.kind, numeric.name, &slot.verbs};
    // Only where the pose moves the element past the tolerance: elsewhere what it shows at rest will do.
    // The values at rest are rounded as written: the pose's key frames leave that rounding over, so
    // that the two together stray no further than one animation would.
    const PathLayout& layout = written.layout;
    const double rest_rounding = written.rounding;
    const double tolerance = tolerance_ - rest_rounding - chain_rounding(layout);
    bool is_moved = false;
    for (std::size_t i = 0; i < added.numbers.size() && !is_moved; ++i) {
        is_moved = std::abs(added.numbers[i]) > tolerance;
    }
    if (!is_moved) return {};
    const std::string extra = " class=\"tf-pose\" additive=\"sum\"";
    // Added to a value written as the model writes it: the same commands (absolute, every control
    // point given), or a browser adds nothing; in whole units, as relative values are.
    const auto values_of = [&](const KeyFrames& keys) {
        if (written.is_relative || numeric.kind == AttributeKind::number)
            return key_values(form, layout, keys);
        std::string values;
        for (std::size_t i = 0; i < keys.positions.size(); ++i) {
            if (i > 0) values += ';';
            std::vector<Point2> points(keys.values.width / 2);
            for (std::size_t k = 0; k < points.size(); ++k) {
                points[k] = {keys.values.numbers[i * keys.values.width + 2 * k],
                             keys.values.numbers[i * keys.values.width + 2 * k + 1]};
            }
            if (numeric.kind == AttributeKind::path_data) {
                append_path_data(values, Path{slot.verbs, std::move(points)}, 0);
            } else {
                append_polyline_points(values, points, 0);
            }
        }
        return values;
    };
    const KeyFrames keys = attribute_key_frames(added, layout, frame_count_, tolerance_ - rest_rounding);
    std::string plain = "<animate" + extra + " attributeName=\"" + std::string(form.name) + "\"" +
                        attribute("dur", clock_value(duration_s)) + attribute("values", values_of(keys)) +
                        attribute("keyTimes", key_times_of(keys, frame_count_)) + " fill=\"freeze\"/>";
    // An outline the turn carries as a whole, as finish() writes the posed outlines (outline_motion.hpp).
    if (numeric.kind == AttributeKind::number || added.width % 2 != 0) return plain;
    std::string moved = added_outline_text(split_motion(added, frame_count_), form, layout, frame_count_,
                                           duration_s, tolerance_ - rest_rounding, extra, values_of);
    return moved.size() < plain.size() ? moved : plain;
}

std::string KeyframesEncoder::finish(const ProgressCallback& progress, double from, double to) const {
    const double duration_s = static_cast<double>(frame_count_ - 1) / fps_;
    std::vector<AttributeOverride> overrides(slots_.size());
    for (std::size_t i = 0; i < slots_.size(); ++i) {
        if (i % 16 == 0) {
            report_progress(progress, from + (to - from) * static_cast<double>(i) / static_cast<double>(slots_.size()),
                            "encoding", frame_count_);
        }
        overrides[i] = write_attribute(i, duration_s, false).text;
    }
    std::string svg;
    write_layer_svg(first_, SvgLayerOptions{decimals_, {}, &overrides}, svg);
    return svg;
}

std::string KeyframesEncoder::finish_with_pose(const KeyframesEncoder& posed,
                                               const ProgressCallback& progress, double from,
                                               double to) const {
    if (posed.frame_count_ != frame_count_ || posed.slots_.size() != slots_.size()) {
        throw internal_error("the posed head has " + std::to_string(posed.frame_count_) + " frames and " +
                             std::to_string(posed.slots_.size()) + " numeric attributes, the head at rest " +
                             std::to_string(frame_count_) + " and " + std::to_string(slots_.size()));
    }
    const double duration_s = static_cast<double>(frame_count_ - 1) / fps_;
    std::vector<AttributeOverride> overrides(slots_.size());
    for (std::size_t i = 0; i < slots_.size(); ++i) {
        if (i % 16 == 0) {
            report_progress(progress,
                            from + (to - from) * static_cast<double>(i) / static_cast<double>(slots_.size()),
                            "encoding", frame_count_);
        }
        const TrackRecorder& at_rest = slots_[i].numbers;
        const TrackRecorder& with_pose = posed.slots_[i].numbers;
        if (with_pose.width() != at_rest.width() || posed.slots_[i].verbs != slots_[i].verbs) {
            throw internal_error(
                "the posed head draws attribute " + std::string(first_attributes_[i].name) +
                " with other path commands or another number of coordinates than the head at rest");
        }
        const bool is_same = with_pose.first() == at_rest.first() &&
                             with_pose.track().varies == at_rest.track().varies &&
                             with_pose.track().numbers == at_rest.track().numbers;
        WrittenAttribute written = write_attribute(i, duration_s, !is_same);
        if (!is_same) {
            // What the pose adds to what the element shows at rest, at every frame.
            Track added = written.shown;
            for (std::size_t frame = 0; frame < frame_count_; ++frame) {
                for (std::size_t k = 0; k < added.width; ++k) {
                    const double number =
                        with_pose.track().varies
                            ? static_cast<double>(with_pose.track().numbers[frame * added.width + k])
                            : with_pose.first()[k];
                    float& sum = added.numbers[frame * added.width + k];
                    sum = static_cast<float>(number - static_cast<double>(sum));
                }
            }
            const std::string animation = pose_animation(i, written, added, duration_s);
            if (!animation.empty() && !written.text.is_set) {
                written.text.is_set = true;
                append_attribute_value(written.text.value, first_attributes_[i], decimals_);
            }
            written.text.children += animation;
        }
        overrides[i] = std::move(written.text);
    }
    std::string svg;
    write_layer_svg(first_, SvgLayerOptions{decimals_, {}, &overrides}, svg);
    return svg;
}

}  // namespace talkface::detail

#include "render/keyframes_encoder.hpp"

#include <optional>

#include "common/internal_error.hpp"
#include "render/attribute_animation.hpp"
#include "render/outline_motion.hpp"
#include "render/svg_text.hpp"
#include "render/svg_writer.hpp"
#include "render/progress_report.hpp"
#include "talkface/errors.hpp"

namespace talkface::detail {

namespace {

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

std::string KeyframesEncoder::finish(const ProgressCallback& progress, double from, double to) const {
    const double duration_s = static_cast<double>(frame_count_ - 1) / fps_;
    std::vector<AttributeOverride> overrides(slots_.size());
    for (std::size_t i = 0; i < slots_.size(); ++i) {
        if (i % 16 == 0) {
            report_progress(progress, from + (to - from) * static_cast<double>(i) / static_cast<double>(slots_.size()),
                            "encoding", frame_count_);
        }
        const Slot& slot = slots_[i];
        const Track& track = slot.numbers.track();
        if (!track.varies) continue;
        const NumericAttribute& attribute = first_attributes_[i];
        const TrackForm form{attribute.kind, attribute.name, &slot.verbs};
        const std::string animation = animate_element(form, track, frame_count_, duration_s, tolerance_);
        AttributeOverride& override = overrides[i];
        override.is_set = true;
        // Outlines only: their numbers are points, and the element takes a transform.
        if (attribute.kind != AttributeKind::number && slot.numbers.width() % 2 == 0) {
            MovedText moved = moved_outline_text(split_motion(track, frame_count_), form, frame_count_,
                                                 duration_s, tolerance_);
            std::string plain;
            append_attribute_value(plain, attribute, decimals_);
            if (moved.value.size() + moved.attributes.size() + moved.animations.size() <
                plain.size() + animation.size()) {
                override.value = std::move(moved.value);
                override.attributes = std::move(moved.attributes);
                override.children = std::move(moved.animations);
                continue;
            }
            override.value = std::move(plain);
        } else {
            append_attribute_value(override.value, attribute, decimals_);
        }
        override.children = animation;
    }
    std::string svg;
    write_layer_svg(first_, SvgLayerOptions{decimals_, {}, &overrides}, svg);
    return svg;
}

}  // namespace talkface::detail

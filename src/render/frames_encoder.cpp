#include "render/frames_encoder.hpp"

#include <utility>

#include "render/key_frames.hpp"
#include "render/svg_text.hpp"
#include "render/svg_writer.hpp"

namespace talkface::detail {

FramesEncoder::FramesEncoder(const char* layer_id, double fps, int decimals, std::size_t& group_counter)
    : fps_(fps), decimals_(decimals), groups_(group_counter), svg_("<g" + attribute("id", layer_id) + ">\n") {}

void FramesEncoder::add(const Layer& layer) {
    // Frames are compared as the document shows them: two frames whose numbers differ by less than
    // the rounding are one. Their elements are the same (keyframes_encoder.hpp), so the numbers
    // decide.
    list_numeric_attributes(layer, attributes_);
    numbers_.clear();
    for (const NumericAttribute& attribute : attributes_) append_numbers_as_written(attribute, decimals_, numbers_);
    if (frames_ > 0 && numbers_ == run_numbers_) {
        ++frames_;
        return;
    }
    if (frames_ > 0) flush(false);
    run_ = layer;
    std::swap(run_numbers_, numbers_);
    run_start_ = frames_++;
}

std::string FramesEncoder::finish() {
    flush(true);
    return svg_ + "</g>\n";
}

void FramesEncoder::flush(bool is_last) {
    const double begin_s = static_cast<double>(run_start_) / fps_;
    // The last group stays on after the end, as the key-frame encoding's fill="freeze" does.
    const std::string timing =
        is_last ? attribute("begin", clock_value(begin_s)) + attribute("fill", "freeze")
                : attribute("begin", clock_value(begin_s)) +
                      attribute("dur", clock_value(static_cast<double>(frames_) / fps_ - begin_s));
    svg_ += "<g visibility=\"hidden\">\n<set attributeName=\"visibility\" to=\"visible\"" + timing + "/>\n";
    const std::string prefix = "f" + std::to_string(groups_++) + "-";
    write_layer_svg(run_, SvgLayerOptions{decimals_, prefix, nullptr}, svg_);
    svg_ += "</g>\n";
}

}  // namespace talkface::detail

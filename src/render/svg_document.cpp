#include "render/svg_document.hpp"

#include <cmath>

#include "common/number_format.hpp"
#include "render/face_canvas.hpp"
#include "render/svg_text.hpp"
#include "render/svg_writer.hpp"

namespace talkface::detail {

SvgCanvas face_svg_canvas(const FaceModel& face, int width_px, int height_px) {
    const CanvasBox box = fit_face_canvas(face);
    const double aspect = box.width / box.height;
    if (width_px == 0 && height_px == 0) {
        width_px = static_cast<int>(box.width);
        height_px = static_cast<int>(box.height);
    } else if (height_px == 0) {
        height_px = static_cast<int>(std::lround(width_px / aspect));
    } else if (width_px == 0) {
        width_px = static_cast<int>(std::lround(height_px * aspect));
    }
    return {box, width_px, height_px};
}

std::string open_svg_root(const SvgCanvas& canvas, int decimals, const std::string& class_name) {
    auto number = [&](double value) { return format_fixed(value, decimals); };
    std::string svg = "<svg xmlns=\"http://www.w3.org/2000/svg\" xmlns:xlink=\"http://www.w3.org/1999/xlink\"";
    svg += " version=\"1.1\"";
    if (!class_name.empty()) svg += attribute("class", class_name);
    svg += attribute("width", std::to_string(canvas.width_px)) +
           attribute("height", std::to_string(canvas.height_px)) +
           attribute("viewBox", number(canvas.box.x) + " " + number(canvas.box.y) + " " +
                                    number(canvas.box.width) + " " + number(canvas.box.height)) +
           ">\n";
    return svg;
}

std::string layer_group_svg(const char* id, const Layer& layer, int decimals) {
    std::string svg = "<g" + attribute("id", id) + ">\n";
    write_layer_svg(layer, SvgLayerOptions{decimals, {}, nullptr}, svg);
    return svg + "</g>\n";
}

std::string background_layer_svg(const SvgCanvas& canvas, const std::optional<Rgb>& colour, int decimals) {
    return layer_group_svg("background", draw_background_layer(canvas.box, colour), decimals);
}

}  // namespace talkface::detail

#include "render/svg_text.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "common/number_format.hpp"

namespace talkface::detail {

Rgb blend(Rgb a, Rgb b, double amount) {
    auto channel = [amount](std::uint8_t from, std::uint8_t to) {
        return static_cast<std::uint8_t>(std::lround(from + (to - from) * amount));
    };
    return {channel(a.r, b.r), channel(a.g, b.g), channel(a.b, b.b)};
}

std::string attribute(const char* name, const std::string& value) {
    return std::string(" ") + name + "=\"" + value + "\"";
}

std::string paint(const std::string& fill, const std::string& stroke, double stroke_px, int decimals) {
    std::string text = attribute("fill", fill);
    text += attribute("stroke", stroke);
    if (stroke != "none") {
        // A thin outline must not round to 0 when coordinates are written with few decimals.
        text += attribute("stroke-width", format_fixed(stroke_px, std::max(decimals, 2)));
        text += attribute("stroke-linejoin", "round");
        text += attribute("stroke-linecap", "round");
    }
    return text;
}

}  // namespace talkface::detail

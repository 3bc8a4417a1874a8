#include "render/svg_text.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>

#include "common/number_format.hpp"

namespace talkface::detail {

Rgb blend(Rgb a, Rgb b, double amount) {
    auto channel = [amount](std::uint8_t from, std::uint8_t to) {
        return static_cast<std::uint8_t>(std::lround(from + (to - from) * amount));
    };
    return {channel(a.r, b.r), channel(a.g, b.g), channel(a.b, b.b)};
}

void append_fixed(std::string& text, double value, int decimals) {
    static constexpr long long kPowersOfTen[] = {1, 10, 100, 1000, 10000, 100000, 1000000};
    // Beyond these, or out of a long long's range, the general conversion is as fast as needed.
    constexpr double kLargestScaled = 1e15;
    if (decimals < 0 || decimals > 6) {
        text += format_fixed(value, decimals);
        return;
    }
    const long long power = kPowersOfTen[decimals];
    const double product = value * static_cast<double>(power);
    const double scaled = std::nearbyint(product);
    // A product that lands on a tie may have been rounded onto it from either side: the general
    // conversion, which sees the exact value, decides. Elsewhere rounding the product cannot
    // cross a tie, so the digits are the same.
    if (!(std::abs(scaled) < kLargestScaled) || std::abs(product - std::trunc(product)) == 0.5) {
        text += format_fixed(value, decimals);
        return;
    }
    // Digits are written backwards from the end of the buffer, then appended at once.
    char buffer[32];
    char* const end = buffer + sizeof buffer;
    char* p = end;
    long long magnitude = std::llabs(static_cast<long long>(scaled));
    long long fraction = magnitude % power;
    int width = decimals;
    while (fraction != 0 && fraction % 10 == 0) {
        fraction /= 10;
        --width;
    }
    if (fraction != 0) {
        for (int digit = 0; digit < width; ++digit, fraction /= 10)
            *--p = static_cast<char>('0' + fraction % 10);
        *--p = '.';
    }
    long long whole = magnitude / power;
    do {
        *--p = static_cast<char>('0' + whole % 10);
        whole /= 10;
    } while (whole != 0);
    if (scaled < 0.0) *--p = '-';
    text.append(p, static_cast<std::size_t>(end - p));
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

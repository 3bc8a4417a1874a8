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

namespace {

constexpr long long kPowersOfTen[] = {1, 10, 100, 1000, 10000, 100000, 1000000};

// The value times 10^decimals rounded to a whole number, as format_fixed() rounds it, or false
// where only the general conversion knows: beyond 6 decimals, out of a long long's range, or on a
// tie. A product that lands on a tie may have been rounded onto it from either side: the general
// conversion, which sees the exact value, decides. Elsewhere rounding the product cannot cross a
// tie, so the digits are the same.
bool scaled_whole(double value, int decimals, double& scaled) {
    constexpr double kLargestScaled = 1e15;
    if (decimals < 0 || decimals > 6) return false;
    const double product = value * static_cast<double>(kPowersOfTen[decimals]);
    scaled = std::nearbyint(product);
    return std::abs(scaled) < kLargestScaled && std::abs(product - std::trunc(product)) != 0.5;
}

// What reading "[-]whole.fraction" gives: the whole part plus the fraction over its power of ten.
double read_back(bool is_negative, long long whole, long long fraction, long long power) {
    const double result = static_cast<double>(whole) + static_cast<double>(fraction) / static_cast<double>(power);
    return is_negative ? -result : result;
}

}  // namespace

void append_fixed(std::string& text, double value, int decimals) {
    double scaled = 0.0;
    if (!scaled_whole(value, decimals, scaled)) {
        text += format_fixed(value, decimals);
        return;
    }
    const long long power = kPowersOfTen[decimals];
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

double round_as_written(double value, int decimals) {
    double scaled = 0.0;
    if (scaled_whole(value, decimals, scaled)) {
        // The fraction's trailing zeros, which the text leaves out, do not change the quotient: the
        // division is correctly rounded either way.
        const long long power = kPowersOfTen[decimals];
        const long long magnitude = std::llabs(static_cast<long long>(scaled));
        return read_back(scaled < 0.0, magnitude / power, magnitude % power, power);
    }
    // Rare: read the text the general conversion writes, as a reader of the document would.
    const std::string text = format_fixed(value, decimals);
    std::size_t i = 0;
    const bool is_negative = !text.empty() && text[0] == '-';
    if (is_negative) ++i;
    long long whole = 0;
    for (; i < text.size() && text[i] != '.'; ++i) whole = whole * 10 + (text[i] - '0');
    long long fraction = 0;
    long long power = 1;
    for (++i; i < text.size() && power < 1000000000; ++i) {
        fraction = fraction * 10 + (text[i] - '0');
        power *= 10;
    }
    return read_back(is_negative, whole, fraction, power);
}

std::string attribute(const char* name, const std::string& value) {
    return std::string(" ") + name + "=\"" + value + "\"";
}

}  // namespace talkface::detail

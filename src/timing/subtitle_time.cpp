#include "timing/subtitle_time.hpp"

#include <cmath>
#include <vector>

namespace talkface::detail {

namespace {

std::string two_digits(long value) { return (value < 10 ? "0" : "") + std::to_string(value); }

// A run of ASCII digits, nullopt otherwise.
std::optional<long> digits(std::string_view text) {
    if (text.empty() || text.size() > 9) return std::nullopt;
    long value = 0;
    for (const char c : text) {
        if (c < '0' || c > '9') return std::nullopt;
        value = value * 10 + (c - '0');
    }
    return value;
}

}  // namespace

std::string subtitle_time(double seconds, char separator) {
    const long milliseconds = std::lround(std::max(seconds, 0.0) * 1000.0);
    const long ms = milliseconds % 1000;
    const long total_s = milliseconds / 1000;
    const std::string ms_text = std::to_string(ms);
    return two_digits(total_s / 3600) + ":" + two_digits(total_s / 60 % 60) + ":" + two_digits(total_s % 60) +
           separator + std::string(3 - ms_text.size(), '0') + ms_text;
}

std::optional<double> parse_subtitle_time(std::string_view text, char separator) {
    const std::size_t point = text.rfind(separator);
    if (point == std::string_view::npos || text.size() - point - 1 != 3) return std::nullopt;
    const std::optional<long> ms = digits(text.substr(point + 1));
    std::vector<long> fields;
    std::string_view rest = text.substr(0, point);
    while (true) {
        const std::size_t colon = rest.find(':');
        const std::optional<long> field = digits(rest.substr(0, colon));
        if (!field) return std::nullopt;
        fields.push_back(*field);
        if (colon == std::string_view::npos) break;
        rest.remove_prefix(colon + 1);
    }
    // SubRip always writes the hours; WebVTT may leave them out.
    if (!ms || fields.size() < (separator == ',' ? 3u : 2u) || fields.size() > 3) return std::nullopt;
    if (fields.size() == 2) fields.insert(fields.begin(), 0);
    if (fields[1] > 59 || fields[2] > 59) return std::nullopt;
    return static_cast<double>(fields[0] * 3600 + fields[1] * 60 + fields[2]) + static_cast<double>(*ms) / 1000.0;
}

}  // namespace talkface::detail

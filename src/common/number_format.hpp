// Locale-independent number text: shortest round-trip form for files, fixed decimals for SVG.
#ifndef TALKFACE_COMMON_NUMBER_FORMAT_HPP
#define TALKFACE_COMMON_NUMBER_FORMAT_HPP

#include <optional>
#include <string>
#include <string_view>

namespace talkface::detail {

// The shortest text that reads back as exactly `value` ("12.5", "0.1", "1e-07").
std::string format_shortest(double value);

// `value` with at most `decimals` digits after the point, trailing zeros dropped ("12.5", "-3").
std::string format_fixed(double value, int decimals);

// `value` rounded to `decimals` digits after the point, as a number (what format_fixed writes, for
// callers that compare or reuse the written value).
double rounded(double value, int decimals);

// Parses a whole string as a double ("12.5", "-3e2"); nullopt if it is not exactly a number.
// Does not depend on the C locale.
std::optional<double> parse_double(std::string_view text);

}  // namespace talkface::detail

#endif

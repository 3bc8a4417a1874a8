// Small helpers for writing SVG text: numbers at fixed precision, colours, blended colours.
#ifndef TALKFACE_RENDER_SVG_TEXT_HPP
#define TALKFACE_RENDER_SVG_TEXT_HPP

#include <string>

#include "talkface/types.hpp"

namespace talkface::detail {

// `a` moved towards `b` by `amount` (0..1), rounded per channel.
Rgb blend(Rgb a, Rgb b, double amount);

// Appends format_fixed(value, decimals) (common/number_format.hpp), the same text, without its
// general-purpose conversion: an animation writes millions of coordinates.
void append_fixed(std::string& text, double value, int decimals);

// The number a reader of append_fixed(value, decimals)'s text gets back: whole + fraction / 10^n,
// computed as SVG text would be read, without writing it. The animation encodings compare and
// interpolate what the document shows, not the unrounded numbers.
double round_as_written(double value, int decimals);

// An attribute ` name="value"` (value written as given; callers pass numbers, ids, colours).
std::string attribute(const char* name, const std::string& value);

}  // namespace talkface::detail

#endif

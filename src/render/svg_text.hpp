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

// An attribute ` name="value"` (value written as given; callers pass numbers, ids, colours).
std::string attribute(const char* name, const std::string& value);

// Fill and stroke presentation attributes; `fill` or `stroke` "none" turns that paint off.
std::string paint(const std::string& fill, const std::string& stroke, double stroke_px, int decimals);

}  // namespace talkface::detail

#endif

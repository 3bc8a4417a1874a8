// Simplified or Traditional: which one a transcript is written in, so that the syllables a written
// form becomes (2本書 -> 兩, 3万 -> 萬) show in the transcript's own script (issue 13).
#ifndef TALKFACE_TEXT_SCRIPT_VARIANT_HPP
#define TALKFACE_TEXT_SCRIPT_VARIANT_HPP

#include <string>
#include <string_view>
#include <vector>

#include "text/code_points.hpp"

namespace talkface::detail {

// Whether `text` holds more characters found only in Traditional writing (們 這 說 ...) than ones
// found only in Simplified (们 这 说 ...), among some of the commonest of each.
bool is_traditional_text(const std::vector<CodePoint>& text);

// A character of a written form's reading (the Simplified words of written_numbers.hpp) in its
// Traditional form: 两 -> 兩, 万 -> 萬, 点 -> 點; other characters as they are.
std::string traditional_form(std::string_view character);

}  // namespace talkface::detail

#endif

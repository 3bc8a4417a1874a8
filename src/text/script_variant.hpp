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

// Whether `text` writes Cantonese, as Hong Kong's chats, posts and subtitles do: one of the characters only
// written Cantonese uses (嘅 咗 喺 哋 嘢 佢 冇 啲 嚟 睇 噉). Hong Kong's Traditional text is told from
// Taiwan's so where it says something of its own (its units: 厘米, not 公分); its formal Chinese, which
// writes none of them, reads as Taiwan's.
bool writes_cantonese(const std::vector<CodePoint>& text);

// A character of a written form's reading (the Simplified words of written_numbers.hpp) in its
// Traditional form: 两 -> 兩, 万 -> 萬, 点 -> 點; other characters as they are.
std::string traditional_form(std::string_view character);

}  // namespace talkface::detail

#endif

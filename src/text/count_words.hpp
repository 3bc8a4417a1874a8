// The characters a count is written with in words (一 二 两 ... 十 百 千 万 几 半), Simplified and
// Traditional: what a measure word follows (三种 几只: measure_or_verb.hpp), what 得 "get" takes
// before what was got (得一百分: must_verb.hpp), what starts a span (三天假: counted_noun.hpp) and a
// value (为三成: quantity_copula.hpp).
#ifndef TALKFACE_TEXT_COUNT_WORDS_HPP
#define TALKFACE_TEXT_COUNT_WORDS_HPP

#include <string_view>

namespace talkface::detail {

bool starts_with_count(std::string_view word);
bool ends_with_count(std::string_view word);

}  // namespace talkface::detail

#endif

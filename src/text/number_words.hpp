// Numbers said in Mandarin words: cardinals (12999 一万二千九百九十九), digit strings (2026
// 二零二六, 110 幺幺零 on the phone) and decimals (3.14 三点一四). The written-form reader
// (number_context.cpp, for written_numbers.cpp) decides which of them a number on the page is.
#ifndef TALKFACE_TEXT_NUMBER_WORDS_HPP
#define TALKFACE_TEXT_NUMBER_WORDS_HPP

#include <cstddef>
#include <string>
#include <string_view>

namespace talkface::detail {

// The most digits read as a number; longer runs are read digit by digit (issue 13).
constexpr std::size_t kMostCardinalDigits = 16;

// `digits` (ASCII 0-9, 1 to kMostCardinalDigits of them; leading zeros ignored) as a cardinal
// in Simplified characters: "12999" -> 一万二千九百九十九, "10" -> 十, "105" -> 一百零五,
// "100010" -> 十万零一十. With `liang_at_head` a 2 leading a 千, 万 or 亿 place is 两
// (2400 两千四百, 20000 两万, 12000 一万二千), as a native reader says it.
std::string cardinal_words(std::string_view digits, bool liang_at_head = true);

// `digits` one by one: "2026" -> 二零二六; with `yao_for_one` 1 is 幺, as phone numbers are said.
std::string digit_words(std::string_view digits, bool yao_for_one = false);

// A decimal: the whole part as a cardinal (两 at the head of a 千, 万 or 亿 place: 2350.5
// 两千三百五十点五), then 点 and the fraction digits one by one: ("3", "14") -> 三点一四,
// ("2", "5") -> 二点五.
std::string decimal_words(std::string_view whole_digits, std::string_view fraction_digits);

}  // namespace talkface::detail

#endif

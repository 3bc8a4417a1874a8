// How a number is read off the page, for every part of the written-form reader (written_numbers.cpp
// and the files beside it): its digits, thousands separators and point, the marks around it, the
// text before and after it in its clause, and the measure words that make a 2 两.
#ifndef TALKFACE_TEXT_WRITTEN_NUMBER_SCAN_HPP
#define TALKFACE_TEXT_WRITTEN_NUMBER_SCAN_HPP

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "common/string_ends.hpp"
#include "text/code_points.hpp"
#include "text/written_numbers.hpp"

namespace talkface::detail {

bool is_digit_at(const std::vector<CodePoint>& text, std::size_t i);

char32_t value_at(const std::vector<CodePoint>& text, std::size_t i);

std::string digits_from(const std::vector<CodePoint>& text, std::size_t& i);

// A number as written: 1,234.5 is whole "1234", fraction "5".
struct WrittenNumber {
    std::string whole;
    std::string fraction;
    bool has_point = false;
    bool has_separators = false;
    std::size_t end = 0;
};

WrittenNumber parse_number(const std::vector<CodePoint>& text, std::size_t i);

// Where the last number of a list joined by 、 starts, the list opened by `first` and each of its numbers
// `digits` digits long with no point or separators (2022、2023年, 80、90后); 0 where `first` opens no such
// list or stands alone.
std::size_t last_listed_start(const std::vector<CodePoint>& text, const WrittenNumber& first,
                              std::size_t digits);

// A month and a day of it, each of one or two digits (a longer run is no date, and is not parsed
// as a number: 2026-12-123456789012345678901 is read digit by digit, not thrown on).
bool is_month_and_day(const std::string& month, const std::string& day);

bool is_one_of(char32_t c, std::u32string_view set);

// A Chinese character of the CJK Unified Ideographs or their Extension A.
bool is_han(char32_t c);

std::string text_between(const std::vector<CodePoint>& text, std::size_t first, std::size_t end);

// Measure words and magnitudes before which 2 is 两 (两本书, 两个, 两万, 两步, 两男三女). Not 月 号
// 日 楼 路 度 代, where 2 is a name or an ordinal (二月, 二号, 二楼, 二代).
bool takes_liang(char32_t c);

// Whether any of the words [first, last) stands in `text` (the clause names a score, a lamp, a race
// ...), starts it, ends it, or is all of it.
bool contains_any(std::string_view text, const std::string_view* first, const std::string_view* last);
bool starts_with_any(std::string_view text, const std::string_view* first, const std::string_view* last);
bool ends_with_any(std::string_view text, const std::string_view* first, const std::string_view* last);
bool is_any_of(std::string_view text, const std::string_view* first, const std::string_view* last);

// The same for `words` written where they are looked for ({"比分", "战成"}), or kept as a table (a
// constexpr std::string_view array) where a rule's words make an idea of their own.
template <std::size_t N>
bool contains_any(std::string_view text, const std::string_view (&words)[N]) {
    return contains_any(text, words, words + N);
}
template <std::size_t N>
bool starts_with_any(std::string_view text, const std::string_view (&words)[N]) {
    return starts_with_any(text, words, words + N);
}
template <std::size_t N>
bool ends_with_any(std::string_view text, const std::string_view (&words)[N]) {
    return ends_with_any(text, words, words + N);
}
template <std::size_t N>
bool is_any_of(std::string_view text, const std::string_view (&words)[N]) {
    return is_any_of(text, words, words + N);
}

// The text before text[start] back to the last end mark or line break (the sentence so far), and
// with `clause_only` to the last pause mark too.
std::string text_before(const std::vector<CodePoint>& text, std::size_t start, bool clause_only);

// The text after text[end) up to the next pause or end mark (the rest of the clause; 、 does not
// end it: 6-3、6-4 获胜 is one clause), or without `clause_only` up to the next end mark or line
// break (the rest of the sentence).
std::string text_after(const std::vector<CodePoint>& text, std::size_t end, bool clause_only = true);

constexpr const char* kTooLongWarning = "a number of more than 16 digits; read digit by digit";

void append_warning(SpokenForm& form, const std::string& warning);

bool is_dash(char32_t c);

// A sign of a relation between two terms, as a lesson writes it: = ≈ ≠ < > ≤ ≥.
bool is_relation_sign(char32_t c);

bool is_range_mark(char32_t c);

}  // namespace talkface::detail

#endif

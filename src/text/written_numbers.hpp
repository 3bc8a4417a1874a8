// Numbers as written on a page (2026年, 12月1日, 3:30, 85%, 1/3, 3-5, -3, 1,234, ¥199, NT$300,
// 5km, 25℃, 13812345678), read as a native reader says them (issue 13, SPEC "Transcript to
// syllables"). The conventions chosen where usage varies are in docs/written-forms.md.
// This file's reader (written_numbers.cpp: which form a number takes) calls on parts of one idea each:
// written_number_scan (the digits and the clause around them), number_context (how one number is said
// by the words around it), number_signs, quantities_and_ranges (a number or a range with its unit),
// number_pairs (two numbers about a mark: scores, ratios, fractions), dates_and_times, units_and_money,
// digit_codes (numbers said by their digits) and formula_signs (a lesson's signs, powers and number
// characters, declared here with the reader's other entry points).
#ifndef TALKFACE_TEXT_WRITTEN_NUMBERS_HPP
#define TALKFACE_TEXT_WRITTEN_NUMBERS_HPP

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "text/code_points.hpp"

namespace talkface::detail {

struct WrittenNumber;

struct SpokenForm {
    std::size_t end = 0;   // index past the written form in the code points
    std::string words;     // what is said, in Simplified characters: 二零二六年
    std::string warning;   // what the reader should know ("read digit by digit"), or ""
    bool is_dialled = false;  // a phone's or a service's number (its 1 is 幺 on the mainland, 一 in Taiwan)
};

// The number form that starts at text[start] (a digit, full-width or not, or a sign or currency
// sign right before one: -3, ¥199, $5, NT$300), with the characters after it that decide how it is
// said and are said with it (年 of a year, % , ℃, km, the 万 of $5万); nullopt if no number
// starts there. Characters before it are looked at, not taken: 第 (an ordinal keeps 二), a phone
// word earlier in the sentence (电话, 號碼: digits are said one by one, 1 as 幺).
std::optional<SpokenForm> read_number_form(const std::vector<CodePoint>& text, std::size_t start);

// A subtitle's or a lyric's timing at text[start], which is no speech and is not said: a cue's
// times, hh:mm:ss,mmm (SRT) or hh:mm:ss.mmm (WebVTT), with the arrow and the second time after it
// (00:01:23,450 --> 00:01:25,900), or a lyric's time tag inside its brackets ([00:12.50], LRC).
// Where the timing ends, or nullopt (session 16: they were read as clock times, 零点零一分...).
// Defined in dates_and_times.cpp.
std::optional<std::size_t> past_subtitle_timing(const std::vector<CodePoint>& text, std::size_t start);

// The slash at text[i] between a unit after a number and a unit symbol: 每 and the symbol's words. After a
// byte unit (7,000MB/s 七千 MB 每秒, 1GB/s), whose letters the Latin reader says before it; after a unit of
// Chinese characters (0.7元/W 零点七元每瓦, 1.2元/kWh; session 30: the symbol was spelled, W da bu liu).
// nullopt elsewhere.
std::optional<SpokenForm> read_per_unit(const std::vector<CodePoint>& text, std::size_t i);

// True where the slash at text[i] joins two units after a number and is said 每 (25元/公斤
// 二十五元每公斤, 3次/周): a number, one to three Chinese characters, the slash, a Chinese
// character, but 双一流 (a list of top schools, 985/211/双一流). Elsewhere a slash is not said (男/女).
bool slash_reads_per(const std::vector<CodePoint>& text, std::size_t i);

// True where the slash at text[i] joins two currencies as a rate quotes one in the other (美元/人民币
// 美元兑人民币, 欧元/美元, 美元/日元), said 兑 as market news says the pair (session 36: unsaid): a
// currency's name on each side, by the names news gives them (美元 欧元 日元 英镑 人民币 港元 ...) or their
// ISO codes (USD/CNY).
bool slash_pairs_currencies(const std::vector<CodePoint>& text, std::size_t i);

// True where the slash at text[i] joins two sizes of a model in billions of parameters (7B/70B 七B和七十B,
// 1.5B/7B), said 和 as the two versions are listed (session 28: unsaid). A byte unit's B (8GB/256GB) is no
// size of this kind: a spec pair, not joined so. In a list of three or more only the last slash is 和
// (1.5B/7B/32B 一点五B、七B和三十二B).
bool slash_joins_sizes(const std::vector<CodePoint>& text, std::size_t i);

// What the sign at text[i] of a formula is said as, as a lesson reads it; empty where it is not
// said so. Between two terms (a digit, a letter or a closing bracket each side, spaces allowed):
// = 等于, ≈ 约等于, ≠ 不等于 (a Chinese character may stand beside them too: 答案是x=5), > 大于,
// < 小于, ≥ 大于等于, ≤ 小于等于, × 乘, ÷ 除以, + 加 between two digits or two letters (1+1, A+B)
// or in a clause with a relation sign (x+y=10), - 减 only there (a-b>0; elsewhere a hyphen joins,
// Wi-Fi). √ before a term is 根号, ² and ³ after one 平方 and 立方 (的平方 after a digit: 3²), and
// a Greek letter is said by its name (π 派, α 阿尔法). A row of = under a heading is not said.
std::string_view said_math_sign(const std::vector<CodePoint>& text, std::size_t i);

// A number written as one character, as lessons and lists write them (session 14; they were skipped
// with a warning): circled and bracketed ones (①水 一水, ⑴, ⒈, ❶), Roman numerals (第Ⅱ卷 第二卷, ⅲ)
// and fractions (½ 二分之一, ¾ 四分之三), and a rating drawn in stars, said by its filled ones (★★★★☆ 四星;
// session 21); nullopt where text[i] is none.
std::optional<SpokenForm> read_number_character(const std::vector<CodePoint>& text, std::size_t i);

// A power written right after a term (a digit, a letter, a closing bracket) at text[i - 1]:
// superscript digits (10⁸ 十的八次方, 10⁻³ 十的负三次方, x⁴ x的四次方) or a caret and digits as typed
// (2^10 二的十次方, x^2 x平方, as x² is); a lone ² or ³ is said_math_sign's. nullopt where none starts
// at text[i]. Session 14: the superscripts were skipped with a warning, the caret too.
std::optional<SpokenForm> read_power(const std::vector<CodePoint>& text, std::size_t i);

// A logarithm as a lesson writes it, log and its base in subscript digits or after an underscore, then its
// number (log₂8, log_3 9), said 以 the base 为底 the number 的对数 (以二为底八的对数), as a teacher reads it;
// lg and ln before a number are the common and the natural one (lg100 一百的常用对数, ln10 十的自然对数);
// a variable of one letter in the number's place is said by its name (log₃x 以三为底x的对数, lnx x的自然
// 对数; session 34: log₃x kept lo ge); nullopt elsewhere, and before a number with a letter after it.
std::optional<SpokenForm> read_logarithm(const std::vector<CodePoint>& text, std::size_t i);

// A repeating decimal, a dot above (U+0307) over the first and the last digit of its repeating part or over
// each (0.3̇, 0.1̇2̇, 0.16̇): the decimal through the last dotted digit and 循环 (零点一二循环), as a lesson
// reads it; nullopt where no dot follows the number's digits (session 33: the dots were skipped with a
// warning).
std::optional<SpokenForm> read_repeating_decimal(const std::vector<CodePoint>& text,
                                                 const WrittenNumber& number, const std::string& sign_words);

// True for a service number that is a name wherever it does not count (12306, 12315, 95588: five
// digits), said digit by digit with 幺 for 1 also in a web address (www.12306.cn).
bool is_named_service_number(const std::string& digits);

}  // namespace talkface::detail

#endif

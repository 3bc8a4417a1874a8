#include "text/approximate_counts.hpp"

#include "text/number_words.hpp"

namespace talkface::detail {

std::optional<std::string> approximate_low_end(const std::vector<CodePoint>& text, std::size_t start,
                                               const WrittenNumber& number) {
    constexpr char32_t kListMark = 0x3001;  // 、
    if (number.has_point || number.has_separators || value_at(text, number.end) != kListMark ||
        !is_digit_at(text, number.end + 1) || (start > 0 && is_one_of(text[start - 1].value, U"第、")))
        return std::nullopt;
    const auto next = parse_number(text, number.end + 1);
    const auto after = value_at(text, next.end);
    // After a verb's 了 the pair counts what was done, whatever the measure orders (看了2、3期 两三期,
    // 追了2、3集).
    const bool after_done = start > 0 && text[start - 1].value == U'了';
    if (next.has_point || next.has_separators || !takes_liang(after) ||
        (!after_done && (is_one_of(after, U"层層期届屆章页頁集册冊节節局") ||
                         starts_with_any(text_between(text, next.end, next.end + 2), {"年级", "年級"}))))
        return std::nullopt;
    const auto& low = number.whole;
    const auto& high = next.whole;
    const bool ones = low.size() == 1 && high.size() == 1;
    const bool tens = low.size() == 2 && high.size() == 2 && low[1] == '0' && high[1] == '0';
    if (!(ones || tens) || low[0] < '1' || high[0] != low[0] + 1) return std::nullopt;
    // A 2 at the low end of a count is 两 as before its measure word (两三天); a tens digit stays 二
    // (二三十个).
    if (ones && low == "2") return std::string("两");
    return cardinal_words(low.substr(0, 1), false);
}

}  // namespace talkface::detail

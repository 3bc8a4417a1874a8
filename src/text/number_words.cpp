#include "text/number_words.hpp"

#include "common/internal_error.hpp"
#include "talkface/errors.hpp"

namespace talkface::detail {

namespace {

const char* const kDigitWords[] = {"零", "一", "二", "三", "四", "五", "六", "七", "八", "九"};

std::string_view strip_leading_zeros(std::string_view digits) {
    while (!digits.empty() && digits.front() == '0') digits.remove_prefix(1);
    return digits;
}

// Up to four digits (a 万 group). `is_head`: nothing is said before the group, so 10-19 start
// with 十, not 一十, and a leading 2 may be 两. `before_unit`: 万 or 亿 follows the group, where
// a lone 2 is 两 (两万, but 十二万).
std::string group_words(std::string_view group, bool is_head, bool before_unit, bool liang_at_head) {
    static const char* const kPlaces[] = {"千", "百", "十", ""};
    const std::size_t offset = 4 - group.size();
    std::string words;
    bool started = false;
    bool pending_zero = false;
    for (std::size_t k = 0; k < group.size(); ++k) {
        const auto place = k + offset;
        const int digit = group[k] - '0';
        if (digit == 0) {
            pending_zero = pending_zero || started;
            continue;
        }
        if (pending_zero) words += "零";
        pending_zero = false;
        const bool leads = is_head && !started;
        if (place == 2 && digit == 1 && leads) {
            words += "十";  // 十二, not 一十二
        } else {
            const bool is_liang = liang_at_head && leads && digit == 2 &&
                                  (place == 0 || (place == 3 && before_unit));
            words += is_liang ? "两" : kDigitWords[digit];
            words += kPlaces[place];
        }
        started = true;
    }
    return words;
}

// Up to eight digits, leading zeros stripped by the caller.
std::string below_yi_words(std::string_view digits, bool is_head, bool before_unit, bool liang_at_head) {
    if (digits.size() <= 4) return group_words(digits, is_head, before_unit, liang_at_head);
    const auto high = digits.substr(0, digits.size() - 4);
    const auto low = digits.substr(digits.size() - 4);
    std::string words = group_words(high, is_head, true, liang_at_head) + "万";
    const auto low_significant = strip_leading_zeros(low);
    if (low_significant.empty()) return words;
    if (low.front() == '0') words += "零";
    return words + group_words(low_significant, false, before_unit, liang_at_head);
}

}  // namespace

std::string cardinal_words(std::string_view digits, bool liang_at_head) {
    if (digits.size() > kMostCardinalDigits) {
        throw internal_error("a cardinal of " +
                                             std::to_string(digits.size()) + " digits");
    }
    digits = strip_leading_zeros(digits);
    if (digits.empty()) return "零";
    if (digits.size() <= 8) return below_yi_words(digits, true, false, liang_at_head);
    const auto high = digits.substr(0, digits.size() - 8);
    const auto low = digits.substr(digits.size() - 8);
    std::string words = below_yi_words(high, true, true, liang_at_head) + "亿";
    const auto low_significant = strip_leading_zeros(low);
    if (low_significant.empty()) return words;
    if (low.front() == '0') words += "零";
    return words + below_yi_words(low_significant, false, false, liang_at_head);
}

std::string digit_words(std::string_view digits, bool yao_for_one) {
    std::string words;
    for (const char digit : digits) words += yao_for_one && digit == '1' ? "幺" : kDigitWords[digit - '0'];
    return words;
}

std::string decimal_words(std::string_view whole_digits, std::string_view fraction_digits) {
    return cardinal_words(whole_digits) + "点" + digit_words(fraction_digits);
}

}  // namespace talkface::detail

#include "text/home_layouts.hpp"

namespace talkface::detail {

namespace {

// The parts a layout counts: bedrooms (室 房), living rooms (厅), bathrooms (卫), kitchens (厨), and the
// lifts to the homes on a landing (梯 户).
constexpr std::u32string_view kLayoutParts = U"室房厅廳卫衛厨廚梯户戶";
constexpr std::size_t kMostPartDigits = 2;

bool is_part_count(const WrittenNumber& number) {
    return !number.has_point && !number.has_separators && number.whole.size() <= kMostPartDigits;
}

bool is_part_at(const std::vector<CodePoint>& text, std::size_t i) {
    return i < text.size() && is_one_of(text[i].value, kLayoutParts);
}

}  // namespace

bool counts_in_layout(const std::vector<CodePoint>& text, std::size_t start, const WrittenNumber& number) {
    if (!is_part_count(number) || !is_part_at(text, number.end)) return false;
    const auto after = number.end + 1;
    if (is_digit_at(text, after)) {
        const auto next = parse_number(text, after);
        if (is_part_count(next) && is_part_at(text, next.end)) return true;
    }
    if (start < 2 || !is_part_at(text, start - 1) || !is_digit_at(text, start - 2)) return false;
    auto first = start - 1;
    while (first > 0 && is_digit_at(text, first - 1)) --first;
    return is_part_count(parse_number(text, first));
}

}  // namespace talkface::detail

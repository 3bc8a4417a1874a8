#include "text/counted_parts.hpp"

#include <algorithm>
#include <iterator>
#include <string_view>

namespace talkface::detail {

namespace {

// The parts a layout counts: bedrooms (室 房), living rooms (厅), bathrooms (卫), kitchens (厨), and the
// lifts to the homes on a landing (梯 户).
constexpr std::u32string_view kLayoutParts = U"室房厅廳卫衛厨廚梯户戶";
// The roles a game's team counts when it calls for players (缺1坦2補, 2奶3射): a tank, a healer (奶, 补 or
// 辅, a support), a marksman, a mage, a warrior and an assassin.
constexpr std::u32string_view kTeamRoles = U"坦奶补補辅輔射法战戰刺";
constexpr std::u32string_view kWholes[] = {kLayoutParts, kTeamRoles};
constexpr std::size_t kMostPartDigits = 2;

bool is_part_count(const WrittenNumber& number) {
    return !number.has_point && !number.has_separators && number.whole.size() <= kMostPartDigits;
}

bool is_part_at(const std::vector<CodePoint>& text, std::size_t i, std::u32string_view parts) {
    return i < text.size() && is_one_of(text[i].value, parts);
}

// The parts of the whole text[i] names a part of, or an empty view.
std::u32string_view whole_of_part_at(const std::vector<CodePoint>& text, std::size_t i) {
    for (const auto parts : kWholes)
        if (is_part_at(text, i, parts)) return parts;
    return {};
}

// Words for a home that a count of its rooms names (2房單位 兩房單位, 3室户型, 1房公寓): a part alone before
// one counts as a layout does (session 34: 二房, a part alone read as a name, 二房 a family's second branch).
constexpr std::u32string_view kHomeWords[] = {U"单位", U"單位", U"户型", U"戶型",
                                              U"公寓", U"住宅", U"房源", U"套房"};

bool names_home_at(const std::vector<CodePoint>& text, std::size_t i) {
    return std::any_of(std::begin(kHomeWords), std::end(kHomeWords), [&](std::u32string_view word) {
        if (i + word.size() > text.size()) return false;
        for (std::size_t k = 0; k < word.size(); ++k)
            if (text[i + k].value != word[k]) return false;
        return true;
    });
}

}  // namespace

bool counts_in_layout(const std::vector<CodePoint>& text, std::size_t start, const WrittenNumber& number) {
    const auto parts = whole_of_part_at(text, number.end);
    if (!is_part_count(number) || parts.empty()) return false;
    const auto after = number.end + 1;
    if (parts == kLayoutParts && names_home_at(text, after)) return true;
    if (is_digit_at(text, after)) {
        const auto next = parse_number(text, after);
        if (is_part_count(next) && is_part_at(text, next.end, parts)) return true;
    }
    if (start < 2 || !is_part_at(text, start - 1, parts) || !is_digit_at(text, start - 2)) return false;
    auto first = start - 1;
    while (first > 0 && is_digit_at(text, first - 1)) --first;
    return is_part_count(parse_number(text, first));
}

}  // namespace talkface::detail

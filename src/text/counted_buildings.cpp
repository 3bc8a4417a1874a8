#include "text/counted_buildings.hpp"

#include <string_view>

namespace talkface::detail {

bool counts_buildings(const std::vector<CodePoint>& text, const WrittenNumber& number) {
    constexpr std::size_t kMostBuildingDigits = 2;
    constexpr std::string_view kBuildingNouns[] = {
        "民房", "房屋", "楼房", "樓房", "大楼", "大樓", "住宅",   "建筑",   "建築",   "厂房",
        "廠房", "宿舍", "别墅", "別墅", "平房", "民宅", "教学楼", "教學樓", "办公楼", "辦公樓"};
    if (number.has_point || number.has_separators || number.whole.size() > kMostBuildingDigits) return false;
    return number.end < text.size() && is_one_of(text[number.end].value, U"栋棟幢") &&
           starts_with_any(text_after(text, number.end + 1, true), kBuildingNouns);
}

}  // namespace talkface::detail

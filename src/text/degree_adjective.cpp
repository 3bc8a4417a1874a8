#include "text/degree_adjective.hpp"

#include "text/written_number_scan.hpp"

namespace talkface::detail {

std::string_view degree_adjective_reading(const std::vector<std::string>& words, std::size_t w) {
    if (w == 0 || w >= words.size()) return {};
    // The list's 冲了 (冲了个澡) takes 了 in: the word, then, closes the adjective itself.
    const bool with_particle = words[w] == "冲了" || words[w] == "衝了";
    if (words[w] != "冲" && words[w] != "衝" && !with_particle) return {};
    constexpr std::string_view kDegrees[] = {"太",   "很",   "挺",   "真",   "那么",   "那麼",
                                             "这么", "這麼", "有点", "有點", "有些",   "特别",
                                             "特別", "非常", "更",   "最",   "越来越", "越來越"};
    if (!ends_with_any(words[w - 1], kDegrees)) return {};
    constexpr std::string_view kClosing[] = {"了", "的", "啊", "吧", "啦", "呀"};
    if (!with_particle && w + 1 < words.size() && !is_any_of(words[w + 1], kClosing)) return {};
    return "chong4";
}

}  // namespace talkface::detail

#include "text/counted_noun.hpp"

#include "text/count_words.hpp"
#include "text/written_number_scan.hpp"

namespace talkface::detail {

namespace {

// 一片片 一块块: the measure word said twice, the last two characters alike.
bool ends_said_twice(std::string_view word) {
    if (word.size() < 6) return false;
    return word.substr(word.size() - 3) == word.substr(word.size() - 6, 3);
}

}  // namespace

std::string_view counted_noun_reading(const std::vector<std::string>& words, std::size_t w) {
    if (w == 0 || w >= words.size()) return {};
    const auto& before = words[w - 1];
    if (words[w] == "地") {
        constexpr std::string_view kPointsToPlace[] = {"该", "該", "此", "这", "這", "那",
                                                       "某", "块", "塊", "片", "亩", "畝"};
        return ends_with_any(before, kPointsToPlace) && !ends_said_twice(before) ? "di4" : "";
    }
    if (words[w] == "假") {
        constexpr std::string_view kSpans[] = {"天", "日", "周", "週", "月", "星期"};
        return starts_with_count(before) && ends_with_any(before, kSpans) ? "jia4" : "";
    }
    return {};
}

}  // namespace talkface::detail

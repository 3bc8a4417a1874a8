#include "text/counted_noun.hpp"

#include <algorithm>
#include <cstddef>

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
    if (words[w] == "觉" || words[w] == "覺") {
        // A sleep's noun takes what is said of the sleep between it and its verb (睡不着觉 睡了个觉 睡大觉).
        const auto sleeps = [](const std::string& word) { return word.find("睡") != std::string::npos; };
        const auto first = w < 3 ? words.begin() : words.begin() + static_cast<std::ptrdiff_t>(w - 3);
        return std::any_of(first, words.begin() + static_cast<std::ptrdiff_t>(w), sleeps) ? "jiao4" : "";
    }
    return {};
}

}  // namespace talkface::detail

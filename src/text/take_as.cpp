#include "text/take_as.hpp"

#include "text/written_number_scan.hpp"

namespace talkface::detail {

std::string_view take_as_reading(const std::vector<std::string>& words, std::size_t w) {
    if (w < 2 || w >= words.size() || !starts_with_any(words[w], {"为", "為"})) return {};
    // The list joins 为 to what may follow it (为重 为主), but 为了 为什么 为何 are "for" and "why".
    if (starts_with_any(words[w], {"为了", "為了", "为什么", "為什麼", "为何", "為何", "为着", "為著"}))
        return {};
    for (std::size_t before = 0; before + 1 < w; ++before)
        if (words[before] == "以") return "wei2";
    return {};
}

}  // namespace talkface::detail

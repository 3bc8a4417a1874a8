#include "text/count_words.hpp"

#include "text/written_number_scan.hpp"

namespace talkface::detail {

namespace {

constexpr std::string_view kCountCharacters[] = {"一", "二", "两", "兩", "三", "四", "五", "六", "七", "八",
                                                 "九", "十", "百", "千", "万", "萬", "几", "幾", "半"};

}  // namespace

bool starts_with_count(std::string_view word) {
    return starts_with_any(word, kCountCharacters);
}

bool ends_with_count(std::string_view word) {
    return ends_with_any(word, kCountCharacters);
}

}  // namespace talkface::detail

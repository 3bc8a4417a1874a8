#include "text/count_down.hpp"

#include "text/count_words.hpp"
#include "text/written_number_scan.hpp"

namespace talkface::detail {

bool names_reciprocal(const std::vector<std::string>& words, std::size_t w) {
    if (w == 0 || w >= words.size() || !is_any_of(words[w], {"倒数", "倒數"})) return false;
    if (!ends_with_any(words[w - 1], {"的", "为", "為", "取", "求"})) return false;
    constexpr std::string_view kCountingOn[] = {"第", "计时", "計時", "秒", "天"};
    return w + 1 == words.size() ||
           !(starts_with_any(words[w + 1], kCountingOn) || starts_with_count(words[w + 1]));
}

}  // namespace talkface::detail

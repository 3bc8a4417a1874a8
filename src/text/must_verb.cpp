#include "text/must_verb.hpp"

#include "text/count_words.hpp"
#include "text/person_words.hpp"
#include "text/written_number_scan.hpp"

namespace talkface::detail {

std::string_view must_verb_reading(const std::vector<std::string>& words, std::size_t w) {
    if (w == 0 || w + 1 >= words.size() || words[w] != "得" || !is_person_word(words[w - 1])) return {};
    // What dé, "get", takes: a particle, 的 of what was got, 到, 不 of 得不到, a count or a place, or a
    // prize, which is won and never done (她得冠军了, 他得金牌了).
    constexpr std::string_view kAfterGet[] = {"了",   "过",   "過",   "着",   "著",   "的",   "到",   "不",
                                              "个",   "個",   "第",   "满",   "滿",   "冠",   "亚军", "亞軍",
                                              "季军", "季軍", "金牌", "银牌", "銀牌", "铜牌", "銅牌", "奖",
                                              "獎",   "金奖", "金獎", "银奖", "銀獎", "铜奖", "銅獎"};
    return starts_with_any(words[w + 1], kAfterGet) || starts_with_count(words[w + 1]) ? "de2" : "dei3";
}

}  // namespace talkface::detail

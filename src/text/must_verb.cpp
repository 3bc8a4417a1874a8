#include "text/must_verb.hpp"

#include "text/count_words.hpp"
#include "text/person_words.hpp"
#include "text/written_number_scan.hpp"

namespace talkface::detail {

std::string_view must_verb_reading(const std::vector<std::string>& words, std::size_t w) {
    if (w == 0 || w + 1 >= words.size() || words[w] != "得" || !is_person_word(words[w - 1])) return {};
    // What dé, "get", takes: a particle, 的 of what was got, 到, 不 of 得不到, or a count or a place.
    constexpr std::string_view kAfterGet[] = {"了", "过", "過", "着", "著", "的", "到",
                                              "不", "个", "個", "第", "满", "滿"};
    return starts_with_any(words[w + 1], kAfterGet) || starts_with_count(words[w + 1]) ? "" : "dei3";
}

}  // namespace talkface::detail

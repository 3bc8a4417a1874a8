#include "text/return_verb.hpp"

#include <algorithm>
#include <iterator>

namespace talkface::detail {

namespace {

bool is_huan(std::string_view word) {
    return word == "还" || word == "還";
}

// Whom something is given back to: 还我, 还他们. (还你 is in the phrase list already.)
bool is_person(std::string_view word) {
    constexpr std::string_view kPersons[] = {"我", "你", "他", "她", "它", "您", "我们", "你们", "他们", "她们",
                                             "我們", "你們", "他們", "她們", "咱们", "咱們", "人家", "大家"};
    return std::find(std::begin(kPersons), std::end(kPersons), word) != std::end(kPersons);
}

bool ends_with(std::string_view word, std::string_view end) {
    return word.size() >= end.size() && word.substr(word.size() - end.size()) == end;
}

// A debt, what 还 takes as the verb: 房贷 车贷 外债 欠债 (还贷 还债 are in the phrase list).
bool is_debt(std::string_view word) {
    return word.size() > std::string_view("贷").size() &&
           (ends_with(word, "贷") || ends_with(word, "貸") || ends_with(word, "债") || ends_with(word, "債"));
}

}  // namespace

std::string_view return_verb_reading(const std::vector<std::string>& words, std::size_t w, bool ends_clause) {
    if (w >= words.size()) return {};
    // 还不 is a word of the list (还不快走); before a second 还 it is the verb's question.
    if ((words[w] == "还不" || words[w] == "還不") && w + 1 < words.size() && words[w + 1].rfind(words[w].substr(0, 3), 0) == 0)
        return "huan2";
    if (!is_huan(words[w])) return {};
    if (w + 1 == words.size()) return ends_clause ? "huan2" : "";
    const auto& next = words[w + 1];
    if (is_person(next) || is_debt(next)) return "huan2";
    // 还不还: the verb asked yes or no; the adverb is never repeated so.
    if (next == "不" && w + 2 < words.size() && is_huan(words[w + 2])) return "huan2";
    return {};
}

}  // namespace talkface::detail

#include "text/return_verb.hpp"

#include <algorithm>
#include <iterator>

#include "text/aspect_particle.hpp"
#include "text/person_words.hpp"
#include "text/written_number_scan.hpp"

namespace talkface::detail {

namespace {

bool is_huan(std::string_view word) {
    return word == "还" || word == "還";
}

// A debt, what 还 takes as the verb: 房贷 车贷 外债 欠债 (还贷 还债 are in the phrase list), money
// owed (贷款), and what is paid back as a debt is (信用卡, 花呗, 利息, 本金, 人情).
bool is_debt(std::string_view word) {
    constexpr std::string_view kOwed[] = {"贷款", "貸款", "信用卡", "花呗", "花唄", "利息", "本金", "人情"};
    if (std::find(std::begin(kOwed), std::end(kOwed), word) != std::end(kOwed)) return true;
    return word.size() > std::string_view("贷").size() && ends_with_any(word, {"贷", "貸", "债", "債"});
}

// A complement of result after the verb 还 (还上 还完 还回 还清): paid up, paid off, given back.
bool is_complement(std::string_view word) {
    constexpr std::string_view kComplements[] = {"上", "完", "回", "清"};
    return std::find(std::begin(kComplements), std::end(kComplements), word) != std::end(kComplements);
}

}  // namespace

std::string_view return_verb_reading(const std::vector<std::string>& words, std::size_t w, bool ends_clause) {
    if (w >= words.size()) return {};
    // 还不 is a word of the list (还不快走); before a second 还 it is the verb's question.
    if ((words[w] == "还不" || words[w] == "還不") && w + 1 < words.size() &&
        starts_with(words[w + 1], std::string_view(words[w]).substr(0, std::string_view("还").size())))
        return "huan2";
    if (!is_huan(words[w])) return {};
    if (w + 1 == words.size()) return ends_clause ? "huan2" : "";
    const auto& next = words[w + 1];
    // Whom something is given back to: 还我, 还他们. (还你 is in the phrase list already.)
    if (is_person_word(next) || is_debt(next)) return "huan2";
    // 把钱还上, 早点还完吧: a complement ending the clause (a final particle after it), or before 了. (还上学, 还完成 are other words.)
    const bool closes = w + 2 == words.size()
                            ? ends_clause
                            : words[w + 2] == "了" || (w + 3 == words.size() && ends_clause && is_final_particle(words[w + 2]));
    if (is_complement(next) && closes) return "huan2";
    // 完了 上了 are words of the list: the complement with its 了.
    if (next.size() > std::string_view("了").size() && ends_with(next, "了") &&
        is_complement(std::string_view(next).substr(0, next.size() - std::string_view("了").size())))
        return "huan2";
    // 还不还: the verb asked yes or no; the adverb is never repeated so.
    if (next == "不" && w + 2 < words.size() && is_huan(words[w + 2])) return "huan2";
    return {};
}

}  // namespace talkface::detail

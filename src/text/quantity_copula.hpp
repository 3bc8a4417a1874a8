// 为 (為) alone between a quantity's noun and its value is the copula wéi, "is": 失业率为3.9%,
// 浓度为每立方米35微克, 气温为零下5度. The table reads 为 alone as wèi, "for", which its commonest words
// take (为了 因为), and the phrase list joins 为 to a quantity's last character only in a few words
// (率为 值为 价为), so a cut that keeps the noun whole (失业率 为) left it wèi. A quantity's noun ends in
// 率 度 值 价 量 额 温 速 重, or in 润 入 数 积 差 压 高, a report's sums, counts and measures
// (净利润为15.8亿元, 收入为 人数为 得票数为 面积为 温差为 血压为 身高为); its value is a number: a written
// one right after 为 (the run ends there), or a word a count, 每, 约, 负 or 零 starts (the list's 为每 joins
// them). A share closing its clause right after 为 is a value after any noun (对手为45.1%, 男性为52%).
// docs/written-forms.md ("Words and polyphonic characters") lists the rules.
#ifndef TALKFACE_TEXT_QUANTITY_COPULA_HPP
#define TALKFACE_TEXT_QUANTITY_COPULA_HPP

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace talkface::detail {

// "wei2" where words[w] is 为 or 為, alone or starting a word the value starts after it (为每), after
// a quantity's noun and before its value, as above;
// or 为 alone ending the run before a share that closes its clause (`written_after`: the text after
// the run); empty elsewhere. `words` is a run of Chinese characters cut into words; `ends_clause`: a
// pause or an end mark follows the run, so what follows its last word is no written number.
std::string_view quantity_copula_reading(const std::vector<std::string>& words, std::size_t w,
                                         bool ends_clause, std::string_view written_after = {});

}  // namespace talkface::detail

#endif

// 为 (為) after 以 and what it takes is wéi, "as": 以X为Y, "take X as Y" (一切以安全为重,
// 我们以他为榜样, 以经济建设为中心), whether 为 stands alone or the list joins it to what follows (为重
// 为主). The table reads 为 alone as wèi, "for", which its commonest words take (为了 因为), and the
// phrase list holds only the set phrases (以人为本 以此为例). 以 must stand as a word of
// its own earlier in the run: 可以 所以 以为 以便 are words the list cuts whole, and 可以为你做饭 keeps wèi.
// 为 right after a verb that chooses, appoints or names is wéi too, "as" (他当选为主席, 被评选为优秀教师,
// 被任命为校长, 被认定为工伤), as the list's own 选为 评为 聘为 称为 are: a word the list cuts whole (当选
// 评选) left 为 alone. Not after any word whose last character makes a wéi word of the list with 为:
// 银行为 本人为 可以为 are "for".
// docs/written-forms.md ("Words and polyphonic characters") lists the rules.
#ifndef TALKFACE_TEXT_TAKE_AS_HPP
#define TALKFACE_TEXT_TAKE_AS_HPP

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace talkface::detail {

// "wei2" where words[w] is 为 or 為, alone or starting a word the list joins it to (为重 为主; not 为了
// 为什么 为何 为着), and a word before it in the run is 以 alone, or the word right before it chooses or
// names (ends in 选; 任命 命名 提名 认定 ...); empty elsewhere.
// `words` is a run of Chinese characters cut into words.
std::string_view take_as_reading(const std::vector<std::string>& words, std::size_t w);

}  // namespace talkface::detail

#endif

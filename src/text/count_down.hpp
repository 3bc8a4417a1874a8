// 倒数 is the verb dào shǔ, counting down or from the end (倒数第二, 倒数三秒, 与民众一同倒数), as the phrase
// list reads it (tools/phrase_additions.tsv), and the Xiandai Hanyu Cidian gives the verb first; the
// reciprocal of maths, the noun dàoshù, stands where a noun does: after 的 (五的倒数是五分之一), 为 (互为
// 倒数), 取 or 求 (取倒数), unless what follows counts from the end or down (他的倒数第一, 我们的倒数计时).
// docs/written-forms.md ("Words and polyphonic characters") lists the rules.
#ifndef TALKFACE_TEXT_COUNT_DOWN_HPP
#define TALKFACE_TEXT_COUNT_DOWN_HPP

#include <cstddef>
#include <string>
#include <vector>

namespace talkface::detail {

// Whether words[w] is 倒数 (倒數) the reciprocal, as above: its 数 is shu4, not the list's shu3.
// `words` is a run of Chinese characters cut into words.
bool names_reciprocal(const std::vector<std::string>& words, std::size_t w);

}  // namespace talkface::detail

#endif

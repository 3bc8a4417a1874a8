// 冲 (衝) said of a smell, a drink or a manner, strong or blunt, is chòng, an adjective: an adverb of
// degree stands right before it (太冲了 很冲 那么冲 有点冲), where the verb chōng, to rush or to rinse,
// is never graded so; the table's chōng, 冲 alone's reading, stays where anything but the clause's end or
// a final particle follows (那么冲过去: the verb, going somewhere). 冲动 冲向 are words of their own.
// docs/written-forms.md ("Words and polyphonic characters") lists the rules.
#ifndef TALKFACE_TEXT_DEGREE_ADJECTIVE_HPP
#define TALKFACE_TEXT_DEGREE_ADJECTIVE_HPP

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace talkface::detail {

// "chong4" where words[w] is 冲 or 衝 alone (or the list's 冲了) after a word ending in a degree adverb (太
// 很 挺 真 那么 这么 有点 有些 特别 非常 ...) and last in its run or before 了 的 啊 吧 啦 呀 alone; empty
// elsewhere. `words` is a run of Chinese characters cut into words.
std::string_view degree_adjective_reading(const std::vector<std::string>& words, std::size_t w);

}  // namespace talkface::detail

#endif

// 地 and 假 alone where what stands before them makes them nouns: 地 is the ground or the place, dì,
// after a demonstrative or a measure word of land (该地 此地 这块地 一片地 三亩地): the particle de5, the
// table's reading of 地 alone, follows an adjective or an adverb (慢慢地 认真地) and never those; a
// measure word said twice (一片片地 一块块地) makes the adverb, and keeps de5. 假 is the leave, jià,
// after a span counted (请了三天假 放两周假), where the table's jiǎ (假的, 真假) is "false". 觉 alone after
// 睡 and what is said of the sleep (睡不着觉 睡了个觉 睡大觉) is the sleep, jiào, where the table's jué is
// the feeling of its words (觉得 感觉 不知不觉).
// docs/written-forms.md ("Words and polyphonic characters") lists the rules.
#ifndef TALKFACE_TEXT_COUNTED_NOUN_HPP
#define TALKFACE_TEXT_COUNTED_NOUN_HPP

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace talkface::detail {

// "di4" where words[w] is 地 alone after a word ending in 该 此 这 那 某 块 片 亩 (and their Traditional
// forms) not said twice; "jia4" where it is 假 alone after a word a count starts and 天 日 周 月 or 星期
// ends (三天 两周 几个星期); "jiao4" where it is 觉 (覺) alone with a word holding 睡 among the three
// before it; empty elsewhere. `words` is a run of Chinese characters cut into words.
std::string_view counted_noun_reading(const std::vector<std::string>& words, std::size_t w);

}  // namespace talkface::detail

#endif

// 长 (長) the head zhang3 of the place or body the word before it names, where the cut into words
// splits the title: 台北市长 is cut 台北市 长 (the phrase list's 台北市 and 长 cost less than 台北 and
// 市长), 广东省长 广东省 长, so 长 stands alone and takes its first reading, the adjective chang2. A
// place or a body is never called long by a 长 alone right after it, so there it heads it, as in the
// list's own 市长 省长 局长 校长; a word 长 starts keeps its reading (北京市 长安街, 城市 长年).
// docs/written-forms.md ("Words and polyphonic characters") lists the rules.
#ifndef TALKFACE_TEXT_TITLE_HEAD_HPP
#define TALKFACE_TEXT_TITLE_HEAD_HPP

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace talkface::detail {

// "zhang3" where words[w] is 长 or 長 alone and words[w - 1], of two characters or more, ends in a
// place or a body a head of it is named after (市 省 县 区 镇 乡 村 州, 局 部 厅 处 科 院 校 所 厂 社
// 团 队 组 站 馆 会 司, and their Traditional forms); empty elsewhere. `words` is a run of Chinese
// characters cut into words.
std::string_view title_head_reading(const std::vector<std::string>& words, std::size_t w);

}  // namespace talkface::detail

#endif

// A polyphonic character the cut leaves alone, whose words carry one reading and the character alone
// another: 种 and 只 are measure words after a count or a demonstrative (三种 这种 两只 那只: zhǒng,
// zhī), 只 after a written number too (2只猫, and the list's 只猫 joined there), and 种 is the verb
// zhòng after anything else in its run (爷爷种了几棵树); first in a run, where a written number may
// count it (3种, 第3种), it keeps the measure word's reading. 教 alone is the verb jiāo (老师教我们语文),
// jiào being the reading of its words (教育 教师 请教), and 切 alone is the verb qiē (切薄片), qiè being
// its words' (一切 亲切), the adverb's before a warning (切不可 切勿) and names' before 尔 (切尔西). 撒 alone
// before how much or what a cook strews or where it lands (点 些 少许 一 上 入 在, 盐 糖 葱 芝麻 胡椒 粉) is
// sǎ (撒葱花 撒点盐 撒在), sā being the table's, of its words (撒网 撒手 撒谎) and names (撒哈拉). 量 alone
// before a count of times, an aspect particle or a body's measure (一 了 过 着 体温 血压 身高 体重 尺寸 腰围)
// is the verb liáng (每天各量一次血压, 量了体温), liàng being the amount's, and 量 after 的 (这批货的量). The
// table reads each character alone by its commonest reading in running text, the words' (zhong3, zhi3, jiao4,
// qie4, sa1, liang4). docs/written-forms.md ("Words and polyphonic characters") lists the rules.
#ifndef TALKFACE_TEXT_MEASURE_OR_VERB_HPP
#define TALKFACE_TEXT_MEASURE_OR_VERB_HPP

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace talkface::detail {

// The reading of words[w] where it is 教 (教) or 种 (種) alone, 只 alone after a count or a
// demonstrative, 量 alone before what it measures, 切 alone, or 撒 alone before what it strews; empty
// elsewhere. `words` is a run of Chinese characters
// cut into words; `follows_number`: a written number ends right where the run starts (2只猫: 两 counts 只).
std::string_view measure_or_verb_reading(const std::vector<std::string>& words, std::size_t w,
                                         bool follows_number = false);

}  // namespace talkface::detail

#endif

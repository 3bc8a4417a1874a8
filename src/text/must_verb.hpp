// 得 the verb děi, "must", where a cut into words leaves it alone after whom it binds (我们得赶紧走,
// 大家得注意): the table reads 得 alone as the particle de5, which follows a verb or an adjective
// (跑得快) and never a pronoun. After a person 得 is děi unless what follows makes it dé, "get": 了 过
// 着 的 (他得了第一名, 我得过奖, 他得的是感冒), 到 (得到), a count (他得一百分, 得第一, 得个奖) or a prize
// (她得冠军了, 他得金牌了), a written one too (他得100分): there it is dé, which the table's de5 is not.
// 得 before 多 or 少 and a verb of a little more or less (这道菜得多放点盐) is děi after anyone. The
// words the phrase list joins to 得 after an adverb (还得 也得 ...) are read by the list; its 你得 and 我得
// are cut (aspect_particle.hpp), so 得 stands alone there too. docs/written-forms.md
// ("Words and polyphonic characters") lists the rules.
#ifndef TALKFACE_TEXT_MUST_VERB_HPP
#define TALKFACE_TEXT_MUST_VERB_HPP

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace talkface::detail {

// "dei3" where words[w] is 得 alone, words[w - 1] names a person (person_words.hpp) and a word of
// the run follows that does not start as above, "de2" where one that does follows; where 得 ends the
// run before a written number, `written_after`, "de2", or "dei3" if a time or a span follows the number
// (他得100分, 我得5点起床). "dei3" too where 得 (or the list's 得多 得少) is followed by 多 or 少, a
// verb and 点 or 些, whoever is before it (这道菜得多放点盐). Empty elsewhere. `words` is a run of
// Chinese characters cut into words.
std::string_view must_verb_reading(const std::vector<std::string>& words, std::size_t w,
                                   std::string_view written_after = {});

}  // namespace talkface::detail

#endif

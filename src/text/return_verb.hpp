// 还 (還) the verb huan2, "give back", where a cut into words cannot tell it from the adverb hai2
// ("still"): the adverb modifies what follows it, a verb or an adjective, so 还 is the verb where
// nothing follows it in its clause (借了要按时还), where it is asked as 还不还, and before a
// person it is given back to (还我钱, 还你一个公道) or a debt (还房贷, 还贷款, 还信用卡), and with a
// complement that closes its clause (把钱还上, 还完了). The words the
// phrase list reads (还钱 还给 还款 还书 ...) and 还 before the particle 了 (aspect_particle.hpp)
// are read elsewhere. docs/written-forms.md ("Words and polyphonic characters") lists the rules.
#ifndef TALKFACE_TEXT_RETURN_VERB_HPP
#define TALKFACE_TEXT_RETURN_VERB_HPP

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace talkface::detail {

// "huan2" where the 还 or 還 that starts words[w] is the verb (a word of its own, or 还不 before
// another 还); empty elsewhere. `words`
// is a run of Chinese characters cut into words; `ends_clause` says that the run is followed by
// a pause or end mark, or ends the text (not by a number or a Latin word: 还500元).
std::string_view return_verb_reading(const std::vector<std::string>& words, std::size_t w, bool ends_clause);

}  // namespace talkface::detail

#endif

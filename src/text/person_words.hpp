// The words that name a person as a pronoun does (我 你 他们 咱们 人家 大家), Simplified and
// Traditional: to whom a verb gives something back (还我), and who must do something (我们得走).
#ifndef TALKFACE_TEXT_PERSON_WORDS_HPP
#define TALKFACE_TEXT_PERSON_WORDS_HPP

#include <string_view>

namespace talkface::detail {

bool is_person_word(std::string_view word);

}  // namespace talkface::detail

#endif

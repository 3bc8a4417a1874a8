// The aspect particle 了 after a verb, which a cut into words by word frequencies alone cannot
// see: the verb before it decides both the cut (看了 解说, not 看 了解 说) and the reading of
// 还 (还了 huan2 le5, "returned": the adverb hai2 modifies a verb and never takes 了 itself).
// docs/written-forms.md ("Words and polyphonic characters") lists the rules.
#ifndef TALKFACE_TEXT_ASPECT_PARTICLE_HPP
#define TALKFACE_TEXT_ASPECT_PARTICLE_HPP

#include <cstddef>
#include <string_view>
#include <vector>

#include "text/reading_tables.hpp"

namespace talkface::detail {

// False where the word characters[start, end) starts with 了 (了解, 了结) right after a
// one-character verb that takes an object and 了 (看 听 做 写 ...), and its last character
// starts a word with the character after it (解说, 解释, 解决): there 了 is the particle, the verb's
// (看了解说 看了 解说, 听了解释 听了 解释). Elsewhere 了解 stays a word (去了解, 想了解, 很了解).
bool may_start_word_here(const std::vector<std::string_view>& characters, std::size_t start, std::size_t end,
                         const ReadingTables& tables);

// The reading of `word` when the next two characters of the run are `next` and `after_next`
// (empty past its end), where the particle decides it: huan2 for 还 (還) before 了, except in the
// idiom 还了得 ("how outrageous", hai2 liao3 de2). Empty elsewhere. The caller passes `next`
// only where 了 is a word of its own: 还了解 (了解 a word) keeps the adverb.
std::string_view reading_before_particle(std::string_view word, std::string_view next, std::string_view after_next);

}  // namespace talkface::detail

#endif

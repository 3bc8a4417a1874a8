// The aspect particle 了 after a verb, which a cut into words by word frequencies alone cannot
// see: the verb before it decides both the cut (看了 解说, not 看 了解 说) and the reading of
// 还 (还了 huan2 le5, "returned": the adverb hai2 modifies a verb and never takes 了 itself).
// And 了 that is not the particle: the idioms 还了得 and 还得了 ("how can this be tolerated"),
// said so only where they end a clause (这还了得！), and 得 "must", which never takes 了.
// docs/written-forms.md ("Words and polyphonic characters") lists the rules.
#ifndef TALKFACE_TEXT_ASPECT_PARTICLE_HPP
#define TALKFACE_TEXT_ASPECT_PARTICLE_HPP

#include <cstddef>
#include <string_view>
#include <vector>

#include "text/reading_tables.hpp"

namespace talkface::detail {

// True for a particle that closes a clause after what it says (吗 啊 吧 呢 ...: 这还得了吗, 早点还上吧).
bool is_final_particle(std::string_view character);

// False where the word characters[start, end) starts with 了 (了解, 了结) right after a
// one-character verb that takes an object and 了 (看 听 做 写 ...), and its last character
// starts a word with the character after it (解说, 解释, 解决): there 了 is the particle, the verb's
// (看了解说 看了 解说, 听了解释 听了 解释). Elsewhere 了解 stays a word (去了解, 想了解, 很了解).
// Also false for the idioms 还了得 and 还得了 (還了得 還得了) where they do not end the clause
// (`ends_clause`: the run is followed by a pause or end mark or ends the text; a final particle
// such as 吗 啊 may follow the idiom inside the run): 他还了得到的钱 is 还 了 得到, 他还得了第一名
// 还 得了. And false for 还得 (hai2 dei3, "still must") right before 了: 得 "must" never takes 了,
// so there 得 is the verb de2, "get" (还得了奖). And false for the list's 你得 and 我得: a person and 得,
// děi or dé by what follows (must_verb.hpp).
bool may_start_word_here(const std::vector<std::string_view>& characters, std::size_t start, std::size_t end,
                         const ReadingTables& tables, bool ends_clause);

// The reading of `word` when the next character of the run is `next` (empty past its end), where
// the particle decides it: huan2 for 还 (還) before 了 (the idiom 还了得, hai2 liao3 de5, is a word
// of its own where it stands), and de2 for 得 before 了: the particle de5 never takes 了, so 得
// there is the verb "get" (他还得了第一名, 得了感冒) or "enough" (得了，别说了), dé·le in the
// Xiandai Hanyu Cidian (a potential complement, 受得了 shou4 de5 liao3, is a word of the table).
// Empty elsewhere. The caller passes `next` only where 了 is a word of its own: 还了解 (了解 a
// word) keeps the adverb.
std::string_view reading_before_particle(std::string_view word, std::string_view next);

// True where characters[i] is the 得 of a potential complement 得了 (de5 liao3, "able to"): right
// after a one-character verb (吃得了吗, 我还走得了, 搬得了, 来得了), cut as 得了, 得 了 or the verb's
// 吃得 and 了 (`lengths`: the run's words). Not after an adverb or a subject (他还得了第一名, 他得了
// 感冒: the verb de2, reading_before_particle) nor inside a longer word (记得了, 获得了: 了 the particle).
bool is_potential_complement(const std::vector<std::string_view>& characters, const std::vector<std::size_t>& lengths,
                             std::size_t i);

}  // namespace talkface::detail

#endif

// 中 after a count of shots taken and a count of them made is zhòng, "hit": a box score writes a
// player's shooting as the attempts, 投 (or 罚 for free throws), and the makes (三分球12投7中, 6罚5中),
// where the table reads 中 alone as zhōng, "middle", the reading of its words (中国 其中). A number alone
// before 中 stays a school's or a middle's (七中, 3中). docs/written-forms.md ("Words and polyphonic
// characters") lists the rule.
#ifndef TALKFACE_TEXT_SHOTS_MADE_HPP
#define TALKFACE_TEXT_SHOTS_MADE_HPP

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace talkface::detail {

// Whether `before_run`, a sentence's text up to where a run of Chinese characters starts, ends with a
// count of attempts: digits, 投 罚 or 罰, and `number`, the written number right before the run.
bool follows_attempts(std::string_view before_run, std::string_view number);

// "zhong4" where words[w] is 中 alone, first in a run that follows a count of attempts as above
// (`after_attempts`); empty elsewhere.
std::string_view shots_made_reading(const std::vector<std::string>& words, std::size_t w,
                                    bool after_attempts);

}  // namespace talkface::detail

#endif

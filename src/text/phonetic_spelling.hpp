// A word's pronunciation written in the International Phonetic Alphabet inside brackets or slashes after it,
// as an English lesson or a dictionary prints it (apple [ˈæpl], /ˈæpl/): no speech of its own.
#ifndef TALKFACE_TEXT_PHONETIC_SPELLING_HPP
#define TALKFACE_TEXT_PHONETIC_SPELLING_HPP

#include <cstddef>
#include <optional>
#include <vector>

#include "text/code_points.hpp"

namespace talkface::detail {

// Where a phonetic spelling that opens at text[start] ([ or /) ends, past its closing mark, or nullopt: the
// marks hold letters, IPA's symbols, stress and length marks and spaces only, one of them a sign only IPA
// writes (æ ə ɪ ʃ ˈ ː ...). A teacher reads the word, not its spelling, so the reader keeps it in the
// sentence's text unsaid and unwarned, as a subtitle's timing (session 33: the letters it shares with the
// alphabet were read, pl pi ai le, and the rest warned of).
std::optional<std::size_t> past_phonetic_spelling(const std::vector<CodePoint>& text, std::size_t start);

}  // namespace talkface::detail

#endif

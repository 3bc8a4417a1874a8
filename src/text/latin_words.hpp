// Latin letters and English words in a Mandarin transcript, said as Mandarin speakers say them:
// an acronym letter by letter with the letter names of docs/letter-names.md (AI ei ai, USB you ai
// si bi), an English word by the CMU pronouncing dictionary mapped onto Mandarin syllables
// (tools/make_english.py: iPhone ai feng, OK ou kei).
#ifndef TALKFACE_TEXT_LATIN_WORDS_HPP
#define TALKFACE_TEXT_LATIN_WORDS_HPP

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace talkface::detail {

// The numbered-pinyin syllables of ASCII letters said one by one ("CEO" -> xi1 yi4 ou1).
// Letters other than A-Z and a-z are not letters here and throw an internal error.
std::vector<std::string> letter_syllables(std::string_view letters);

// The syllables of an English word (ASCII letters, any case; "iPhone", "wifi"), or nullopt if
// the dictionary does not have it.
std::optional<std::vector<std::string>> english_word_syllables(std::string_view word);

// Every line of the English table, "word\tsyl1 syl2", sorted by word (for the lookup, and for a
// test that checks every reading).
const std::vector<std::string_view>& english_lines();

}  // namespace talkface::detail

#endif

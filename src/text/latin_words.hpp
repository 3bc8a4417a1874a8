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

#include "text/sorted_lines.hpp"

namespace talkface::detail {

// The numbered-pinyin syllables of ASCII letters said one by one ("CEO" -> xi1 yi4 ou1).
// Letters other than A-Z and a-z are not letters here and throw an internal error.
std::vector<std::string> letter_syllables(std::string_view letters);

// The syllables of a name a number follows (Cas of Cas9) that the dictionary lacks, or nullopt.
std::optional<std::vector<std::string>> name_before_number_syllables(std::string_view word);

// The syllables of an English word (ASCII letters, any case; "iPhone", "wifi"), or nullopt if
// the dictionary does not have it.
std::optional<std::vector<std::string>> english_word_syllables(std::string_view word);

// A word the dictionary lacks, made of a consonant letter and a word it has, where the letter starts
// no English syllable with the one after it (Gmail's gm, Xbox's xb, vlog's vl): the letter's name and
// the word's syllables (Gmail ji4 mei4 er5), as Mandarin speakers say a brand so made; nullopt where
// the word is not so made.
std::optional<std::vector<std::string>> letter_and_word_syllables(std::string_view word);

// True where the dictionary's syllables for `word` say more than its letters would (etc ai te sai te e, et
// cetera): an abbreviation the dictionary expands, which a name typed in a path or an address is not (/etc/
// hosts: E T C, as presenters spell it; session 33: et cetera).
bool expands_abbreviation(std::string_view word, const std::vector<std::string>& syllables);

// Where a word the dictionary lacks is two words at an h after a consonant: the h's index where the letters
// before it hold a vowel and from the h on the dictionary has a word of three letters or more (github: git
// hub; spelled, the h went with the t, gi thub); nullopt elsewhere.
std::optional<std::size_t> word_after_h(std::string_view word);

// `word` as two words the dictionary has, each `shortest_part` letters or more, cut where the two are nearest
// in length and, among those, with the longer first part (Facebook face book, Photoshop photo shop, not
// photos hop): their syllables, or nullopt.
std::optional<std::vector<std::string>> two_word_syllables(std::string_view word, std::size_t shortest_part);

// A word in capitals the dictionary lacks, made of two words it has of three letters or more (BLACKPINK black
// pink; the most even cut), or of one to three letters and a word of four letters or more (TFBOYS T F boys):
// the letters' names and the words' syllables; nullopt where it is neither.
std::optional<std::vector<std::string>> capitals_of_words(std::string_view word);

// The syllables of a number said in English, as Mandarin speakers say No.1 (number one): 0 to 99
// as English number words (twelve, forty two), a longer number digit by digit (one oh one).
// `digits` are ASCII 0-9, at least one.
std::vector<std::string> english_number_syllables(std::string_view digits);

// True for a word of ASCII capitals only (CEO, NASA), false for an empty one.
bool is_all_capitals(std::string_view word);

// True for a word with two or more capitals after a small letter (iOS, macOS): an acronym inside
// a word, said letter by letter, not as the dictionary's word.
bool has_inner_acronym(std::string_view word);

// True where a word in capitals is said as a word, not letter by letter (COVID, SARS, TOP, MAX):
// the words Mandarin speakers say their own way, and English words written in capitals for a
// product, a game or a rank.
bool is_said_as_word(std::string_view word);

// A word nothing here reads (Zorblax), cut where its spelling puts syllables: one per group of
// vowels (y among them after a consonant), a final silent e not counted, each cut before the
// consonant that starts the next syllable, or before two that usually start one together (bl,
// st, th ...): Zor blax. Empty if it has no vowel (Xkcd), which no one says as a word.
std::vector<std::string> spelled_syllables(std::string_view word);

// The English table, "word\tsyl1 syl2" sorted by word (for the lookup, and for a test that
// checks every reading).
const SortedLines& english_lines();

}  // namespace talkface::detail

#endif

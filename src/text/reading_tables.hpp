// The character, phrase and syllable tables of the transcript reader, parsed once from the
// embedded text (embedded_text.hpp) on first use.
#ifndef TALKFACE_TEXT_READING_TABLES_HPP
#define TALKFACE_TEXT_READING_TABLES_HPP

#include <cstddef>
#include <string>
#include <string_view>
#include <unordered_map>
#include <unordered_set>
#include <vector>

namespace talkface::detail {

// A word of the phrase list (tools/make_phrases.py), one character or more.
struct Word {
    // -ln P(word) in hundredths: what the word costs a cut of the text into words
    // (word_segmentation.hpp).
    int cost = 0;
    // One numbered reading per character where the word settles a polyphonic character (首都
    // shou3 du1); empty where each character takes its first reading.
    std::vector<std::string_view> readings;
};

struct ReadingTables {
    // UTF-8 character -> its readings in numbered pinyin, most frequent first.
    std::unordered_map<std::string_view, std::vector<std::string_view>> character_readings;
    // UTF-8 word -> its cost and readings.
    std::unordered_map<std::string_view, Word> words;
    std::size_t longest_word_characters = 0;
    // The cost of a character the phrase list lacks: that of its rarest one-character word.
    int unknown_character_cost = 0;
    std::unordered_set<std::string_view> toneless_syllables;
};

// The tables, built on first call; views point into the embedded text, which lives as long as
// the program. Thread-safe: a function-local static.
const ReadingTables& reading_tables();

// Lowercases and normalises a pinyin syllable with an optional tone digit: "Lü4", "lu:4" and
// "lue4" become "lv4", "jv" becomes "ju"; no tone gives tone 5. Returns "" if the result is not
// a legal syllable with tone 1-5.
std::string normalise_pinyin(std::string_view written);

}  // namespace talkface::detail

#endif

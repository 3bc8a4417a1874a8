// The character, phrase and syllable tables of the transcript reader, searched in place in the
// embedded text (embedded_text.hpp, sorted_lines.hpp), indexed once on first use.
#ifndef TALKFACE_TEXT_READING_TABLES_HPP
#define TALKFACE_TEXT_READING_TABLES_HPP

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "text/sorted_lines.hpp"

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

class ReadingTables {
public:
    ReadingTables();

    // Whether the UTF-8 character has a reading: what makes it a Han character to the reader.
    bool has_readings(std::string_view character) const { return characters_.find(character).has_value(); }
    // Its readings in numbered pinyin, most frequent first; empty if it has none.
    std::vector<std::string_view> readings(std::string_view character) const;

    // The UTF-8 word's cost and readings, if the phrase list has it. Throws an internal error for a
    // line of the list that is not "word\tcost" or "word\tcost\treadings" (one per character).
    std::optional<Word> word(std::string_view word) const;
    // The most characters a word of the phrase list has.
    std::size_t longest_word_characters() const { return longest_word_characters_; }
    // The cost of a character the phrase list lacks: that of its rarest one-character word.
    int unknown_character_cost() const { return unknown_character_cost_; }

    // Whether a lowercase toneless syllable ("lv", "zhuang") is one Mandarin has.
    bool is_toneless_syllable(std::string_view letters) const { return syllables_.find(letters).has_value(); }

    // The tables' lines, for checks over every entry.
    const SortedLines& character_lines() const { return characters_; }
    const SortedLines& word_lines() const { return words_; }
    const SortedLines& syllable_lines() const { return syllables_; }

private:
    SortedLines characters_;
    SortedLines words_;
    SortedLines syllables_;
    std::size_t longest_word_characters_ = 0;
    int unknown_character_cost_ = 0;
};

// The tables, indexed on first call; views point into the embedded text, which lives as long as
// the program. Thread-safe: a function-local static.
const ReadingTables& reading_tables();

// Lowercases and normalises a pinyin syllable with an optional tone digit: "Lü4", "lu:4" and
// "lue4" become "lv4", "jv" becomes "ju"; no tone gives tone 5. Returns "" if the result is not
// a legal syllable with tone 1-5.
std::string normalise_pinyin(std::string_view written);

}  // namespace talkface::detail

#endif

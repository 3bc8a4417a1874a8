#include "text/reading_tables.hpp"

#include <algorithm>

#include "common/internal_error.hpp"
#include "text/embedded_text.hpp"
#include "talkface/errors.hpp"

namespace talkface::detail {

namespace {

std::size_t count_characters(std::string_view utf8) {
    return static_cast<std::size_t>(std::count_if(utf8.begin(), utf8.end(), [](char byte) {
        return (static_cast<unsigned char>(byte) & 0xC0U) != 0x80U;
    }));
}

// "cost" or "cost\treadings" after a word of the phrase list. The generator guarantees the shape,
// so another is a build of mismatched files, not a user error.
Word parse_word(std::string_view word, std::string_view value) {
    const auto line = [&] { return "phrase table line \"" + std::string(word) + "\t" + std::string(value) + "\""; };
    const auto cost = SortedLines::key_of(value);
    const auto readings = SortedLines::value_of(value);
    const bool is_number = !cost.empty() && cost.size() < 7 &&
                           std::all_of(cost.begin(), cost.end(), [](char c) { return c >= '0' && c <= '9'; });
    if (!is_number || readings.find('\t') != std::string_view::npos) {
        throw internal_error(line() + " is not word, cost, readings");
    }
    Word entry;
    for (const char digit : cost) entry.cost = entry.cost * 10 + (digit - '0');
    if (!readings.empty()) entry.readings = split_words(readings);
    const auto characters = count_characters(word);
    if (!entry.readings.empty() && entry.readings.size() != characters) {
        throw internal_error(line() + " has " + std::to_string(entry.readings.size()) + " readings for " +
                             std::to_string(characters) + " characters");
    }
    return entry;
}

}  // namespace

ReadingTables::ReadingTables()
    : characters_(readings_text()), words_(phrases_text()), syllables_(syllables_text()) {
    for (const auto line : words_.lines()) {
        const auto word = SortedLines::key_of(line);
        const auto characters = count_characters(word);
        longest_word_characters_ = std::max(longest_word_characters_, characters);
        if (characters == 1) {
            unknown_character_cost_ = std::max(unknown_character_cost_, parse_word(word, SortedLines::value_of(line)).cost);
        }
    }
}

std::vector<std::string_view> ReadingTables::readings(std::string_view character) const {
    const auto found = characters_.find(character);
    return found ? split_words(*found) : std::vector<std::string_view>();
}

std::optional<Word> ReadingTables::word(std::string_view word) const {
    const auto found = words_.find(word);
    if (!found) return std::nullopt;
    return parse_word(word, *found);
}

const ReadingTables& reading_tables() {
    static const ReadingTables tables;
    return tables;
}

std::string normalise_pinyin(std::string_view written) {
    std::string letters;
    char tone = '5';
    for (std::size_t i = 0; i < written.size(); ++i) {
        const char byte = written[i];
        if (byte >= 'A' && byte <= 'Z') {
            letters += static_cast<char>(byte - 'A' + 'a');
        } else if (byte >= 'a' && byte <= 'z') {
            letters += byte;
        } else if (byte == ':' && !letters.empty() && letters.back() == 'u') {
            letters.back() = 'v';
        } else if (written.substr(i, 2) == "\xC3\xBC" || written.substr(i, 2) == "\xC3\x9C") {  // ü Ü
            letters += 'v';
            ++i;
        } else if (byte >= '1' && byte <= '5' && i + 1 == written.size() && !letters.empty()) {
            tone = byte;
        } else {
            return {};
        }
    }
    // j q x y never take u-umlaut in spelling (ju = jü); lüe is often typed lue.
    if (!letters.empty() && std::string_view("jqxy").find(letters.front()) != std::string_view::npos) {
        std::replace(letters.begin(), letters.end(), 'v', 'u');
    } else if (letters == "lue" || letters == "nue") {
        letters[1] = 'v';
    }
    if (!reading_tables().is_toneless_syllable(letters)) return {};
    return letters + tone;
}

}  // namespace talkface::detail

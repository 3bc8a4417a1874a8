#include "text/reading_tables.hpp"

#include <algorithm>

#include "common/internal_error.hpp"
#include "text/embedded_text.hpp"
#include "talkface/errors.hpp"

namespace talkface::detail {

namespace {

std::vector<std::string_view> split(std::string_view text, char separator) {
    std::vector<std::string_view> parts;
    std::size_t start = 0;
    while (start <= text.size()) {
        const auto end = std::min(text.find(separator, start), text.size());
        if (end > start) parts.push_back(text.substr(start, end - start));
        start = end + 1;
    }
    return parts;
}

// Calls `visit(line)` for every line of an embedded table.
template <typename Visit>
void for_each_line(EmbeddedText text, Visit visit) {
    for (std::size_t chunk = 0; chunk < text.chunk_count; ++chunk) {
        for (const auto line : split(text.chunks[chunk], '\n')) visit(line);
    }
}

std::size_t count_characters(std::string_view utf8) {
    return static_cast<std::size_t>(std::count_if(utf8.begin(), utf8.end(), [](char byte) {
        return (static_cast<unsigned char>(byte) & 0xC0U) != 0x80U;
    }));
}

// A table line is "key\treading reading ...". The generators guarantee the shape, so a line
// without a tab is a build of mismatched files, not a user error.
std::pair<std::string_view, std::vector<std::string_view>> parse_line(std::string_view line) {
    const auto tab = line.find('\t');
    if (tab == std::string_view::npos) {
        throw internal_error("reading table line \"" +
                                             std::string(line) + "\" has no tab");
    }
    return {line.substr(0, tab), split(line.substr(tab + 1), ' ')};
}

int parse_cost(std::string_view digits, std::string_view line) {
    const bool is_number = !digits.empty() && digits.size() < 7 &&
                           std::all_of(digits.begin(), digits.end(), [](char c) { return c >= '0' && c <= '9'; });
    if (!is_number) throw internal_error("phrase table line \"" + std::string(line) + "\" has no cost");
    int cost = 0;
    for (const char digit : digits) cost = cost * 10 + (digit - '0');
    return cost;
}

ReadingTables build_tables() {
    ReadingTables tables;
    for_each_line(syllables_text(), [&](std::string_view line) { tables.toneless_syllables.insert(line); });
    for_each_line(readings_text(), [&](std::string_view line) {
        auto [character, readings] = parse_line(line);
        tables.character_readings.emplace(character, std::move(readings));
    });
    // "詞語\tcost" or "詞語\tcost\tci2 yu3".
    for_each_line(phrases_text(), [&](std::string_view line) {
        const auto fields = split(line, '\t');
        if (fields.size() < 2 || fields.size() > 3) {
            throw internal_error("phrase table line \"" + std::string(line) + "\" is not word, cost, readings");
        }
        const auto word = fields[0];
        Word entry;
        entry.cost = parse_cost(fields[1], line);
        if (fields.size() == 3) entry.readings = split(fields[2], ' ');
        const auto characters = count_characters(word);
        if (!entry.readings.empty() && entry.readings.size() != characters) {
            throw internal_error("phrase table line \"" + std::string(line) + "\" has " +
                                 std::to_string(entry.readings.size()) + " readings for " +
                                 std::to_string(characters) + " characters");
        }
        tables.longest_word_characters = std::max(tables.longest_word_characters, characters);
        if (characters == 1) tables.unknown_character_cost = std::max(tables.unknown_character_cost, entry.cost);
        tables.words.emplace(word, std::move(entry));
    });
    return tables;
}

}  // namespace

const ReadingTables& reading_tables() {
    static const ReadingTables tables = build_tables();
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
    if (reading_tables().toneless_syllables.count(letters) == 0) return {};
    return letters + tone;
}

}  // namespace talkface::detail

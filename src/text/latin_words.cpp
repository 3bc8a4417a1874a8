#include "text/latin_words.hpp"

#include <algorithm>
#include <string_view>
#include <utility>

#include "talkface/errors.hpp"
#include "text/embedded_text.hpp"

namespace talkface::detail {

namespace {

// The letter names most Mandarin speakers use (docs/letter-names.md); several take more than one
// syllable (F ai fu, W da bu liu).
const char* const kLetterNames[26] = {
    "ei1",         "bi4",      "xi1",     "di4",  "yi4",  "ai2 fu5", "ji4",     "ai1 qi1", "ai4",
    "zhei4",       "kei4",     "ai2 le5", "ai2 mu5", "en1", "ou1",  "pi1",     "qiu1",    "a4 er5",
    "ai2 si5",     "ti4",      "you1",    "wei1", "da2 bu5 liu5", "ai2 ke4 si5", "wai4", "zei4",
};

// Words Mandarin speakers say their own way, where the dictionary's mapping misses it: email is
// 伊妹儿 (the mapping of its first vowel gave "e").
constexpr std::pair<std::string_view, std::string_view> kSaidOtherwise[] = {
    {"email", "yi1 mei4 er5"},
    {"e-mail", "yi1 mei4 er5"},
};

void append_words(std::vector<std::string>& syllables, std::string_view words) {
    std::size_t start = 0;
    while (start < words.size()) {
        const auto end = std::min(words.find(' ', start), words.size());
        syllables.emplace_back(words.substr(start, end - start));
        start = end + 1;
    }
}

}  // namespace

// A binary search of the sorted lines finds a word (a map of 100k words would cost
// more memory than the text it indexes).
const std::vector<std::string_view>& english_lines() {
    static const std::vector<std::string_view> lines = [] {
        std::vector<std::string_view> result;
        const auto text = english_text();
        for (std::size_t chunk = 0; chunk < text.chunk_count; ++chunk) {
            std::string_view rest(text.chunks[chunk]);
            while (!rest.empty()) {
                const auto end = rest.find('\n');
                result.push_back(rest.substr(0, end));
                rest.remove_prefix(end == std::string_view::npos ? rest.size() : end + 1);
            }
        }
        return result;
    }();
    return lines;
}

std::vector<std::string> letter_syllables(std::string_view letters) {
    std::vector<std::string> syllables;
    for (const char letter : letters) {
        const char upper = letter >= 'a' && letter <= 'z' ? static_cast<char>(letter - 'a' + 'A') : letter;
        if (upper < 'A' || upper > 'Z') {
            throw Error(ErrorCode::internal, std::string("internal error (a bug in talkface): \"") + letter +
                                                 "\" is not a Latin letter");
        }
        append_words(syllables, kLetterNames[upper - 'A']);
    }
    return syllables;
}

std::optional<std::vector<std::string>> english_word_syllables(std::string_view word) {
    std::string key;
    for (const char letter : word) {
        key += letter >= 'A' && letter <= 'Z' ? static_cast<char>(letter - 'A' + 'a') : letter;
    }
    for (const auto& [spelled, said] : kSaidOtherwise) {
        if (key != spelled) continue;
        std::vector<std::string> syllables;
        append_words(syllables, said);
        return syllables;
    }
    const auto& lines = english_lines();
    const auto found = std::lower_bound(lines.begin(), lines.end(), key, [](std::string_view line, const std::string& k) {
        return line.substr(0, line.find('\t')) < k;
    });
    if (found == lines.end() || found->substr(0, found->find('\t')) != key) return std::nullopt;
    std::vector<std::string> syllables;
    append_words(syllables, found->substr(found->find('\t') + 1));
    return syllables;
}

}  // namespace talkface::detail

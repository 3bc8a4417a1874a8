#include "speech/latin_only_text.hpp"

#include <algorithm>
#include <vector>

#include "text/code_points.hpp"

namespace talkface::detail {

namespace {

// The words a message names before it counts the rest.
constexpr std::size_t kNamedWords = 3;

// An English word or letters as a written form's text shows them: Latin letters, with the
// apostrophes, hyphens and full stops inside a word (don't, e-mail, U.S.).
bool is_latin_word(const std::string& text) {
    bool has_letter = false;
    for (const char c : text) {
        if (is_ascii_letter(static_cast<unsigned char>(c)))
            has_letter = true;
        else if (c != '\'' && c != '-' && c != '.')
            return false;
    }
    return has_letter;
}

}  // namespace

std::optional<std::string> describe_latin_only_text(const Timeline& transcript) {
    const std::size_t count = transcript.syllables.size();
    std::vector<bool> is_guessed(count, false);
    for (std::size_t i = 0; i < count; ++i) is_guessed[i] = transcript.syllables[i].generic_speech;
    std::vector<std::string> words;
    for (const WrittenForm& form : transcript.written_forms) {
        if (!is_latin_word(form.text) || form.first_syllable >= count) continue;
        words.push_back(form.text);
        const std::size_t end = std::min(count, form.first_syllable + form.syllable_count);
        std::fill(is_guessed.begin() + static_cast<std::ptrdiff_t>(form.first_syllable),
                  is_guessed.begin() + static_cast<std::ptrdiff_t>(end), true);
    }
    if (count == 0 ||
        !std::all_of(is_guessed.begin(), is_guessed.end(), [](bool guessed) { return guessed; }))
        return std::nullopt;
    std::string named;
    for (std::size_t i = 0; i < std::min(words.size(), kNamedWords); ++i)
        named += (i > 0 ? ", " : "") + words[i];
    if (words.size() > kNamedWords) named += " and " + std::to_string(words.size() - kNamedWords) + " more";
    return "none of its " + std::to_string(count) + " syllables has a Mandarin reading: its words (" + named +
           ") are English, each read as a guess at how a Mandarin speaker says it, or fitted as any speech "
           "where no table reads it, and such guesses fit other speech about as well as the speech they "
           "stand for, so the checks cannot confirm that the audio says them";
}

}  // namespace talkface::detail

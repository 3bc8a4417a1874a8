// The transcript reader's Latin words (latin_words.hpp has the dictionary and the letters' names): which
// Latin runs are English rather than pinyin, and how a word, an acronym, a chat's initials, No.1 and a
// web address's parts are said.
#include "text/transcript_reader.hpp"

#include <algorithm>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "text/code_points.hpp"
#include "text/digit_codes.hpp"
#include "text/episode_codes.hpp"
#include "text/formula_letters.hpp"
#include "text/keyboard_keys.hpp"
#include "text/latin_words.hpp"
#include "text/number_words.hpp"
#include "text/pinyin_tokens.hpp"
#include "text/units_and_money.hpp"
#include "text/web_addresses.hpp"
#include "text/written_number_scan.hpp"
#include "text/written_numbers.hpp"

namespace talkface::detail {

namespace {

std::string toneless_of(const std::string& pinyin) {
    return pinyin.substr(0, pinyin.size() - 1);
}

}  // namespace

bool TranscriptReader::is_english_line(const std::vector<CodePoint>& text, std::size_t at) {
    const int line = text[at].line;
    if (const auto known = english_lines_.find(line); known != english_lines_.end()) return known->second;
    auto first = at;
    while (first > 0 && text[first - 1].line == line) --first;
    int pinyin_words = 0;
    int english_words = 0;
    for (auto i = first; i < text.size() && text[i].line == line;) {
        const bool starts_word =
            is_pinyin_letter(text[i].value) &&
            (i == first || !(is_pinyin_letter(text[i - 1].value) || is_ascii_digit(text[i - 1].value)));
        if (!starts_word) {
            ++i;
            continue;
        }
        const auto end = end_of_token(text, i);
        const std::vector<CodePoint> token(text.begin() + static_cast<std::ptrdiff_t>(i),
                                           text.begin() + static_cast<std::ptrdiff_t>(end));
        const auto spelling = latin_spelling(text, i, end);
        if (spelling.size() == 1 || !detail::is_all_capitals(spelling)) {
            const auto split = looks_like_pinyin(token) ? split_pinyin(token) : std::nullopt;
            const bool is_pinyin = split && (has_tone_digit(token) || !splits_into_interjection(*split));
            const bool is_english = !has_tone_digit(token) && detail::english_word_syllables(spelling);
            if (is_pinyin != is_english) ++(is_pinyin ? pinyin_words : english_words);
        }
        i = end;
    }
    return english_lines_[line] = english_words > pinyin_words;
}

std::size_t TranscriptReader::read_latin(const std::vector<CodePoint>& text, std::size_t start) {
    form_warnings_ = timeline_.warnings.size();
    auto letters_end = [&](std::size_t from) {
        while (from < text.size() && is_ascii_letter(text[from].value)) ++from;
        return from;
    };
    auto end = letters_end(start);
    if (end == start) {  // ü or Ü alone
        append_text(text[start].text);
        warn_no_reading(text[start]);
        return start + 1;
    }
    if (auto episode = detail::read_season_episode(text, start)) {  // S3E5 第三季第五集
        add_form(text, start, episode->end, read_words(episode->words));
        return episode->end;
    }
    std::string word = latin_spelling(text, start, end);
    if (const auto key = detail::key_name_word(text, start, end)) {  // Ctrl control
        add_form(text, start, end, said_syllables(*detail::english_word_syllables(*key)));
        return end;
    }
    // A card's suffix after its model's digits (RTX 4070 Ti) is its letters, where Ti alone is pinyin.
    // Capitals glued to a number are a unit's or a model's letters (45TOPS ti ou pi ai si, a chip's trillions
    // of operations a second; session 32: the dictionary's tops, ta pu si), unless said as a word (15PRO).
    const bool follows_digits = start > 0 && detail::is_digit_at(text, start - 1) &&
                                detail::is_all_capitals(word) && !detail::is_said_as_word(word);
    // Letters right before a triangle's sign name its kind (Rt△ABC, a right triangle, as lessons write it):
    // said as letters, R T (session 33: the same, with a warning that Rt is no word).
    const bool names_triangle = end < text.size() && text[end].value == 0x25B3 /*△*/;
    if (follows_digits || names_triangle || in_chemical_formula(text, start) ||
        detail::follows_card_model(text, start)) {
        add_form(text, start, end, said_syllables(detail::letter_syllables(word)));
        return end;
    }
    // A name of two parts joined by & (S&P 标普, P&G 宝洁) is said whole where the table has it; the &
    // alone has no reading (session 30: S P, the & unsaid with a warning).
    if (end + 1 < text.size() && text[end].value == '&' && is_ascii_letter(text[end + 1].value)) {
        const auto second_end = letters_end(end + 1);
        if (auto found =
                detail::english_word_syllables(word + "&" + latin_spelling(text, end + 1, second_end))) {
            add_form(text, start, second_end, said_syllables(*found));
            return second_end;
        }
    }
    // A hyphen in a formula is a minus sign (a-b>0), not a join.
    if (end + 1 < text.size() && text[end].value == '-' && is_ascii_letter(text[end + 1].value) &&
        detail::said_math_sign(text, end).empty()) {
        const auto second_end = letters_end(end + 1);
        const auto joined = word + latin_spelling(text, end + 1, second_end);
        if (std::any_of(joined.begin(), joined.end(), [](char l) { return l >= 'a' && l <= 'z'; }) &&
            detail::english_word_syllables(joined)) {
            word = joined;
            end = second_end;
        }
    }
    // A chat's laugh, h written three or more times (hhh, hhhhh), is read 哈 for each h.
    constexpr std::size_t kShortestLaugh = 3;
    if (word.size() >= kShortestLaugh && word.find_first_not_of('h') == std::string::npos) {
        std::string laugh;
        for (std::size_t k = 0; k < word.size(); ++k) laugh += "哈";
        add_form(text, start, end, read_words(laugh));
        return end;
    }
    // A chat's hum, an e and its m's drawn out (emm, emmm, Emmmm), is 嗯, the hum it writes (session 33:
    // generic speech with a warning).
    constexpr std::size_t kShortestHum = 3;
    if (word.size() >= kShortestHum && (word.front() == 'e' || word.front() == 'E') &&
        word.find_first_not_of('m', 1) == std::string::npos) {
        add_form(text, start, end, read_words("嗯"));
        return end;
    }
    // A game's level, Lv.50 (LV50, Lv 50): L V and the number, the dot not said (session 14; Lv was
    // the pinyin lü and its dot ended the sentence).
    if (word == "Lv" || word == "LV" || word == "lv") {
        auto level_end = end;
        if (level_end + 1 < text.size() && text[level_end].value == '.' &&
            is_ascii_digit(text[level_end + 1].value))
            ++level_end;
        if (level_end < text.size() &&
            (is_ascii_digit(text[level_end].value) || text[level_end].value == ' ')) {
            add_form(text, start, level_end, said_syllables(detail::letter_syllables("LV")));
            return level_end;
        }
    }
    if (auto number = number_sign(text, word, end)) {
        add_form(text, start, number->first, number->second);
        return number->first;
    }
    // A rate's basis points with a plural's s (降息25bps) are bp's letters and the s a reader says after
    // them, as after capitals (SDGs; session 33: the s by its letter's name, ai si).
    if (word.size() == 3 && word.back() == 's' && detail::is_basis_points_at(text, start)) {
        auto syllables = detail::letter_syllables("bp");
        syllables.emplace_back("si5");
        add_form(text, start, end, said_syllables(syllables));
        return end;
    }
    add_form(text, start, end, latin_word_syllables(word, text[start], is_digit_at(text, end)));
    return end;
}

std::vector<Syllable> TranscriptReader::latin_word_syllables(const std::string& word, const CodePoint& at,
                                                             bool names_with_number) {
    // A letter alone is a letter (选a, x=5), not the dictionary's word a or x (ai si).
    if (word.size() == 1 || (detail::is_all_capitals(word) && !detail::is_said_as_word(word)))
        return read_capitals(word);
    // A small letter and a capital (pH, as chemistry writes it) are letters, P H (session 17: the
    // dictionary's word ph, pi ei qi).
    if (word.size() == 2 && word.front() >= 'a' && word.front() <= 'z' &&
        is_ascii_capital(static_cast<char32_t>(word.back())))
        return said_syllables(detail::letter_syllables(word));
    // A capital, a small letter and a capital (YoY, QoQ, MoM: year over year, as finance copy abbreviates
    // a comparison) are the three words' letters (session 30: Yo and Y, you wai).
    if (word.size() == 3 && is_ascii_capital(static_cast<char32_t>(word[0])) && word[1] >= 'a' &&
        word[1] <= 'z' && is_ascii_capital(static_cast<char32_t>(word[2])))
        return said_syllables(detail::letter_syllables(word));
    // Capitals and one small letter after them (PCIe) are an acronym's letters, said one by one (P C
    // I E); no part of them is a word to say.
    const bool is_acronym_with_small_end = word.size() >= 3 && word.back() >= 'a' && word.back() <= 'z' &&
                                           detail::is_all_capitals(word.substr(0, word.size() - 1));
    // A plural's s after two capitals or more (SDGs, GPUs, ETFs) is the s a reader says after the letters, as
    // an English word's final s is (stores si5), not the letter's name (session 32: ai si).
    constexpr std::size_t kFewestPluralCapitals = 2;
    if (is_acronym_with_small_end && word.back() == 's' && word.size() > kFewestPluralCapitals &&
        !detail::english_word_syllables(word)) {
        auto syllables = detail::letter_syllables(word.substr(0, word.size() - 1));
        syllables.emplace_back("si5");
        return said_syllables(syllables);
    }
    if (is_acronym_with_small_end && !detail::english_word_syllables(word))
        return said_syllables(detail::letter_syllables(word));
    if (detail::has_inner_acronym(word)) return read_word_parts(word, at);
    // Small letters without a vowel but y (yyds, xswl, dbq): a chat's initials of a phrase's
    // pinyin, said as their letters, as chat is read out (session 14; yyds was generic speech).
    constexpr std::size_t kLongestInitials = 6;
    const bool is_initials =
        word.size() >= 2 && word.size() <= kLongestInitials &&
        std::all_of(word.begin(), word.end(), [](char l) { return l >= 'a' && l <= 'z'; }) &&
        word.find_first_of("aeiou") == std::string::npos;
    // Without a y either, the dictionary's word is an abbreviation Mandarin speakers spell
    // (湖人vs勇士 V S, 5ppm, bbq; session 20: vs was the dictionary's wa se zi); with a y it may be a
    // word (my, sky).
    if (is_initials && word.find('y') == std::string::npos)
        return said_syllables(detail::letter_syllables(word));
    if (auto found = detail::english_word_syllables(word)) return said_syllables(*found);
    if (is_initials || is_initials_with_vowel_syllable(word))
        return said_syllables(detail::letter_syllables(word));
    // Three small letters or fewer that the dictionary lacks and that spell no pinyin (orz, a chat's
    // kneeling figure; abc, ufo) are their letters, as three capitals are: too short to be said as a word
    // (session 21: generic speech). Pinyin read as Latin (ni with read_pinyin off) stays generic speech.
    // So with a capital first, as a key's name is written (Esc yi ai si xi; session 33: generic speech).
    // A number written right after it makes it a name said as a word, as a protein's or a gene's is
    // (Cas9 ka si 九, Cas12a; session 34: C A S): a key's name never takes one (Esc, Alt+4, F12's letter).
    constexpr std::size_t kLongestSpelledSmall = 3;
    const bool is_name = names_with_number && word.size() > 1 &&
                         is_ascii_capital(static_cast<unsigned char>(word[0])) && word[1] >= 'a';
    if (auto found = is_name ? detail::name_before_number_syllables(word) : std::nullopt)
        return said_syllables(*found);
    if (word.size() <= kLongestSpelledSmall && !is_name &&
        std::all_of(word.begin() + 1, word.end(), [](char l) { return l >= 'a' && l <= 'z'; }) &&
        is_ascii_letter(static_cast<unsigned char>(word.front())) &&
        !split_pinyin(decode_utf8(detail::ascii_lower_case(word), "<word>")))
        return said_syllables(detail::letter_syllables(word));
    return read_word_parts(word, at);
}

bool TranscriptReader::is_initials_with_vowel_syllable(const std::string& word) const {
    constexpr std::size_t kShortest = 4;
    constexpr std::size_t kLongest = 6;
    if (word.size() < kShortest || word.size() > kLongest ||
        !std::all_of(word.begin(), word.end(), [](char l) { return l >= 'a' && l <= 'z'; }))
        return false;
    const auto vowels = std::count_if(word.begin(), word.end(), [](char l) {
        return std::string_view("aeiou").find(l) != std::string_view::npos;
    });
    const auto vowel = word.find_first_of("aeiou");
    if (vowels != 1 || (vowel != 0 && vowel + 1 != word.size())) return false;
    std::string consonants = word;
    consonants.erase(vowel, 1);
    std::sort(consonants.begin(), consonants.end());
    if (std::adjacent_find(consonants.begin(), consonants.end()) != consonants.end()) return false;
    return !split_pinyin(decode_utf8(word, "<word>"));
}

std::optional<std::pair<std::size_t, std::vector<Syllable>>> TranscriptReader::number_sign(
    const std::vector<CodePoint>& text, const std::string& word, std::size_t end) const {
    if ((word != "No" && word != "NO") || end >= text.size() || text[end].value != '.') return std::nullopt;
    auto first = end + 1;
    if (first < text.size() && text[first].value == ' ') ++first;
    auto last = first;
    while (last < text.size() && is_ascii_digit(text[last].value)) ++last;
    if (last == first) return std::nullopt;
    auto syllables = *detail::english_word_syllables("number");
    for (auto& syllable : detail::english_number_syllables(latin_spelling(text, first, last)))
        syllables.push_back(std::move(syllable));
    return std::make_pair(last, said_syllables(syllables));
}

std::vector<Syllable> TranscriptReader::address_syllables(const detail::WebAddress& address,
                                                          const CodePoint& at) {
    std::vector<Syllable> syllables;
    auto append = [&](std::vector<Syllable> more) {
        for (auto& syllable : more) syllables.push_back(std::move(syllable));
    };
    for (const auto& part : address.parts) {
        if (part.kind == detail::AddressPart::Kind::words) {
            append(read_words(part.text));
        } else if (part.kind == detail::AddressPart::Kind::digits) {
            append(read_words(detail::digit_words(part.text, detail::is_named_service_number(part.text))));
        } else if (detail::is_all_capitals(part.text)) {
            append(latin_word_syllables(part.text, at));
        } else if (auto name_pinyin =
                       starts_as_pinyin_only(part.text) ? address_pinyin(part.text) : std::nullopt) {
            append(std::move(*name_pinyin));
        } else if (auto found = detail::english_word_syllables(part.text);
                   found && !detail::expands_abbreviation(part.text, *found)) {
            append(said_syllables(*found));
        } else if (constexpr std::size_t kLongestSpelled = 3;
                   part.text.size() <= kLongestSpelled || detail::spelled_syllables(part.text).empty()) {
            append(said_syllables(detail::letter_syllables(part.text)));
        } else if (auto pinyin = address_pinyin(part.text)) {
            append(std::move(*pinyin));
        } else {
            append(latin_word_syllables(part.text, at));
        }
    }
    return syllables;
}

std::optional<std::vector<Syllable>> TranscriptReader::address_pinyin(const std::string& letters) const {
    if (!options_.read_pinyin ||
        std::any_of(letters.begin(), letters.end(), [](char c) { return c < 'a' || c > 'z'; }))
        return std::nullopt;
    const auto token = decode_utf8(letters, "<address>");
    auto split = split_pinyin(token);
    if (!split) return std::nullopt;
    std::vector<Syllable> syllables;
    for (auto& syllable : *split)
        syllables.push_back(make_syllable(std::move(syllable.written), std::move(syllable.pinyin)));
    return syllables;
}

std::vector<Syllable> TranscriptReader::said_syllables(const std::vector<std::string>& pinyin) const {
    std::vector<Syllable> syllables;
    for (const auto& reading : pinyin) syllables.push_back(make_syllable(toneless_of(reading), reading));
    return syllables;
}

std::vector<Syllable> TranscriptReader::read_capitals(const std::string& word) const {
    constexpr std::size_t kLongestAcronym = 4;
    constexpr std::size_t kLongestSaidConsonants = 2;
    if (word.size() >= kLongestAcronym) {
        if (auto found = detail::english_word_syllables(word)) return said_syllables(*found);
    }
    if (word.size() > kLongestAcronym) {
        // A name in capitals made of words, or of letters and a word (a group's: BLACKPINK black pink,
        // TFBOYS T F boys), is said as its fans say it (session 34: spelled, B L A C K P I N K).
        if (auto found = detail::capitals_of_words(word)) return said_syllables(*found);
        std::size_t consonants = 0, longest = 0;
        for (const char letter : word) {
            consonants =
                std::string_view("AEIOUY").find(letter) == std::string_view::npos ? consonants + 1 : 0;
            longest = std::max(longest, consonants);
        }
        auto spelled = detail::spelled_syllables(word);
        if (!spelled.empty() && longest <= kLongestSaidConsonants) return generic_syllables(spelled);
    }
    return said_syllables(detail::letter_syllables(word));
}

std::vector<Syllable> TranscriptReader::generic_syllables(const std::vector<std::string>& spelled) const {
    std::vector<Syllable> syllables;
    for (const auto& piece : spelled) {
        syllables.push_back(make_syllable(piece, kGenericSpeechPinyin));
        syllables.back().generic_speech = true;
    }
    return syllables;
}

std::vector<Syllable> TranscriptReader::read_word_parts(const std::string& word, const CodePoint& at) {
    std::vector<std::string> parts;
    for (std::size_t i = 0; i < word.size(); ++i) {
        const bool starts_part = i == 0 || (is_ascii_capital(static_cast<char32_t>(word[i])) &&
                                            !is_ascii_capital(static_cast<char32_t>(word[i - 1])));
        if (starts_part) parts.emplace_back();
        parts.back() += word[i];
    }
    // A part the dictionary lacks whose h after a consonant starts a word it has is two words (Github,
    // github: git hub), as pothole's h starts hole; its spelling would put the h with the consonant (session
    // 33: gi thub).
    if (parts.size() == 1 && !detail::english_word_syllables(word) && !read_compound(word)) {
        if (const auto h = detail::word_after_h(word)) parts = {word.substr(0, *h), word.substr(*h)};
    }
    std::vector<Syllable> syllables;
    for (const auto& part : parts) {
        // A part in capitals is an acronym or a word in capitals (iOS: i + OS, ou ai si).
        if (part.size() > 1 && detail::is_all_capitals(part)) {
            for (auto& syllable : read_capitals(part)) syllables.push_back(std::move(syllable));
            continue;
        }
        // A letter alone is the letter (mRNA: M R N A; session 21: the dictionary's m, an), as a word of
        // one letter is.
        if (part.size() == 1) {
            for (auto& syllable : said_syllables(detail::letter_syllables(part)))
                syllables.push_back(std::move(syllable));
            continue;
        }
        auto found = parts.size() > 1 ? detail::english_word_syllables(part) : std::nullopt;
        // A letter before a word (Gmail: G mail; session 24: generic speech of one syllable).
        if (!found) found = detail::letter_and_word_syllables(part);
        if (!found) found = read_compound(part);
        std::vector<Syllable> read;
        if (found) {
            read = said_syllables(*found);
        } else if (const auto spelled = detail::spelled_syllables(part); !spelled.empty()) {
            warn(at,
                 "\"" + part +
                     "\" is not in the English pronouncing dictionary; aligned as generic speech of about " +
                     std::to_string(spelled.size()) + (spelled.size() == 1 ? " syllable" : " syllables") +
                     " (fix it in place: " + part + "{...})");
            read = generic_syllables(spelled);
        } else {
            warn(at, "\"" + part +
                         "\" is not in the English pronouncing dictionary and has no vowel; read letter by "
                         "letter (fix it in place: " +
                         part + "{...})");
            read = said_syllables(detail::letter_syllables(part));
        }
        for (auto& syllable : read) syllables.push_back(std::move(syllable));
    }
    return syllables;
}

std::optional<std::vector<std::string>> TranscriptReader::read_compound(const std::string& word) {
    constexpr std::size_t kShortestPart = 2;
    return detail::two_word_syllables(word, kShortestPart);
}

bool TranscriptReader::joins_two_words(const std::vector<CodePoint>& text, std::size_t i) const {
    if (text[i].value != '&') return false;
    const auto is_word_at = [&](std::size_t k) {
        return k < text.size() &&
               (is_ascii_letter(text[k].value) || is_digit_at(text, k) || tables_.has_readings(text[k].text));
    };
    const auto before = i > 0 && text[i - 1].value == ' ' ? i - 1 : i;
    const auto after = i + 1 < text.size() && text[i + 1].value == ' ' ? i + 2 : i + 1;
    return before > 0 && is_word_at(before - 1) && is_word_at(after);
}

}  // namespace talkface::detail

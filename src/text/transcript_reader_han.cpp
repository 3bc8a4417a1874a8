// The transcript reader's runs of Chinese characters: each run cut into its likeliest words and read by
// the tables, a particle, a return verb, a title's head, 得 "must", a measure word or a verb alone (种
// 只 教), a noun after what counts or points to it (该地 三天假), 冲 graded by a degree adverb (太冲了), the
// copula after a quantity (率为) or 为 "as" after 以 or a verb of choosing (以安全为重 当选为) or 倒数 the
// reciprocal (2的倒数) deciding a reading in context, and a written form's words read so.
#include "text/transcript_reader.hpp"

#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "common/internal_error.hpp"
#include "text/aspect_particle.hpp"
#include "text/code_points.hpp"
#include "text/count_down.hpp"
#include "text/counted_noun.hpp"
#include "text/degree_adjective.hpp"
#include "text/latin_words.hpp"
#include "text/measure_or_verb.hpp"
#include "text/must_verb.hpp"
#include "text/quantity_copula.hpp"
#include "text/return_verb.hpp"
#include "text/script_variant.hpp"
#include "text/shots_made.hpp"
#include "text/take_as.hpp"
#include "text/title_head.hpp"
#include "text/word_segmentation.hpp"
#include "text/written_number_scan.hpp"

namespace talkface::detail {

std::vector<std::string> TranscriptReader::read_han(const std::vector<HanCharacter>& run, bool ends_clause,
                                                    bool follows_number, bool follows_attempts,
                                                    std::string_view written_after) const {
    std::vector<std::string_view> characters;
    for (const auto& character : run) characters.push_back(character.text);
    std::vector<std::string> readings_of_run;
    std::size_t first = 0;
    const auto lengths = detail::likeliest_words(characters, tables_, ends_clause);
    std::vector<std::string> words;
    for (std::size_t w = 0, start = 0; w < lengths.size(); start += lengths[w++]) {
        words.emplace_back();
        for (std::size_t k = start; k < start + lengths[w]; ++k) words.back() += run[k].text;
    }
    for (std::size_t w = 0; w < lengths.size(); ++w) {
        const auto length = lengths[w];
        const auto& word = words[w];
        const auto found = tables_.word(word);
        const bool has_readings = found && !found->readings.empty();
        const auto next_word =
            w + 1 < lengths.size() && lengths[w + 1] == 1 ? characters[first + length] : std::string_view();
        auto in_context = detail::reading_before_particle(word, next_word);
        if (in_context.empty()) in_context = detail::return_verb_reading(words, w, ends_clause);
        if (in_context.empty()) in_context = detail::title_head_reading(words, w);
        if (in_context.empty()) in_context = detail::must_verb_reading(words, w, written_after);
        if (in_context.empty()) in_context = detail::measure_or_verb_reading(words, w, follows_number);
        if (in_context.empty()) in_context = detail::counted_noun_reading(words, w);
        if (in_context.empty()) in_context = detail::degree_adjective_reading(words, w);
        if (in_context.empty())
            in_context = detail::quantity_copula_reading(words, w, ends_clause, written_after);
        if (in_context.empty()) in_context = detail::take_as_reading(words, w);
        if (in_context.empty()) in_context = detail::shots_made_reading(words, w, follows_attempts);
        for (std::size_t k = 0; k < length; ++k) {
            const auto& character = run[first + k];
            std::string pinyin = character.fix;
            if (pinyin.empty() && k == 0 && !in_context.empty()) {
                pinyin = in_context;
            } else if (pinyin.empty()) {
                pinyin = has_readings ? std::string(found->readings[k])
                                      : std::string(tables_.readings(character.text).front());
                check_table_reading(character, pinyin);
            }
            if (k == 1 && character.fix.empty() && detail::names_reciprocal(words, w)) pinyin = "shu4";
            readings_of_run.push_back(std::move(pinyin));
        }
        first += length;
    }
    // 得了 as a potential complement (吃得了吗 de5 liao3) is read across the words it is cut into.
    for (std::size_t k = 0; k + 1 < run.size(); ++k) {
        if (!detail::is_potential_complement(characters, lengths, k)) continue;
        if (run[k].fix.empty()) readings_of_run[k] = "de5";
        if (run[k + 1].fix.empty()) readings_of_run[k + 1] = "liao3";
    }
    return readings_of_run;
}

void TranscriptReader::flush_run(bool ends_clause, std::string_view written_after) {
    const auto readings =
        read_han(run_, ends_clause, run_follows_number_, run_follows_attempts_, written_after);
    for (std::size_t k = 0; k < run_.size(); ++k) add_syllable(std::string(run_[k].text), readings[k]);
    run_.clear();
}

bool TranscriptReader::follows_written_number(std::size_t i) const {
    if (last_form_end_ != i || !pending_space_.empty() || timeline_.written_forms.empty()) return false;
    // A count written in digits (ASCII or full-width, thousands' commas), a 万 or 亿 after them allowed
    // (3万); not a time, a date, a percentage or a decimal (10:00只剩, 30%只是).
    const auto characters = decode_utf8(timeline_.written_forms.back().text, "<form>");
    for (std::size_t k = 0; k < characters.size(); ++k) {
        const auto c = ascii_form(characters[k].value);
        const bool magnitude = k + 1 == characters.size() && k > 0 && is_one_of(c, U"万萬亿億");
        if (!is_ascii_digit(c) && c != ',' && !magnitude) return false;
    }
    return true;
}

std::string TranscriptReader::with_local_one(std::string words) const {
    if (!is_traditional_) return words;
    constexpr std::string_view kYao = "幺";
    for (auto at = words.find(kYao); at != std::string::npos; at = words.find(kYao, at))
        words.replace(at, kYao.size(), "一");
    return words;
}

std::vector<Syllable> TranscriptReader::read_words(const std::string& words) const {
    const auto characters = decode_utf8(words, "<reading>");
    std::vector<Syllable> syllables;
    std::vector<HanCharacter> run;
    const auto flush = [&] {
        if (run.empty()) return;
        const auto readings = read_han(run);
        // The readings are the tables' (Simplified); what a syllable shows follows the transcript.
        for (std::size_t k = 0; k < run.size(); ++k)
            syllables.push_back(make_syllable(
                is_traditional_ ? detail::traditional_form(run[k].text) : std::string(run[k].text),
                readings[k]));
        run.clear();
    };
    for (std::size_t i = 0; i < characters.size(); ++i) {
        // A letter a form names (log₃x 以三为底x的对数: the argument) is said by its name.
        if (detail::is_ascii_letter(characters[i].value)) {
            flush();
            for (auto& syllable : said_syllables(detail::letter_syllables(characters[i].text)))
                syllables.push_back(std::move(syllable));
            continue;
        }
        if (!tables_.has_readings(characters[i].text)) {
            throw detail::internal_error("the reading \"" + words + "\" holds \"" +
                                         std::string(characters[i].text) + "\", which has no reading");
        }
        run.push_back({nullptr, characters[i].text, {}});
    }
    flush();
    return syllables;
}

void TranscriptReader::check_table_reading(const HanCharacter& character, const std::string& pinyin) const {
    if (detail::normalise_pinyin(pinyin) != pinyin) {
        throw detail::internal_error("the reading table gives \"" + std::string(character.text) +
                                     "\" the reading \"" + pinyin + "\", not a Mandarin syllable");
    }
}

}  // namespace talkface::detail

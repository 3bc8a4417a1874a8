// Transcript -> sentences and syllables [thesis 3.3.2; SPEC "Transcript to syllables"]. The
// thesis picked the reading of each polyphonic character by hand; here the word it stands in
// decides (word_segmentation.hpp), then the character's most frequent reading.
#include "talkface/transcript.hpp"

#include <algorithm>
#include <cstdio>
#include <map>
#include <optional>
#include <vector>

#include "text/code_points.hpp"
#include "text/dates_and_times.hpp"
#include "text/digit_codes.hpp"
#include "text/drawn_faces.hpp"
#include "text/formula_letters.hpp"
#include "text/kana_words.hpp"
#include "text/keyboard_keys.hpp"
#include "text/latin_words.hpp"
#include "text/legend_shapes.hpp"
#include "text/line_sentences.hpp"
#include "text/phonetic_spelling.hpp"
#include "text/pinyin_tokens.hpp"
#include "text/reading_tables.hpp"
#include "text/script_marks.hpp"
#include "text/script_variant.hpp"
#include "text/sentence_marks.hpp"
#include "text/shots_made.hpp"
#include "text/transcript_cut.hpp"
#include "text/transcript_reader.hpp"
#include "text/typed_names.hpp"
#include "text/units_and_money.hpp"
#include "text/web_addresses.hpp"
#include "text/written_number_scan.hpp"
#include "text/written_numbers.hpp"

namespace talkface::detail {

namespace {

// Full-width Latin letters, digits and symbols (ＡＩ ｉＰｈｏｎｅ ５Ｇ ％ ＄ ／ ：) are read as their ASCII
// forms, as the numbers' reader already did with digits; each keeps its text, so sentences and
// written forms show what the page shows. The braces of a reading fix stay ASCII only: ｛ is text.
std::vector<CodePoint> width_folded(const std::vector<CodePoint>& text) {
    auto folded = text;
    for (auto& c : folded) {
        if (c.value != 0xFF5B /*｛*/ && c.value != 0xFF5D /*｝*/) c.value = ascii_form(c.value);
    }
    return folded;
}

}  // namespace

std::string describe_character(const CodePoint& c) {
    const auto written = decode_utf8(c.text, "<character>").front().value;
    char code[16];
    std::snprintf(code, sizeof code, "U+%04X", static_cast<unsigned>(written));
    if (c.value < 0x20 || c.value == 0x7F) return code;
    return "\"" + std::string(c.text) + "\" (" + code + ")";
}

Timeline TranscriptReader::read(const std::vector<CodePoint>& written,
                                const std::optional<std::vector<int>>& lines_ending_sentences) {
    const auto text = width_folded(written);
    is_traditional_ = detail::is_traditional_text(text);
    has_han_ = std::any_of(text.begin(), text.end(),
                           [&](const CodePoint& c) { return tables_.has_readings(c.text); });
    const auto marks =
        options_.keep_directions ? std::vector<detail::ScriptMark>() : detail::find_script_marks(text);
    warn_script_marks(text, marks);
    drawing_ends_ = detail::find_drawing_ends(text);
    // A plain transcript's lines written one a sentence end theirs (docs/transcripts.md "Lines"); a
    // subtitle's cues bring their own.
    const auto ending_lines =
        lines_ending_sentences ? *lines_ending_sentences : detail::lines_ending_sentences(text);
    auto mark = marks.begin();
    int last_line = 0;  // of the last code point that is not a space
    for (std::size_t i = 0; i < text.size();) {
        if (lines_ending_sentences && text[i].value == '\n' &&
            pending_space_.find('\n') != std::string::npos) {
            ++i;
            continue;
        }
        const bool starts_line = !is_space(text[i].value) && text[i].line != last_line;
        if (starts_line && std::binary_search(ending_lines.begin(), ending_lines.end(), last_line)) {
            break_sentence();
        }
        if (!is_space(text[i].value)) last_line = text[i].line;
        while (mark != marks.end() && mark->begin < i) ++mark;
        if (mark != marks.end() && mark->begin == i) {
            // A new speaker starts a new sentence.
            if (mark->is_label) break_sentence();
            i = mark->end;
            continue;
        }
        i = read_item(text, i);
    }
    close_sentence();
    return std::move(timeline_);
}

void TranscriptReader::warn_script_marks(const std::vector<CodePoint>& text,
                                         const std::vector<detail::ScriptMark>& marks) {
    constexpr const char* kKeep =
        "; left out (TranscriptOptions::keep_directions, --keep-directions, keeps it)";
    const auto written = [&](const detail::ScriptMark& mark) {
        auto out = written_text(text, mark.name_begin, mark.name_end);
        while (!out.empty() && out.back() == ' ') out.pop_back();
        return out;
    };
    std::map<std::string, std::size_t> label_lines;
    for (const auto& mark : marks) {
        if (mark.is_label) ++label_lines[written(mark)];
    }
    for (const auto& mark : marks) {
        const auto name = written(mark);
        if (!mark.is_label) {
            warn(text[mark.begin], "\"" + name + "\" is a stage direction, not said" + kKeep);
            continue;
        }
        auto& lines = label_lines[name];
        if (lines == 0) continue;  // warned at its first line
        warn(text[mark.name_begin], "\"" + name + "\" is a speaker's label (" + std::to_string(lines) +
                                        (lines == 1 ? " line" : " lines") + "), not said" + kKeep);
        lines = 0;
    }
}

void TranscriptReader::break_sentence() {
    const auto space = pending_space_;
    close_sentence();
    pending_space_ = space;
}

std::optional<std::size_t> TranscriptReader::read_written_form(const std::vector<CodePoint>& text,
                                                               std::size_t i) {
    const auto& c = text[i];
    if (auto address = detail::read_web_address(text, i)) {
        form_warnings_ = timeline_.warnings.size();
        add_form(text, i, address->end, address_syllables(*address, c));
        return address->end;
    }
    if (auto name = detail::read_typed_name(text, i)) {  // C:\Users, /etc/hosts, Home_5G, 0x80070005
        form_warnings_ = timeline_.warnings.size();
        add_form(text, i, name->end, address_syllables(*name, c));
        return name->end;
    }
    if (const auto key = detail::key_sign_word(c.value); !key.empty()) {  // ⌘ command
        form_warnings_ = timeline_.warnings.size();
        add_form(text, i, i + 1, said_syllables(*detail::english_word_syllables(key)));
        return i + 1;
    }
    if (detail::joins_shortcut_keys(text, i)) {  // Shift+⌘+4
        form_warnings_ = timeline_.warnings.size();
        add_form(text, i, i + 1, read_words("加"));
        return i + 1;
    }
    // A subtitle's or a lyric's timing is no speech: kept in the sentence's text, not said.
    if (const auto timing_end = detail::past_subtitle_timing(text, i)) {
        append_text(written_text(text, i, *timing_end));
        return *timing_end;
    }
    // A word's phonetic spelling after it (apple [ˈæpl]) is the word said again: kept, not said.
    if (const auto spelling_end = detail::past_phonetic_spelling(text, i)) {
        append_text(written_text(text, i, *spelling_end));
        return *spelling_end;
    }
    if (auto form = detail::read_number_form(text, i)) {
        form_warnings_ = timeline_.warnings.size();
        if (!form->warning.empty()) warn(c, "\"" + written_text(text, i, form->end) + "\": " + form->warning);
        add_form(text, i, form->end,
                 read_words(form->is_dialled ? with_local_one(form->words) : form->words));
        return form->end;
    }
    if (auto weekday = detail::read_weekday_bracket(text, i)) {  // 12/24(三) 星期三
        form_warnings_ = timeline_.warnings.size();
        add_form(text, i, weekday->end, read_words(weekday->words));
        return weekday->end;
    }
    if (auto unit = detail::read_named_unit(text, i)) {
        form_warnings_ = timeline_.warnings.size();
        add_form(text, i, unit->end, read_words(unit->words));
        return unit->end;
    }
    if (auto shape = detail::read_legend_shape(text, i)) {  // ▲表示上涨 三角
        form_warnings_ = timeline_.warnings.size();
        add_form(text, i, shape->end, read_words(shape->words));
        return shape->end;
    }
    if (auto logarithm = detail::read_logarithm(text, i)) {
        form_warnings_ = timeline_.warnings.size();
        add_form(text, i, logarithm->end, read_words(logarithm->words));
        return logarithm->end;
    }
    if (auto per = detail::read_per_unit(text, i)) {
        form_warnings_ = timeline_.warnings.size();
        add_form(text, i, per->end, read_words(per->words));
        return per->end;
    }
    if (detail::joins_periods(text, i)) {
        form_warnings_ = timeline_.warnings.size();
        add_form(text, i, i + 1, read_words("到"));
        return i + 1;
    }
    if (detail::slash_reads_per(text, i) || detail::slash_joins_sizes(text, i)) {
        form_warnings_ = timeline_.warnings.size();
        add_form(text, i, i + 1, read_words(detail::slash_reads_per(text, i) ? "每" : "和"));
        return i + 1;
    }
    if (detail::slash_pairs_currencies(text, i)) {
        form_warnings_ = timeline_.warnings.size();
        add_form(text, i, i + 1, read_words("兑"));
        return i + 1;
    }
    if (auto number = detail::read_number_character(text, i)) {  // ① Ⅱ ½
        form_warnings_ = timeline_.warnings.size();
        add_form(text, i, number->end, read_words(number->words));
        return number->end;
    }
    if (auto power = detail::read_power(text, i)) {  // after a letter or a bracket (x⁴, x^2)
        form_warnings_ = timeline_.warnings.size();
        add_form(text, i, power->end, read_words(power->words));
        return power->end;
    }
    if (const auto sign = detail::said_math_sign(text, i); !sign.empty()) {
        form_warnings_ = timeline_.warnings.size();
        add_form(text, i, i + 1, read_words(std::string(sign)));
        return i + 1;
    }
    if (joins_two_words(text, i)) {
        form_warnings_ = timeline_.warnings.size();
        add_form(text, i, i + 1, said_syllables(*detail::english_word_syllables("and")));
        return i + 1;
    }
    if (auto kana = detail::read_kana_word(text, i)) {
        form_warnings_ = timeline_.warnings.size();
        add_form(text, i, kana->end, said_syllables(kana->syllables));
        return kana->end;
    }
    return std::nullopt;
}

std::size_t TranscriptReader::read_item(const std::vector<CodePoint>& text, std::size_t i) {
    const auto& c = text[i];
    if (is_space(c.value)) {
        pending_space_ += c.text;
        return i + 1;
    }
    // A blank line starts a paragraph, and a sentence never runs on into the next paragraph
    // (a heading without a full stop is a sentence of its own).
    if (has_blank_line(pending_space_)) {
        close_sentence();
        starts_paragraph_ = !timeline_.sentences.empty();
    }
    if (c.value == '{' && !opens_set(text, i)) return read_fix(text, i);
    // An emoji or a face drawn in signs stays in its sentence's text, unsaid and unwarned, as
    // punctuation does; one after an end mark closes that sentence as a closing quote does.
    if (const auto drawing_end = drawing_ends_[i]; drawing_end != i) {
        flush_run();
        append_text(written_text(text, i, drawing_end));
        return drawing_end;
    }
    if (tables_.has_readings(c.text)) {
        if (sentence_ended_) close_sentence();
        if (run_.empty()) {
            run_follows_number_ = follows_written_number(i);
            run_follows_attempts_ =
                run_follows_number_ &&
                detail::follows_attempts(sentence_text_, timeline_.written_forms.back().text);
        }
        append_text(c.text);
        run_.push_back({&c, c.text, {}});
        return i + 1;
    }
    const bool ends_clause = ends_sentence(c.value) || marks_pause(c.value) || closes_quote(c.value);
    // What follows a run that ends before a written form: enough for a number, its decimals and its
    // unit (45.1%, 100分).
    constexpr std::size_t kWrittenAfter = 12;
    flush_run(ends_clause, ends_clause || run_.empty()
                               ? std::string()
                               : detail::text_between(text, i, std::min(text.size(), i + kWrittenAfter)));
    if (sentence_ended_ && !(ends_sentence(c.value) || closes_quote(c.value))) close_sentence();
    if (const auto form_end = read_written_form(text, i)) return *form_end;
    if (marks_choice(text, i) || marks_list_item(text, i) || marks_lineage_dot(text, i) ||
        marks_initialism_dot(text, i) || marks_reaction_arrow(text, i) || marks_bullet(text, i)) {
        append_text(c.text);
        return i + 1;
    }
    if (ends_sentence(c.value)) {
        append_text(c.text);
        sentence_ended_ = true;
        return i + 1;
    }
    if (marks_pause(c.value)) {
        append_text(c.text);
        if (!timeline_.syllables.empty() &&
            timeline_.syllables.back().sentence == timeline_.sentences.size()) {
            timeline_.syllables.back().pause_after = true;
        }
        return i + 1;
    }
    if (is_pinyin_letter(c.value)) return read_token(text, i);
    append_text(c.text);
    if (!is_silent_punctuation(c.value) && !marks_topic(text, i) && !marks_ticker(text, i) &&
        !marks_screen_mode(text, i))
        warn_no_reading(c);
    return i + 1;
}

std::size_t TranscriptReader::read_token(const std::vector<CodePoint>& text, std::size_t start) {
    const auto end = end_of_token(text, start);
    const std::vector<CodePoint> token(text.begin() + static_cast<std::ptrdiff_t>(start),
                                       text.begin() + static_cast<std::ptrdiff_t>(end));
    std::optional<std::vector<WrittenSyllable>> syllables;
    // Among Chinese characters, a Latin word all in capitals (A股, and A4纸: a digit after
    // capitals is a model or size, not a tone) or one without tone numbers that the English
    // dictionary has (men, long, email) is English or letters, not pinyin: pinyin inside
    // Chinese text is written in small letters with its tones (docs/written-forms.md).
    std::string letters;
    for (const auto& c : token) {
        if (is_pinyin_letter(c.value))
            letters += latin_spelling(token, &c - token.data(), &c - token.data() + 1);
    }
    const bool is_english_among_han = (has_han_ || (options_.read_pinyin && is_english_line(text, start))) &&
                                      (detail::is_all_capitals(letters) ||
                                       (!has_tone_digit(token) && !starts_as_pinyin_only(letters) &&
                                        detail::english_word_syllables(latin_spelling(text, start, end))));
    // Capitals beside a formula's sign are a lesson's letters in a line without Chinese
    // characters too (∠A=30° 角 A 等于三十度; session 14: A was the pinyin a).
    // With a count after it too (2H2+O2=2H2O: O2 was the pinyin o2; session 17).
    const bool is_formula_letter =
        detail::is_all_capitals(letters) &&
        (touches_formula_sign(text, start, -1) || touches_formula_sign(text, end, 1));
    // A game's level (Lv.50, LV50 among Chinese characters) is letters and a number, not the pinyin lü.
    const auto after_letters = start + letters.size();
    const bool is_level =
        (letters == "Lv" || letters == "LV" || letters == "lv") && after_letters + 1 < text.size() &&
        ((text[after_letters].value == '.' && is_ascii_digit(text[after_letters + 1].value)) ||
         (has_han_ && is_ascii_digit(text[after_letters].value) &&
          is_ascii_digit(text[after_letters + 1].value)));
    if (is_level) return read_latin(text, start);
    // An o with a tone digit 1-4 among Chinese characters (o1, o3) is a model's letter and number
    // (OpenAI的o1模型 ou 一; session 27: the pinyin o1, 噢): Chinese text writes the interjection with
    // its character. A light o5 stays pinyin, as numbered pinyin writes an English word's o (Office
    // o5 fa5 si5), and so do a and e, which a letter's name spells (R a4 er5).
    if (has_han_ && token.size() == 2 && token[0].value == 'o' && token[1].value >= '1' &&
        token[1].value <= '4')
        return read_latin(text, start);
    if (in_chemical_formula(text, start) || detail::follows_card_model(text, start))
        return read_latin(text, start);
    if (options_.read_pinyin && looks_like_pinyin(token) && !is_english_among_han && !is_formula_letter)
        syllables = split_pinyin(token);
    if (syllables && !has_tone_digit(token) && splits_into_interjection(*syllables)) syllables.reset();
    if (!syllables) return read_latin(text, start);
    for (const auto& c : token) append_text(c.text);
    for (auto& syllable : *syllables) add_syllable(std::move(syllable.written), std::move(syllable.pinyin));
    return end;
}

Syllable TranscriptReader::make_syllable(std::string text, std::string pinyin) const {
    Syllable syllable;
    syllable.text = std::move(text);
    syllable.pinyin = std::move(pinyin);
    syllable.sentence = timeline_.sentences.size();
    return syllable;
}

void TranscriptReader::add_syllable(std::string text, std::string pinyin) {
    timeline_.syllables.push_back(make_syllable(std::move(text), std::move(pinyin)));
}

void TranscriptReader::add_form(const std::vector<CodePoint>& text, std::size_t start, std::size_t end,
                                std::vector<Syllable> syllables) {
    if (sentence_ended_) close_sentence();
    const auto written = written_text(text, start, end);
    append_text(written);
    timeline_.written_forms.push_back({written, timeline_.syllables.size(), syllables.size()});
    for (auto& syllable : syllables) {
        syllable.sentence = timeline_.sentences.size();
        timeline_.syllables.push_back(std::move(syllable));
    }
    last_form_end_ = end;
}

std::string TranscriptReader::written_text(const std::vector<CodePoint>& text, std::size_t start,
                                           std::size_t end) {
    std::string written;
    for (auto k = start; k < end; ++k) written += text[k].text;
    return written;
}

void TranscriptReader::append_text(std::string_view text) {
    if (!sentence_text_.empty() && !pending_space_.empty()) {
        const bool has_line_break = pending_space_.find('\n') != std::string::npos;
        const bool between_wide = static_cast<unsigned char>(sentence_text_.back()) >= 0x80 &&
                                  static_cast<unsigned char>(text.front()) >= 0x80;
        if (!has_line_break) {
            sentence_text_ += pending_space_;
        } else if (!between_wide) {
            sentence_text_ += ' ';
        }
    }
    pending_space_.clear();
    sentence_text_ += text;
}

void TranscriptReader::close_sentence() {
    flush_run(true);
    const bool has_syllables =
        !timeline_.syllables.empty() && timeline_.syllables.back().sentence == timeline_.sentences.size();
    if (has_syllables) {
        timeline_.sentences.push_back({sentence_text_, 0.0, 0.0, starts_paragraph_});
        starts_paragraph_ = false;
    }
    sentence_text_.clear();
    pending_space_.clear();
    sentence_ended_ = false;
}

void TranscriptReader::warn_no_reading(const CodePoint& c) {
    warn(c, describe_character(c) + " has no Mandarin reading; skipped");
}

void TranscriptReader::warn(const CodePoint& c, const std::string& message) {
    timeline_.warnings.push_back(source_name_ + ":" + std::to_string(c.line) + ":" +
                                 std::to_string(c.column) + ": " + message);
}

Timeline read_transcript_cut(std::string_view utf8_text, const TranscriptOptions& options,
                             const std::string& source_name, const std::vector<int>& lines_ending_sentences) {
    return TranscriptReader(options, source_name)
        .read(decode_utf8(utf8_text, source_name), lines_ending_sentences);
}

}  // namespace talkface::detail

namespace talkface {
inline namespace v0 {

Timeline read_transcript(std::string_view utf8_text, const TranscriptOptions& options,
                         const std::string& source_name) {
    const auto code_points = detail::decode_utf8(utf8_text, source_name);
    return detail::TranscriptReader(options, source_name).read(code_points);
}

bool is_valid_pinyin(std::string_view syllable) {
    return !syllable.empty() && syllable.back() >= '1' && syllable.back() <= '5' &&
           detail::normalise_pinyin(syllable) == syllable;
}

}  // namespace v0
}  // namespace talkface

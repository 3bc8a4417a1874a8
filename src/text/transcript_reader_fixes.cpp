// The transcript reader's reading fixes, written in braces right after what they read: a character's
// pinyin (行{hang2}) or a written form's reading (2026{两千零二十六}, iPhone{ai4 feng4}).
#include "text/transcript_reader.hpp"

#include <string>
#include <utility>
#include <vector>

#include "talkface/errors.hpp"
#include "text/code_points.hpp"
#include "text/pinyin_tokens.hpp"
#include "text/reading_tables.hpp"
#include "text/sentence_marks.hpp"

namespace talkface::detail {

std::size_t TranscriptReader::read_fix(const std::vector<CodePoint>& text, std::size_t open) {
    const auto& brace = text[open];
    auto close = open + 1;
    std::string written;
    while (close < text.size() && text[close].value != '}' && text[close].value != '\n') {
        written += text[close].text;
        ++close;
    }
    if (close == text.size() || text[close].value != '}') {
        throw ParseError(source_name_, brace.line, brace.column, "reading fix \"{" + written + "\"",
                         "no closing \"}\" on this line; write a fix as 行{hang2}");
    }
    const bool follows_form = last_form_end_ == open && pending_space_.empty();
    if (follows_form) {
        fix_form(written, brace);
        return close + 1;
    }
    const bool follows_character =
        !run_.empty() && pending_space_.empty() && run_.back().code_point == &text[open - 1];
    if (!follows_character) {
        throw ParseError(source_name_, brace.line, brace.column, "reading fix \"{" + written + "}\"",
                         "a fix must directly follow the Chinese character or the written form (a number, "
                         "a Latin word) it reads, as in 行{hang2} or 2026{两千零二十六}");
    }
    auto pinyin = detail::normalise_pinyin(written);
    if (pinyin.empty()) {
        throw ParseError(source_name_, brace.line, brace.column,
                         "reading fix \"{" + written + "}\" for \"" + std::string(text[open - 1].text) + "\"",
                         "\"" + written +
                             "\" is not a Mandarin syllable in numbered pinyin (tone 1-5 optional), "
                             "e.g. hang2, lv4");
    }
    run_.back().fix = std::move(pinyin);
    return close + 1;
}

void TranscriptReader::fix_form(const std::string& fix, const CodePoint& brace) {
    auto& form = timeline_.written_forms.back();
    const auto where = "reading fix \"{" + fix + "}\" for \"" + form.text + "\"";
    const auto fix_text = decode_utf8(fix, source_name_);
    std::vector<Syllable> syllables;
    std::vector<HanCharacter> run;
    auto flush = [&] {
        const auto pinyin = read_han(run);
        for (std::size_t k = 0; k < run.size(); ++k)
            syllables.push_back(make_syllable(std::string(run[k].text), pinyin[k]));
        run.clear();
    };
    for (std::size_t i = 0; i < fix_text.size();) {
        const auto& c = fix_text[i];
        if (is_space(c.value)) {
            flush();
            ++i;
        } else if (tables_.has_readings(c.text)) {
            run.push_back({nullptr, c.text, {}});
            ++i;
        } else if (is_pinyin_letter(c.value)) {
            flush();
            const auto end = end_of_token(fix_text, i);
            const std::vector<CodePoint> token(fix_text.begin() + static_cast<std::ptrdiff_t>(i),
                                               fix_text.begin() + static_cast<std::ptrdiff_t>(end));
            const auto split = split_pinyin(token);
            if (!split) {
                throw ParseError(source_name_, brace.line, brace.column, where,
                                 "\"" + written_text(fix_text, i, end) +
                                     "\" is not Mandarin in numbered pinyin; write the reading in Chinese "
                                     "characters or pinyin, e.g. 2026{两千零二十六} or OK{ou1 kei4}");
            }
            for (const auto& syllable : *split)
                syllables.push_back(make_syllable(syllable.written, syllable.pinyin));
            i = end;
        } else {
            throw ParseError(
                source_name_, brace.line, brace.column, where,
                describe_character(c) + " is neither a Chinese character with a reading nor numbered pinyin");
        }
    }
    flush();
    if (syllables.empty()) {
        throw ParseError(source_name_, brace.line, brace.column, where,
                         "the fix is empty; write how the form is said, e.g. 2026{两千零二十六}");
    }
    timeline_.syllables.resize(form.first_syllable);
    // What the reader said of the form (a word it did not know) no longer holds.
    timeline_.warnings.resize(form_warnings_);
    form.syllable_count = syllables.size();
    for (auto& syllable : syllables) timeline_.syllables.push_back(std::move(syllable));
    last_form_end_.reset();
}

}  // namespace talkface::detail

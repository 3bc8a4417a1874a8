// Transcript -> sentences and syllables [thesis 3.3.2; SPEC "Transcript to syllables"]. The
// thesis picked the reading of each polyphonic character by hand; here a phrase table decides
// (longest match first), then the character's most frequent reading.
#include "talkface/transcript.hpp"

#include <algorithm>
#include <cstdio>
#include <optional>
#include <vector>

#include "common/atomic_file.hpp"
#include "text/reading_tables.hpp"
#include "talkface/errors.hpp"

namespace talkface {
inline namespace v0 {

namespace {

struct CodePoint {
    char32_t value = 0;
    std::string_view text;  // its UTF-8 bytes in the transcript
    int line = 1;
    int column = 1;  // in characters
};

std::vector<CodePoint> decode_utf8(std::string_view text, const std::string& source_name) {
    std::vector<CodePoint> code_points;
    code_points.reserve(text.size());
    int line = 1;
    int column = 1;
    std::size_t offset = text.substr(0, 3) == "\xEF\xBB\xBF" ? 3 : 0;
    while (offset < text.size()) {
        const auto lead = static_cast<unsigned char>(text[offset]);
        std::size_t length = 1;
        char32_t value = lead;
        char32_t minimum = 0;
        if (lead >= 0xF0 && lead <= 0xF4) {
            length = 4;
            value = lead & 0x07U;
            minimum = 0x10000;
        } else if (lead >= 0xE0 && lead <= 0xEF) {
            length = 3;
            value = lead & 0x0FU;
            minimum = 0x800;
        } else if (lead >= 0xC2 && lead <= 0xDF) {
            length = 2;
            value = lead & 0x1FU;
            minimum = 0x80;
        } else if (lead >= 0x80) {
            length = 0;  // a continuation byte, or C0 C1 F5..FF, which never start a character
        }
        for (std::size_t i = 1; length > 0 && i < length; ++i) {
            const auto next = offset + i < text.size() ? static_cast<unsigned char>(text[offset + i]) : 0U;
            if ((next & 0xC0U) != 0x80U) {
                length = 0;
            } else {
                value = (value << 6) | (next & 0x3FU);
            }
        }
        // Overlong forms, UTF-16 surrogates and values past U+10FFFF are not characters.
        if (length == 0 || value < minimum || (value >= 0xD800 && value <= 0xDFFF) || value > 0x10FFFF) {
            char byte_text[8];
            std::snprintf(byte_text, sizeof byte_text, "0x%02X", static_cast<unsigned>(lead));
            throw ParseError(source_name, line, column, "byte offset " + std::to_string(offset),
                             std::string("invalid UTF-8: the sequence starting with byte ") + byte_text +
                                 " is not a character; save the transcript as UTF-8");
        }
        code_points.push_back({value, text.substr(offset, length), line, column});
        offset += length;
        if (value == '\n') {
            ++line;
            column = 1;
        } else {
            ++column;
        }
    }
    return code_points;
}

bool is_space(char32_t c) {
    return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' || c == '\f' || c == 0xA0 ||
           c == 0x3000 || c == 0xFEFF;
}

// Full-width ASCII forms (！？，Ａ１％) behave as their ASCII counterparts.
char32_t ascii_form(char32_t c) {
    return c >= 0xFF01 && c <= 0xFF5E ? c - 0xFEE0 : c;
}

bool ends_sentence(char32_t c) {
    const auto a = ascii_form(c);
    return a == '.' || a == '!' || a == '?' || a == ';' || c == 0x3002 /*。*/ || c == 0xFF61 /*｡*/ ||
           c == 0x2026 /*…*/ || c == 0x22EF /*⋯*/;
}

bool marks_pause(char32_t c) {
    const auto a = ascii_form(c);
    return a == ',' || a == ':' || c == 0x3001 /*、*/ || c == 0xFF64 /*､*/ || c == 0xFE50 || c == 0xFE51 ||
           c == 0xFE55;
}

// Closing quotes and brackets after an end mark belong to the sentence it ends: 「好。」
bool closes_quote(char32_t c) {
    const auto a = ascii_form(c);
    return a == '"' || a == '\'' || a == ')' || a == ']' || a == '}' || c == 0x300D /*」*/ ||
           c == 0x300F /*』*/ || c == 0x201D /*”*/ || c == 0x2019 /*’*/ || c == 0x300B /*》*/ ||
           c == 0x3009 /*〉*/ || c == 0x3011 /*】*/ || c == 0x3015 /*〕*/ || c == 0x3017 /*〗*/ ||
           c == 0xFE42 || c == 0xFE44;
}

// Punctuation that is not spoken (quotes, brackets, dashes, dots between names) stays in the
// sentence text silently. Symbols a reader says aloud (% $ + = & @ #) are not here: they get a
// warning like letters and digits, since the speech holds words the transcript lacks there.
bool is_silent_punctuation(char32_t c) {
    const auto a = ascii_form(c);
    if (a < 0x80) {
        return a == '"' || a == '\'' || a == '(' || a == ')' || a == '[' || a == ']' || a == '<' ||
               a == '>' || a == '-' || a == '_' || a == '/' || a == '\\' || a == '`' || a == '|';
    }
    return c == 0xB7 /*·*/ || c == 0x30FB /*・*/ || (c >= 0x2010 && c <= 0x2027) ||
           (c >= 0x2032 && c <= 0x205E) || (c >= 0x3000 && c <= 0x303F) || (c >= 0xFE10 && c <= 0xFE1F) ||
           (c >= 0xFE30 && c <= 0xFE6B) || (c >= 0xFF5F && c <= 0xFF65);
}

bool is_pinyin_letter(char32_t c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == 0xFC /*ü*/ || c == 0xDC /*Ü*/;
}

bool is_digit(char32_t c) {
    return c >= '0' && c <= '9';
}

bool is_capital(char32_t c) {
    return (c >= 'A' && c <= 'Z') || c == 0xDC;
}

// Where a run of letters and digits that may be pinyin ends: "lu:4" and "xi'an" are one token,
// but a colon or apostrophe that does not continue a syllable is punctuation ("hao3:", "ni3'").
std::size_t end_of_token(const std::vector<CodePoint>& text, std::size_t start) {
    auto end = start;
    while (end < text.size()) {
        const auto c = text[end].value;
        const bool continues =
            is_pinyin_letter(c) || is_digit(c) ||
            (c == ':' && end > start && (text[end - 1].value == 'u' || text[end - 1].value == 'U')) ||
            (c == '\'' && end > start && end + 1 < text.size() && is_pinyin_letter(text[end + 1].value));
        if (!continues) break;
        ++end;
    }
    return end;
}

std::string describe_character(const CodePoint& c) {
    char code[16];
    std::snprintf(code, sizeof code, "U+%04X", static_cast<unsigned>(c.value));
    if (c.value < 0x20 || c.value == 0x7F) return code;
    return "\"" + std::string(c.text) + "\" (" + code + ")";
}

struct WrittenSyllable {
    std::string written;
    std::string pinyin;
};

// Splits a pinyin token into syllables ("ni3hao3", "xi'an", "nihao"), or nullopt if it does
// not spell Mandarin. Among the splits with fewest syllables the one with the longer first
// syllables wins ("xian" is one syllable, as in pinyin's own spelling rule).
std::optional<std::vector<WrittenSyllable>> split_pinyin(const std::vector<CodePoint>& token) {
    std::vector<WrittenSyllable> syllables;
    std::size_t part_start = 0;
    while (part_start <= token.size()) {
        std::size_t part_end = part_start;
        while (part_end < token.size() && token[part_end].value != '\'') ++part_end;
        const auto count = part_end - part_start;
        if (count == 0) return std::nullopt;
        auto written = [&](std::size_t from, std::size_t to) {
            std::string text;
            for (auto i = part_start + from; i < part_start + to; ++i) text += token[i].text;
            return text;
        };
        // fewest[i]: fewest syllables spelling the part's code points from i on (count+1 = none).
        constexpr std::size_t kLongestSyllable = 7;  // "zhuang" + tone digit
        std::vector<std::size_t> fewest(count + 1, count + 1);
        fewest[count] = 0;
        for (std::size_t i = count; i-- > 0;) {
            for (std::size_t end = i + 1; end <= std::min(count, i + kLongestSyllable); ++end) {
                if (fewest[end] < fewest[i] - 1 && !detail::normalise_pinyin(written(i, end)).empty()) {
                    fewest[i] = fewest[end] + 1;
                }
            }
        }
        if (fewest[0] > count) return std::nullopt;
        for (std::size_t i = 0; i < count;) {
            for (std::size_t end = std::min(count, i + kLongestSyllable); end > i; --end) {
                auto pinyin = detail::normalise_pinyin(written(i, end));
                if (!pinyin.empty() && fewest[end] + 1 == fewest[i]) {
                    syllables.push_back({written(i, end), std::move(pinyin)});
                    i = end;
                    break;
                }
            }
        }
        part_start = part_end + 1;
    }
    return syllables;
}

// A pinyin token with capitals past its first letter ("TV", "ME") is taken for Latin text.
bool looks_like_pinyin(const std::vector<CodePoint>& token) {
    bool has_tone = false;
    bool has_inner_capital = false;
    for (std::size_t i = 0; i < token.size(); ++i) {
        const auto c = token[i].value;
        has_tone = has_tone || is_digit(c);
        has_inner_capital = has_inner_capital || (is_capital(c) && i > 0 && token[i - 1].value != '\'');
    }
    return has_tone || !has_inner_capital;
}

struct HanCharacter {
    const CodePoint* code_point;
    std::string fix;  // a reading fix, normalised; empty if none
};

class TranscriptReader {
public:
    TranscriptReader(const TranscriptOptions& options, const std::string& source_name)
        : options_(options), source_name_(source_name), tables_(detail::reading_tables()) {}

    Timeline read(const std::vector<CodePoint>& text) {
        for (std::size_t i = 0; i < text.size();) i = read_item(text, i);
        close_sentence();
        return std::move(timeline_);
    }

private:
    // Reads the item starting at text[i]; returns where the next one starts.
    std::size_t read_item(const std::vector<CodePoint>& text, std::size_t i) {
        const auto& c = text[i];
        if (is_space(c.value)) {
            pending_space_ += c.text;
            return i + 1;
        }
        if (c.value == '{') return read_fix(text, i);
        if (tables_.character_readings.count(c.text) != 0) {
            if (sentence_ended_) close_sentence();
            append_text(c.text);
            run_.push_back({&c, {}});
            return i + 1;
        }
        flush_run();
        if (sentence_ended_ && !(ends_sentence(c.value) || closes_quote(c.value))) close_sentence();
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
        if (is_pinyin_letter(c.value) || is_digit(c.value)) return read_token(text, i);
        append_text(c.text);
        if (!is_silent_punctuation(c.value)) warn_no_reading(c);
        return i + 1;
    }

    std::size_t read_token(const std::vector<CodePoint>& text, std::size_t start) {
        const auto end = end_of_token(text, start);
        const std::vector<CodePoint> token(text.begin() + static_cast<std::ptrdiff_t>(start),
                                           text.begin() + static_cast<std::ptrdiff_t>(end));
        std::optional<std::vector<WrittenSyllable>> syllables;
        if (options_.read_pinyin && looks_like_pinyin(token)) syllables = split_pinyin(token);
        for (const auto& c : token) append_text(c.text);
        if (!syllables) {
            for (const auto& c : token) {
                if (!is_silent_punctuation(c.value)) warn_no_reading(c);
            }
            return end;
        }
        for (auto& syllable : *syllables)
            add_syllable(std::move(syllable.written), std::move(syllable.pinyin));
        return end;
    }

    // 行{hang2}: overrides the reading of the character right before the brace.
    std::size_t read_fix(const std::vector<CodePoint>& text, std::size_t open) {
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
        const bool follows_character =
            !run_.empty() && pending_space_.empty() && run_.back().code_point == &text[open - 1];
        if (!follows_character) {
            throw ParseError(source_name_, brace.line, brace.column, "reading fix \"{" + written + "}\"",
                             "a fix must directly follow the Chinese character it reads, as in 行{hang2}");
        }
        auto pinyin = detail::normalise_pinyin(written);
        if (pinyin.empty()) {
            throw ParseError(
                source_name_, brace.line, brace.column,
                "reading fix \"{" + written + "}\" for \"" + std::string(text[open - 1].text) + "\"",
                "\"" + written +
                    "\" is not a Mandarin syllable in numbered pinyin (tone 1-5 optional), "
                    "e.g. hang2, lv4");
        }
        run_.back().fix = std::move(pinyin);
        return close + 1;
    }

    // Reads the pending run of Chinese characters: longest phrase first, then each character's
    // most frequent reading; fixes win over both.
    void flush_run() {
        for (std::size_t i = 0; i < run_.size();) {
            std::size_t matched = 1;
            const std::vector<std::string_view>* readings = nullptr;
            for (auto length = std::min(tables_.longest_phrase_characters, run_.size() - i); length >= 2;
                 --length) {
                std::string phrase;
                for (std::size_t k = i; k < i + length; ++k) phrase += run_[k].code_point->text;
                const auto found = tables_.phrase_readings.find(phrase);
                if (found != tables_.phrase_readings.end() && found->second.size() == length) {
                    readings = &found->second;
                    matched = length;
                    break;
                }
            }
            for (std::size_t k = 0; k < matched; ++k) {
                const auto& character = run_[i + k];
                std::string pinyin = character.fix;
                if (pinyin.empty()) {
                    pinyin =
                        readings != nullptr
                            ? std::string((*readings)[k])
                            : std::string(tables_.character_readings.at(character.code_point->text).front());
                    check_table_reading(character, pinyin);
                }
                add_syllable(std::string(character.code_point->text), std::move(pinyin));
            }
            i += matched;
        }
        run_.clear();
    }

    void check_table_reading(const HanCharacter& character, const std::string& pinyin) const {
        if (detail::normalise_pinyin(pinyin) != pinyin) {
            throw Error(ErrorCode::internal,
                        "internal error (a bug in talkface): the reading table gives \"" +
                            std::string(character.code_point->text) + "\" the reading \"" + pinyin +
                            "\", not a Mandarin syllable");
        }
    }

    void add_syllable(std::string text, std::string pinyin) {
        Syllable syllable;
        syllable.text = std::move(text);
        syllable.pinyin = std::move(pinyin);
        syllable.sentence = timeline_.sentences.size();
        timeline_.syllables.push_back(std::move(syllable));
    }

    // Whitespace between two Chinese characters is layout (a wrapped line), not text; elsewhere
    // a run of it becomes one space, or stays as written if it holds no line break.
    void append_text(std::string_view text) {
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

    // A sentence without syllables (only punctuation, or only characters already warned about)
    // has nothing to align and is left out.
    void close_sentence() {
        flush_run();
        const bool has_syllables =
            !timeline_.syllables.empty() && timeline_.syllables.back().sentence == timeline_.sentences.size();
        if (has_syllables) timeline_.sentences.push_back({sentence_text_, 0.0, 0.0});
        sentence_text_.clear();
        pending_space_.clear();
        sentence_ended_ = false;
    }

    void warn_no_reading(const CodePoint& c) {
        timeline_.warnings.push_back(source_name_ + ":" + std::to_string(c.line) + ":" +
                                     std::to_string(c.column) + ": " + describe_character(c) +
                                     " has no Mandarin reading; skipped");
    }

    const TranscriptOptions& options_;
    const std::string& source_name_;
    const detail::ReadingTables& tables_;
    Timeline timeline_;
    std::vector<HanCharacter> run_;  // Chinese characters not yet read, in order
    std::string sentence_text_;
    std::string pending_space_;
    bool sentence_ended_ = false;  // an end mark was seen; closing quotes may still follow
};

}  // namespace

Timeline read_transcript(std::string_view utf8_text, const TranscriptOptions& options,
                         const std::string& source_name) {
    const auto code_points = decode_utf8(utf8_text, source_name);
    return TranscriptReader(options, source_name).read(code_points);
}

Timeline load_transcript(const std::string& path, const TranscriptOptions& options) {
    return read_transcript(detail::read_file(path), options, path);
}

bool is_valid_pinyin(std::string_view syllable) {
    return !syllable.empty() && syllable.back() >= '1' && syllable.back() <= '5' &&
           detail::normalise_pinyin(syllable) == syllable;
}

}  // namespace v0
}  // namespace talkface

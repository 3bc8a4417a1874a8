// Praat's TextGrid. Written in the long text format, as Praat itself writes it: a "sentences" tier of the
// sentences' texts and a "syllables" tier of numbered pinyin, each tier covering 0 to the audio's
// end with empty intervals between (Praat requires the intervals of a tier to tile it). Lossy:
// drops characters, final starts, confidences and pause marks. Read (below) in either of Praat's
// text formats: the syllables or words tier of a TextGrid from Praat or Montreal Forced Aligner.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "common/number_format.hpp"
#include "common/utf8.hpp"
#include "talkface/errors.hpp"
#include "timing/export_writers.hpp"
#include "timing/import_readers.hpp"

namespace talkface::detail {

namespace {

struct Interval {
    double start_s;
    double end_s;
    std::string text;
};

// Praat doubles a quote inside a string.
std::string praat_string(const std::string& text) {
    std::string out = "\"";
    for (const char c : text) out += c == '"' ? std::string("\"\"") : std::string(1, c);
    return out + "\"";
}

// The labelled spans in order, clipped to 0..end_s and to the span before them, gaps filled with
// empty intervals: a tier Praat reads.
std::vector<Interval> tile(const std::vector<Interval>& labelled, double end_s) {
    std::vector<Interval> tier;
    double at_s = 0.0;
    for (const Interval& span : labelled) {
        const double start_s = std::max(span.start_s, at_s);
        const double stop_s = std::min(span.end_s, end_s);
        if (!(stop_s > start_s)) continue;  // a span of no length cannot be an interval
        if (start_s > at_s) tier.push_back({at_s, start_s, ""});
        tier.push_back({start_s, stop_s, span.text});
        at_s = stop_s;
    }
    if (end_s > at_s) tier.push_back({at_s, end_s, ""});
    return tier;
}

void append_tier(std::string& out, int number, const char* name, const std::vector<Interval>& tier, double end_s) {
    out += "    item [" + std::to_string(number) + "]:\n";
    out += "        class = \"IntervalTier\" \n";
    out += std::string("        name = \"") + name + "\" \n";
    out += "        xmin = 0 \n";
    out += "        xmax = " + format_shortest(end_s) + " \n";
    out += "        intervals: size = " + std::to_string(tier.size()) + " \n";
    for (std::size_t k = 0; k < tier.size(); ++k) {
        out += "        intervals [" + std::to_string(k + 1) + "]:\n";
        out += "            xmin = " + format_shortest(tier[k].start_s) + " \n";
        out += "            xmax = " + format_shortest(tier[k].end_s) + " \n";
        out += "            text = " + praat_string(tier[k].text) + " \n";
    }
}

}  // namespace

std::string textgrid(const Timeline& timeline) {
    double end_s = timeline.duration_s;
    for (const Sentence& sentence : timeline.sentences) end_s = std::max(end_s, sentence.end_s);
    for (const Syllable& syllable : timeline.syllables) end_s = std::max(end_s, syllable.end_s);
    std::vector<Interval> sentences;
    for (const Sentence& sentence : timeline.sentences) sentences.push_back({sentence.start_s, sentence.end_s, sentence.text});
    std::vector<Interval> syllables;
    for (const Syllable& syllable : timeline.syllables) syllables.push_back({syllable.start_s, syllable.end_s, syllable.pinyin});
    std::string out = "File type = \"ooTextFile\"\nObject class = \"TextGrid\"\n\n";
    out += "xmin = 0 \nxmax = " + format_shortest(end_s) + " \ntiers? <exists> \nsize = 2 \nitem []: \n";
    append_tier(out, 1, "sentences", tile(sentences, end_s), end_s);
    append_tier(out, 2, "syllables", tile(syllables, end_s), end_s);
    return out;
}

}  // namespace talkface::detail

// ---- Reading ------------------------------------------------------------------------------------

namespace talkface::detail {

namespace {

// Praat's text files are a sequence of values: numbers, "strings" ("" is a quote inside) and
// <flags>; in the long format each value follows a label (xmin =, intervals [3]:) that Praat
// skips, as this reader does.
struct Token {
    enum class Type { number, string, flag, word } type;  // word: a bare word where a value belongs
    std::string text;
    double number = 0.0;
    int line = 0;
};

std::vector<Token> praat_tokens(const std::string& text, const std::string& source) {
    std::vector<Token> tokens;
    int line = 1;
    bool is_after_equals = false;
    for (std::size_t k = 0; k < text.size();) {
        const char c = text[k];
        if (c == '\n') {
            ++line;
            ++k;
        } else if (c == '"') {
            Token token{Token::Type::string, "", 0.0, line};
            ++k;
            for (;;) {
                if (k >= text.size()) throw ParseError(source, token.line, 0, "", "a string is not closed (expected \")");
                if (text[k] == '"') {
                    if (k + 1 < text.size() && text[k + 1] == '"') {
                        token.text += '"';
                        k += 2;
                        continue;
                    }
                    ++k;
                    break;
                }
                if (text[k] == '\n') ++line;
                token.text += text[k++];
            }
            tokens.push_back(std::move(token));
        } else if (c == '<') {
            const std::size_t close = text.find('>', k);
            if (close == std::string::npos) throw ParseError(source, line, 0, "", "a <flag> is not closed (expected >)");
            tokens.push_back({Token::Type::flag, text.substr(k + 1, close - k - 1), 0.0, line});
            k = close + 1;
        } else if (c == '[') {
            const std::size_t close = text.find(']', k);  // an index label: intervals [3]:
            if (close == std::string::npos) throw ParseError(source, line, 0, "", "a [label] is not closed (expected ])");
            k = close + 1;
        } else if ((c >= '0' && c <= '9') || c == '-' || c == '+' || c == '.') {
            std::size_t end = k + 1;
            while (end < text.size() && (std::isalnum(static_cast<unsigned char>(text[end])) || text[end] == '.' ||
                                         text[end] == '-' || text[end] == '+')) {
                ++end;
            }
            const std::optional<double> number = parse_double(std::string_view(text).substr(k, end - k));
            if (!number || !std::isfinite(*number)) {
                throw ParseError(source, line, 0, "", "expected a number, found \"" + text.substr(k, end - k) + "\"");
            }
            tokens.push_back({Token::Type::number, text.substr(k, end - k), *number, line});
            k = end;
        } else if (std::isalpha(static_cast<unsigned char>(c))) {
            const std::size_t start = k;
            while (k < text.size() && (std::isalnum(static_cast<unsigned char>(text[k])) || text[k] == '_')) ++k;
            // A word is a label, unless it stands where a value belongs: after "=".
            if (is_after_equals) tokens.push_back({Token::Type::word, text.substr(start, k - start), 0.0, line});
        } else {
            ++k;  // = : ? spaces and the like, between labels and values
        }
        if (c == '=') {
            is_after_equals = true;
        } else if (c != ' ' && c != '\t') {
            is_after_equals = false;
        }
    }
    return tokens;
}

class TokenReader {
public:
    TokenReader(std::vector<Token> tokens, const std::string& source) : tokens_(std::move(tokens)), source_(source) {}

    [[noreturn]] void fail(const std::string& expected) const {
        const int line = at_ < tokens_.size() ? tokens_[at_].line : (tokens_.empty() ? 0 : tokens_.back().line);
        const std::string found = at_ < tokens_.size() ? "\"" + tokens_[at_].text + "\"" : "the end of the file";
        throw ParseError(source_, line, 0, "", "expected " + expected + ", found " + found);
    }

    const Token& next(Token::Type type, const std::string& expected) {
        if (at_ >= tokens_.size() || tokens_[at_].type != type) fail(expected);
        return tokens_[at_++];
    }

    double number(const std::string& expected) { return next(Token::Type::number, expected).number; }
    const Token& string(const std::string& expected) { return next(Token::Type::string, expected); }

    std::size_t count(const std::string& expected) {
        const Token& token = next(Token::Type::number, expected);
        if (token.number < 0 || token.number != std::floor(token.number) || token.number > 1e8) {
            --at_;
            fail(expected);
        }
        return static_cast<std::size_t>(token.number);
    }

    bool is_flag_next() const { return at_ < tokens_.size() && tokens_[at_].type == Token::Type::flag; }
    void skip() { ++at_; }

private:
    std::vector<Token> tokens_;
    const std::string& source_;
    std::size_t at_ = 0;
};

struct Tier {
    std::string name;
    bool is_interval = false;
    std::vector<TimedUnit> intervals;
};

}  // namespace

namespace {

std::vector<Tier> read_tiers(std::string_view text, const std::string& source) {
    TokenReader reader(praat_tokens(utf8_from_marked_text(text, source), source), source);
    if (reader.string("File type = \"ooTextFile\"").text != "ooTextFile") reader.fail("File type = \"ooTextFile\"");
    const Token& object_class = reader.string("Object class = \"TextGrid\"");
    if (object_class.text != "TextGrid") {
        throw ParseError(source, object_class.line, 0, "", "expected Object class = \"TextGrid\", found \"" +
                                                               object_class.text + "\"");
    }
    reader.number("the TextGrid's xmin");
    reader.number("the TextGrid's xmax");
    if (!reader.is_flag_next()) reader.fail("tiers? <exists>");
    reader.skip();
    const std::size_t tier_count = reader.count("the number of tiers (size = N)");
    std::vector<Tier> tiers;
    for (std::size_t t = 0; t < tier_count; ++t) {
        Tier tier;
        const std::string tier_class = reader.string("a tier's class, \"IntervalTier\" or \"TextTier\"").text;
        if (tier_class != "IntervalTier" && tier_class != "TextTier") {
            reader.fail("a tier's class, \"IntervalTier\" or \"TextTier\"");
        }
        tier.is_interval = tier_class == "IntervalTier";
        tier.name = reader.string("the tier's name").text;
        reader.number("the tier's xmin");
        reader.number("the tier's xmax");
        const std::size_t count = reader.count(tier.is_interval ? "the number of intervals" : "the number of points");
        for (std::size_t k = 0; k < count; ++k) {
            if (tier.is_interval) {
                TimedUnit unit;
                unit.start_s = reader.number("an interval's xmin");
                unit.end_s = reader.number("an interval's xmax");
                const Token& label = reader.string("an interval's text");
                unit.text = label.text;
                unit.line = label.line;
                tier.intervals.push_back(std::move(unit));
            } else {
                reader.number("a point's time");
                reader.string("a point's mark");
            }
        }
        tiers.push_back(std::move(tier));
    }
    return tiers;
}

const Tier* tier_named(const std::vector<Tier>& tiers, const char* name) {
    for (const Tier& tier : tiers) {
        if (tier.is_interval && tier.name == name) return &tier;
    }
    return nullptr;
}

const Tier& syllables_or_words(const std::vector<Tier>& tiers, const std::string& source) {
    for (const char* wanted : {"syllables", "words"}) {
        if (const Tier* tier = tier_named(tiers, wanted)) return *tier;
    }
    std::string names;
    const Tier* only = nullptr;
    std::size_t interval_tiers = 0;
    for (const Tier& tier : tiers) {
        names += (names.empty() ? "\"" : ", \"") + tier.name + "\"";
        if (tier.is_interval) {
            ++interval_tiers;
            only = &tier;
        }
    }
    if (interval_tiers != 1) {
        throw ParseError(source, 0, 0, "",
                         "expected an interval tier named \"syllables\" or \"words\" (or only one interval tier), "
                         "found " + (names.empty() ? std::string("no tiers") : "tiers " + names));
    }
    return *only;
}

}  // namespace

std::vector<TimedUnit> read_textgrid_units(std::string_view text, const std::string& source) {
    return syllables_or_words(read_tiers(text, source), source).intervals;
}

TextGridText read_textgrid_text_units(std::string_view text, const std::string& source) {
    const auto tiers = read_tiers(text, source);
    if (const Tier* sentences = tier_named(tiers, "sentences")) return {sentences->intervals, true};
    return {syllables_or_words(tiers, source).intervals, false};
}

}  // namespace talkface::detail

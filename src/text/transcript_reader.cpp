// Transcript -> sentences and syllables [thesis 3.3.2; SPEC "Transcript to syllables"]. The
// thesis picked the reading of each polyphonic character by hand; here the word it stands in
// decides (word_segmentation.hpp), then the character's most frequent reading.
#include "talkface/transcript.hpp"

#include <algorithm>
#include <cstdio>
#include <map>
#include <optional>
#include <vector>

#include "common/internal_error.hpp"
#include "talkface/errors.hpp"
#include "text/aspect_particle.hpp"
#include "text/code_points.hpp"
#include "text/dates_and_times.hpp"
#include "text/digit_codes.hpp"
#include "text/drawn_faces.hpp"
#include "text/latin_words.hpp"
#include "text/number_words.hpp"
#include "text/reading_tables.hpp"
#include "text/return_verb.hpp"
#include "text/script_marks.hpp"
#include "text/script_variant.hpp"
#include "text/transcript_cut.hpp"
#include "text/web_addresses.hpp"
#include "text/word_segmentation.hpp"
#include "text/written_number_scan.hpp"
#include "text/written_numbers.hpp"

namespace talkface {
inline namespace v0 {

namespace {

using detail::ascii_form;
using detail::CodePoint;
using detail::decode_utf8;
using detail::is_ascii_capital;
using detail::is_ascii_digit;
using detail::is_ascii_letter;
using detail::starts_with_any;

bool is_space(char32_t c) {
    return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' || c == '\f' || c == 0xA0 ||
           c == 0x3000 || c == 0xFEFF;
}

// Two line breaks with nothing but spaces between them.
bool has_blank_line(std::string_view space) {
    const std::size_t first = space.find('\n');
    if (first == std::string_view::npos) return false;
    return space.find('\n', first + 1) != std::string_view::npos;
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

// Punctuation that is not spoken (quotes, brackets, dashes, dots between names, a tilde: GB/T
// 15834's 连接号, which a chat line also writes to draw a word out, 好的～) stays in the sentence
// text silently. Symbols a reader says aloud (% $ + = & @ #) are not here: they get a
// warning like letters and digits, since the speech holds words the transcript lacks there.
bool is_silent_punctuation(char32_t c) {
    const auto a = ascii_form(c);
    if (a < 0x80) {
        return a == '"' || a == '\'' || a == '(' || a == ')' || a == '[' || a == ']' || a == '<' ||
               a == '>' || a == '-' || a == '_' || a == '/' || a == '\\' || a == '`' || a == '|' || a == '~';
    }
    return c == 0xB7 /*·*/ || c == 0x30FB /*・*/ || (c >= 0x2010 && c <= 0x2027) ||
           (c >= 0x2032 && c <= 0x205E) || (c >= 0x3000 && c <= 0x303F) || (c >= 0xFE10 && c <= 0xFE1F) ||
           (c >= 0xFE30 && c <= 0xFE6B) || (c >= 0xFF5F && c <= 0xFF65);
}

// The dot after a choice's letter (A.正确 B.错误, as a lesson's question lists its choices): a
// capital A to H alone, the dot, and a Chinese character right after it. It ends no sentence and
// is not said (session 14: the question was cut into a sentence at each choice).
bool marks_choice(const std::vector<CodePoint>& text, std::size_t i) {
    if (ascii_form(text[i].value) != '.' || i == 0 || i + 1 >= text.size()) return false;
    const auto letter = ascii_form(text[i - 1].value);
    if (letter < 'A' || letter > 'H') return false;
    if (i >= 2) {
        const auto before = ascii_form(text[i - 2].value);
        if ((before >= 'A' && before <= 'Z') || (before >= 'a' && before <= 'z') || (before >= '0' && before <= '9'))
            return false;
    }
    const auto next = text[i + 1].value;
    return next >= 0x3400 && next <= 0x9FFF;
}

// The dot after a list item's number (积分榜：1.利物浦 68分 2.阿森纳 65分, as a table or a list numbers its
// rows): one or two digits at the start of a line or after a space or a colon, the dot, and a Chinese
// character right after it. It ends no sentence and is not said (session 16: the table was cut into a
// sentence at each row). A number after a word (增长了3.接下来) still ends its sentence.
bool marks_list_item(const std::vector<CodePoint>& text, std::size_t i) {
    constexpr std::size_t kMostDigits = 2;
    if (ascii_form(text[i].value) != '.' || i == 0 || i + 1 >= text.size()) return false;
    auto k = i;
    while (k > 0 && i - k < kMostDigits + 1 && ascii_form(text[k - 1].value) >= '0' && ascii_form(text[k - 1].value) <= '9') --k;
    if (k == i || i - k > kMostDigits) return false;
    if (k > 0) {
        const auto before = ascii_form(text[k - 1].value);
        if (!(before == '\n' || before == ' ' || before == ':' || before == 0x3000)) return false;
    }
    const auto next = text[i + 1].value;
    return next >= 0x3400 && next <= 0x9FFF;
}

// The dot in a virus lineage's name (XBB.1.5, BA.2, JN.1): two or more capitals, the dot and a digit. It
// ends no sentence and is not said, as the name is read (XBB 一点五; session 28: 毒株为XBB.1.5。 was cut
// after XBB.). A capital alone before a dot may be a choice's or an initial's.
bool marks_lineage_dot(const std::vector<CodePoint>& text, std::size_t i) {
    if (ascii_form(text[i].value) != '.' || !detail::is_digit_at(text, i + 1)) return false;
    auto k = i;
    while (k > 0 && is_ascii_capital(text[k - 1].value)) --k;
    return i - k >= 2 && (k == 0 || !is_ascii_letter(text[k - 1].value));
}

// A # that opens or closes a topic (#春节快乐#, as Weibo and other posts mark one): a bracket, not
// said; the topic between them is read. A # with no partner on its line (#5) is still a symbol.
bool marks_topic(const std::vector<CodePoint>& text, std::size_t i) {
    constexpr std::size_t kLongestTopic = 30;  // code points between the two marks
    const auto is_mark = [&](std::size_t k) { return ascii_form(text[k].value) == '#'; };
    const auto breaks_topic = [&](std::size_t k) {
        const auto c = text[k].value;
        return c == '\n' || c == ' ' || c == 0x3000 || ends_sentence(c);
    };
    for (std::size_t k = i + 1; k < text.size() && k <= i + kLongestTopic + 1 && !breaks_topic(k); ++k)
        if (is_mark(k)) return k > i + 1;
    for (std::size_t k = i; k-- > 0 && k + kLongestTopic + 1 >= i && !breaks_topic(k);)
        if (is_mark(k)) return k + 1 < i;
    return false;
}

// A $ that tags a stock's ticker ($TSLA, $AAPL, as posts and market news cite one): one to five capitals
// right after it and no letter or digit on either side, a tag not said; the ticker's letters are read
// (session 22: the $ was skipped with a warning). $5 stays dollars.
bool marks_ticker(const std::vector<CodePoint>& text, std::size_t i) {
    constexpr std::size_t kLongestTicker = 5;
    const auto is_word_character = [&](std::size_t k) {
        const auto c = ascii_form(text[k].value);
        return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9');
    };
    if (ascii_form(text[i].value) != '$' || (i > 0 && is_word_character(i - 1))) return false;
    auto k = i + 1;
    while (k < text.size() && ascii_form(text[k].value) >= 'A' && ascii_form(text[k].value) <= 'Z') ++k;
    return k > i + 1 && k - i - 1 <= kLongestTicker && (k == text.size() || !is_word_character(k));
}

// The @ of a screen's or a camera's mode between its resolution and its rate (4K@144Hz, 8K@60fps,
// 1080P@240fps, as spec sheets write them): no word, read as 4K 一百四十四赫兹 is (session 31: skipped with a
// warning). A resolution is digits and a K or a P; the rate's digits follow the @.
bool marks_screen_mode(const std::vector<CodePoint>& text, std::size_t i) {
    if (ascii_form(text[i].value) != '@' || i < 2 || !detail::is_digit_at(text, i + 1)) return false;
    return detail::is_one_of(ascii_form(text[i - 1].value), U"KkPp") && detail::is_digit_at(text, i - 2);
}

bool is_pinyin_letter(char32_t c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == 0xFC /*ü*/ || c == 0xDC /*Ü*/;
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
            is_pinyin_letter(c) || is_ascii_digit(c) ||
            (c == ':' && end > start && (text[end - 1].value == 'u' || text[end - 1].value == 'U')) ||
            (c == '\'' && end > start && end + 1 < text.size() && is_pinyin_letter(text[end + 1].value));
        if (!continues) break;
        ++end;
    }
    return end;
}

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

// Whether text[start] stands in a chemical formula, as a chemistry lesson writes one (H2SO4, Fe2O3,
// C6H12O6, NaCl): the run of ASCII letters and digits around it is element symbols (a capital and at
// most one small letter, from the periodic table) with their counts, a coefficient allowed before
// (2H2O), and it shows itself a formula: a count between two symbols (Fe2O3, H2O; Win10 has its
// digits only at the end), or, where a symbol has a small letter and none is counted (NaCl, NaOH), a
// word of chemistry in the sentence (溶液 反应 分子 离子 ...). Each letter is then said by its name,
// small ones too (Fe ai fu yi), and each count as a number (C6H12O6 C六H十二O六), as lessons read
// them (session 17: Fe was the pinyin fei, and a formula's O the pinyin o in a line without Chinese).
bool in_chemical_formula(const std::vector<CodePoint>& text, std::size_t start) {
    static constexpr std::string_view kSymbols[] = {
        "H",  "He", "Li", "Be", "B",  "C",  "N",  "O",  "F",  "Ne", "Na", "Mg", "Al", "Si", "P",  "S",  "Cl", "Ar", "K",
        "Ca", "Sc", "Ti", "V",  "Cr", "Mn", "Fe", "Co", "Ni", "Cu", "Zn", "Ga", "Ge", "As", "Se", "Br", "Kr", "Rb", "Sr",
        "Y",  "Zr", "Nb", "Mo", "Tc", "Ru", "Rh", "Pd", "Ag", "Cd", "In", "Sn", "Sb", "Te", "I",  "Xe", "Cs", "Ba", "La",
        "Ce", "Pr", "Nd", "Pm", "Sm", "Eu", "Gd", "Tb", "Dy", "Ho", "Er", "Tm", "Yb", "Lu", "Hf", "Ta", "W",  "Re", "Os",
        "Ir", "Pt", "Au", "Hg", "Tl", "Pb", "Bi", "Po", "At", "Rn", "Fr", "Ra", "Ac", "Th", "Pa", "U",  "Np", "Pu", "Am"};
    auto is_symbol = [](std::string_view symbol) {
        return std::find(std::begin(kSymbols), std::end(kSymbols), symbol) != std::end(kSymbols);
    };
    auto in_run = [&](std::size_t k) {
        return is_ascii_letter(text[k].value) || is_ascii_digit(text[k].value);
    };
    auto first = start;
    while (first > 0 && in_run(first - 1)) --first;
    auto end = start;
    while (end < text.size() && in_run(end)) ++end;
    auto k = first;
    while (k < end && is_ascii_digit(text[k].value)) ++k;  // a coefficient (2H2O)
    std::size_t symbols = 0;
    bool counted_between = false;
    bool has_small = false;
    while (k < end) {
        if (!is_ascii_capital(text[k].value)) return false;
        std::string symbol(1, static_cast<char>(text[k].value));
        if (k + 1 < end && text[k + 1].value >= 'a' && text[k + 1].value <= 'z') symbol += static_cast<char>(text[k + 1].value);
        if (!is_symbol(symbol)) return false;
        has_small = has_small || symbol.size() == 2;
        k += symbol.size();
        ++symbols;
        const auto count_start = k;
        while (k < end && is_ascii_digit(text[k].value)) ++k;
        counted_between = counted_between || (k > count_start && k < end);
    }
    if (symbols < 2) return false;
    if (counted_between) return true;
    if (!has_small) return false;
    const std::string sentence = detail::text_between(text, 0, text.size());
    return detail::contains_any(
        sentence, {"溶液", "溶于", "溶於", "反应", "反應", "化学", "化學", "分子", "离子", "離子", "浓度",
                   "濃度", "摩尔", "摩爾", "晶体", "晶體", "沉淀", "电解", "電解"});
}

// Whether the character next to a token (at `edge - 1` before it, step -1, or at `edge` after it,
// step 1; spaces skipped) is a sign a formula writes between or before terms (= < > ≈ ≠ ≤ ≥ + ×
// ÷ ∠ ⊥ ∥).
bool touches_formula_sign(const std::vector<CodePoint>& text, std::size_t edge, int step) {
    auto k = edge;
    if (step < 0) {
        while (k > 0 && text[k - 1].value == ' ') --k;
        if (k == 0) return false;
        --k;
    } else {
        while (k < text.size() && text[k].value == ' ') ++k;
        if (k == text.size()) return false;
    }
    return std::u32string_view(U"=<>+×÷≈≠≤≥∠⊥∥").find(text[k].value) !=
           std::u32string_view::npos;
}

// What a run of Latin letters spells, in ASCII (ｉＰｈｏｎｅ: iPhone), for the tables.
std::string latin_spelling(const std::vector<CodePoint>& text, std::size_t start, std::size_t end) {
    std::string spelling;
    for (auto k = start; k < end; ++k) {
        if (text[k].value < 0x80) {
            spelling += static_cast<char>(text[k].value);
        } else {
            spelling += text[k].text;
        }
    }
    return spelling;
}

// The character as written: a full-width one (～) is named by its own code point, not the ASCII
// form it is read as.
std::string describe_character(const CodePoint& c) {
    const auto written = decode_utf8(c.text, "<character>").front().value;
    char code[16];
    std::snprintf(code, sizeof code, "U+%04X", static_cast<unsigned>(written));
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
        auto spelling = [&](std::size_t from, std::size_t to) {
            return latin_spelling(token, part_start + from, part_start + to);
        };
        // fewest[i]: fewest syllables spelling the part's code points from i on (count+1 = none).
        constexpr std::size_t kLongestSyllable = 7;  // "zhuang" + tone digit
        std::vector<std::size_t> fewest(count + 1, count + 1);
        fewest[count] = 0;
        for (std::size_t i = count; i-- > 0;) {
            for (std::size_t end = i + 1; end <= std::min(count, i + kLongestSyllable); ++end) {
                if (fewest[end] < fewest[i] - 1 && !detail::normalise_pinyin(spelling(i, end)).empty()) {
                    fewest[i] = fewest[end] + 1;
                }
            }
        }
        if (fewest[0] > count) return std::nullopt;
        for (std::size_t i = 0; i < count;) {
            for (std::size_t end = std::min(count, i + kLongestSyllable); end > i; --end) {
                auto pinyin = detail::normalise_pinyin(spelling(i, end));
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
        has_tone = has_tone || is_ascii_digit(c);
        has_inner_capital = has_inner_capital || (is_capital(c) && i > 0 && token[i - 1].value != '\'');
    }
    return has_tone || !has_inner_capital;
}

// Small letters that start as only pinyin starts a word, x or q before i, or zh (xinhua, qingdao,
// zhejiang): a Chinese name or place, read as pinyin, even where the English dictionary lists it
// among its names (xinhua, which it says jin wa). English words that start with x or q do so
// before other letters (xerox, quick).
bool starts_as_pinyin_only(std::string_view letters) {
    return starts_with_any(letters, {"xi", "xu", "qi", "zh"});
}

bool has_tone_digit(const std::vector<CodePoint>& token) {
    return std::any_of(token.begin(), token.end(),
                       [](const CodePoint& c) { return is_ascii_digit(c.value); });
}

// Whether a pinyin split without tone digits holds a syllable only an interjection writes (m 呣, n 嗯,
// ng, hm, hng, lo 咯, yo 哟) beside others: no word or name spells one inside it, so the letters are a
// Latin word that happens to split (team te a m, Elon E lo n; session 26), not pinyin. A token that is
// that syllable alone (n, hm) is the interjection.
bool splits_into_interjection(const std::vector<WrittenSyllable>& split) {
    constexpr std::string_view kInterjectionOnly[] = {"m", "n", "ng", "hm", "hng", "lo", "yo"};
    if (split.size() < 2) return false;
    return std::any_of(split.begin(), split.end(), [&](const WrittenSyllable& syllable) {
        const auto toneless = syllable.pinyin.substr(0, syllable.pinyin.size() - 1);
        return std::find(std::begin(kInterjectionOnly), std::end(kInterjectionOnly), toneless) !=
               std::end(kInterjectionOnly);
    });
}

struct HanCharacter {
    const CodePoint* code_point;  // where it stands in the transcript; nullptr in a form's reading
    std::string_view text;
    std::string fix;  // a reading fix, normalised; empty if none
};

std::string toneless_of(const std::string& pinyin) {
    return pinyin.substr(0, pinyin.size() - 1);
}

class TranscriptReader {
public:
    TranscriptReader(const TranscriptOptions& options, const std::string& source_name)
        : options_(options), source_name_(source_name), tables_(detail::reading_tables()) {}

    // `lines_ending_sentences`: lines after which a sentence ends whatever its marks (a subtitle's
    // cues). With them, the lines between are the file's other lines blanked, no paragraph's end.
    Timeline read(const std::vector<CodePoint>& written,
                  const std::optional<std::vector<int>>& lines_ending_sentences = {}) {
        const auto text = width_folded(written);
        is_traditional_ = detail::is_traditional_text(text);
        has_han_ = std::any_of(text.begin(), text.end(),
                               [&](const CodePoint& c) { return tables_.has_readings(c.text); });
        const auto marks =
            options_.keep_directions ? std::vector<detail::ScriptMark>() : detail::find_script_marks(text);
        warn_script_marks(text, marks);
        drawing_ends_ = detail::find_drawing_ends(text);
        auto mark = marks.begin();
        int last_line = 0;  // of the last code point that is not a space
        for (std::size_t i = 0; i < text.size();) {
            if (lines_ending_sentences && text[i].value == '\n' &&
                pending_space_.find('\n') != std::string::npos) {
                ++i;
                continue;
            }
            const bool starts_line = !is_space(text[i].value) && text[i].line != last_line;
            if (starts_line && lines_ending_sentences &&
                std::binary_search(lines_ending_sentences->begin(), lines_ending_sentences->end(),
                                   last_line)) {
                break_sentence();
            }
            if (!is_space(text[i].value)) last_line = text[i].line;
            while (mark != marks.end() && mark->begin < i) ++mark;
            if (mark != marks.end() && mark->begin == i) {
                // A new speaker starts a new sentence, as a line break alone does not.
                if (mark->is_label) break_sentence();
                i = mark->end;
                continue;
            }
            i = read_item(text, i);
        }
        close_sentence();
        return std::move(timeline_);
    }

private:
    // Each stage direction left out, and each speaker's label once, with how many lines it starts.
    void warn_script_marks(const std::vector<CodePoint>& text, const std::vector<detail::ScriptMark>& marks) {
        constexpr const char* kKeep =
            "; left out (TranscriptOptions::keep_directions, --keep-directions, keeps it)";
        const auto written = [&](const detail::ScriptMark& mark) {
            auto out = written_text(text, mark.begin, mark.end);
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
            warn(text[mark.begin], "\"" + name + "\" is a speaker's label (" + std::to_string(lines) +
                                       (lines == 1 ? " line" : " lines") + "), not said" + kKeep);
            lines = 0;
        }
    }

    // Ends the sentence here; a blank line before what follows still starts a paragraph.
    void break_sentence() {
        const auto space = pending_space_;
        close_sentence();
        pending_space_ = space;
    }

    // A written form read aloud at text[i] (a web address, a number with what it says, a unit per another,
    // a slash said 每 or 和, a number character, a power, a formula's sign) added as its syllables, or a
    // subtitle's timing kept unsaid: the index past it, nullopt where none starts there.
    std::optional<std::size_t> read_written_form(const std::vector<CodePoint>& text, std::size_t i) {
        const auto& c = text[i];
        if (auto address = detail::read_web_address(text, i)) {
            form_warnings_ = timeline_.warnings.size();
            add_form(text, i, address->end, address_syllables(*address, c));
            return address->end;
        }
        // A subtitle's or a lyric's timing is no speech: kept in the sentence's text, not said.
        if (const auto timing_end = detail::past_subtitle_timing(text, i)) {
            append_text(written_text(text, i, *timing_end));
            return *timing_end;
        }
        if (auto form = detail::read_number_form(text, i)) {
            form_warnings_ = timeline_.warnings.size();
            if (!form->warning.empty()) warn(c, "\"" + written_text(text, i, form->end) + "\": " + form->warning);
            add_form(text, i, form->end, read_words(form->is_dialled ? with_local_one(form->words) : form->words));
            return form->end;
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
        return std::nullopt;
    }

    // Reads the item starting at text[i]; returns where the next one starts.
    std::size_t read_item(const std::vector<CodePoint>& text, std::size_t i) {
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
        if (c.value == '{') return read_fix(text, i);
        // An emoji or a face drawn in signs stays in its sentence's text, unsaid and unwarned, as
        // punctuation does; one after an end mark closes that sentence as a closing quote does.
        if (const auto drawing_end = drawing_ends_[i]; drawing_end != i) {
            flush_run();
            append_text(written_text(text, i, drawing_end));
            return drawing_end;
        }
        if (tables_.has_readings(c.text)) {
            if (sentence_ended_) close_sentence();
            append_text(c.text);
            run_.push_back({&c, c.text, {}});
            return i + 1;
        }
        flush_run(ends_sentence(c.value) || marks_pause(c.value) || closes_quote(c.value));
        if (sentence_ended_ && !(ends_sentence(c.value) || closes_quote(c.value))) close_sentence();
        if (const auto form_end = read_written_form(text, i)) return *form_end;
        if (marks_choice(text, i) || marks_list_item(text, i) || marks_lineage_dot(text, i)) {
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

    std::size_t read_token(const std::vector<CodePoint>& text, std::size_t start) {
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
            if (is_pinyin_letter(c.value)) letters += latin_spelling(token, &c - token.data(), &c - token.data() + 1);
        }
        const bool is_english_among_han =
            (has_han_ || (options_.read_pinyin && is_english_line(text, start))) &&
            (detail::is_all_capitals(letters) ||
             (!has_tone_digit(token) && !starts_as_pinyin_only(letters) &&
              detail::english_word_syllables(latin_spelling(text, start, end))));
        // Capitals beside a formula's sign are a lesson's letters in a line without Chinese
        // characters too (∠A=30° 角 A 等于三十度; session 14: A was the pinyin a).
        // With a count after it too (2H2+O2=2H2O: O2 was the pinyin o2; session 17).
        const bool is_formula_letter = detail::is_all_capitals(letters) &&
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
        for (auto& syllable : *syllables)
            add_syllable(std::move(syllable.written), std::move(syllable.pinyin));
        return end;
    }

    // Whether the line holding text[at] is English: more of its words are English words the dictionary
    // has that spell no pinyin (I, fix, it, no) than are pinyin it lacks (xiao, huan, Xiaoming), as in
    // "I can fix it", where a line of pinyin without tones holds a name or a brand at the most (wo xi
    // huan iPhone). A word that is both (can, man, long, you) or neither does not count, nor an acronym.
    // In such a line a word the dictionary has is English though it splits into syllables (can kan;
    // session 27: the pinyin can), as among Chinese characters. Known lines are kept, so that a long
    // line is scanned once.
    bool is_english_line(const std::vector<CodePoint>& text, std::size_t at) {
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

    // Latin letters that are not pinyin: an acronym (a few capitals) letter by letter, a word by
    // the English dictionary, else by its parts (WeChat: we chat), else as generic speech of about
    // as many syllables as its spelling has, with a warning. A hyphenated word the dictionary has
    // whole (Wi-Fi) is one form.
    std::size_t read_latin(const std::vector<CodePoint>& text, std::size_t start) {
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
        std::string word = latin_spelling(text, start, end);
        // A card's suffix after its model's digits (RTX 4070 Ti) is its letters, where Ti alone is pinyin.
        if (in_chemical_formula(text, start) || detail::follows_card_model(text, start)) {
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
        add_form(text, start, end, latin_word_syllables(word, text[start]));
        return end;
    }

    std::vector<Syllable> latin_word_syllables(const std::string& word, const CodePoint& at) {
        // A letter alone is a letter (选a, x=5), not the dictionary's word a or x (ai si).
        if (word.size() == 1 || (detail::is_all_capitals(word) && !detail::is_said_as_word(word))) return read_capitals(word);
        // A small letter and a capital (pH, as chemistry writes it) are letters, P H (session 17: the
        // dictionary's word ph, pi ei qi).
        if (word.size() == 2 && word.front() >= 'a' && word.front() <= 'z' && is_ascii_capital(static_cast<char32_t>(word.back())))
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
        if (is_acronym_with_small_end && !detail::english_word_syllables(word))
            return said_syllables(detail::letter_syllables(word));
        if (detail::has_inner_acronym(word)) return read_word_parts(word, at);
        // Small letters without a vowel but y (yyds, xswl, dbq): a chat's initials of a phrase's
        // pinyin, said as their letters, as chat is read out (session 14; yyds was generic speech).
        constexpr std::size_t kLongestInitials = 6;
        const bool is_initials = word.size() >= 2 && word.size() <= kLongestInitials &&
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
        constexpr std::size_t kLongestSpelledSmall = 3;
        if (word.size() <= kLongestSpelledSmall &&
            std::all_of(word.begin(), word.end(), [](char l) { return l >= 'a' && l <= 'z'; }) &&
            !split_pinyin(decode_utf8(word, "<word>")))
            return said_syllables(detail::letter_syllables(word));
        return read_word_parts(word, at);
    }

    // A chat's initials where one syllable of the phrase has no initial and is written by its vowel (awsl
    // 啊我死了): four to six small letters, the one vowel first or last and the consonants all
    // different, said as their letters as yyds is (session 31: generic speech of one syllable with a
    // warning). A word of a consonant repeated (emmm, ahhh) draws a sound out and is left as it was; one
    // that spells pinyin (ang, ao) is pinyin.
    bool is_initials_with_vowel_syllable(const std::string& word) const {
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

    // No.1 (No. 1, NO.1) is said the English way, "number one", as Mandarin speakers say it; the
    // end of the form and its syllables, or nullopt where `word` (ending at text[end]) is not No.
    std::optional<std::pair<std::size_t, std::vector<Syllable>>> number_sign(const std::vector<CodePoint>& text,
                                                                             const std::string& word,
                                                                             std::size_t end) const {
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

    // An address's parts as said: capitals as elsewhere (an acronym letter by letter), letters as
    // a word the dictionary has (com, news), one by one where they are three or fewer (cn, qq,
    // gov, www) or have no vowel (html), as pinyin (zhangwei); digits one by one (163).
    std::vector<Syllable> address_syllables(const detail::WebAddress& address, const CodePoint& at) {
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
            } else if (auto name_pinyin = starts_as_pinyin_only(part.text) ? address_pinyin(part.text) : std::nullopt) {
                append(std::move(*name_pinyin));
            } else if (auto found = detail::english_word_syllables(part.text)) {
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

    // Small letters that spell Mandarin (zhangwei, baidu), as pinyin syllables; nullopt otherwise.
    std::optional<std::vector<Syllable>> address_pinyin(const std::string& letters) const {
        if (!options_.read_pinyin || std::any_of(letters.begin(), letters.end(), [](char c) { return c < 'a' || c > 'z'; }))
            return std::nullopt;
        const auto token = decode_utf8(letters, "<address>");
        auto split = split_pinyin(token);
        if (!split) return std::nullopt;
        std::vector<Syllable> syllables;
        for (auto& syllable : *split) syllables.push_back(make_syllable(std::move(syllable.written), std::move(syllable.pinyin)));
        return syllables;
    }

    std::vector<Syllable> said_syllables(const std::vector<std::string>& pinyin) const {
        std::vector<Syllable> syllables;
        for (const auto& reading : pinyin) syllables.push_back(make_syllable(toneless_of(reading), reading));
        return syllables;
    }

    // Capitals: an acronym of up to three letters is spelled (USB, CEO, WHO: the dictionary's who,
    // led, pet are words written small); one of four is a word where the dictionary has it, as
    // English says NASA, NATO, OPEC and APEC, and as Mandarin speakers do after it (session 14; they
    // were spelled), and spelled where it lacks it (CCTV, HDMI). A longer run is a word where the
    // dictionary has it (NASDAQ) or its spelling can be said (a name in capitals), and spelled
    // where it cannot (HTTPS: no vowel, WCDMA: four consonants in a row).
    std::vector<Syllable> read_capitals(const std::string& word) const {
        constexpr std::size_t kLongestAcronym = 4;
        constexpr std::size_t kLongestSaidConsonants = 2;
        if (word.size() >= kLongestAcronym) {
            if (auto found = detail::english_word_syllables(word)) return said_syllables(*found);
        }
        if (word.size() > kLongestAcronym) {
            std::size_t consonants = 0, longest = 0;
            for (const char letter : word) {
                consonants = std::string_view("AEIOUY").find(letter) == std::string_view::npos ? consonants + 1 : 0;
                longest = std::max(longest, consonants);
            }
            auto spelled = detail::spelled_syllables(word);
            if (!spelled.empty() && longest <= kLongestSaidConsonants) return generic_syllables(spelled);
        }
        return said_syllables(detail::letter_syllables(word));
    }

    // Syllables of a word no table reads: its spelling's share each, fitted by the aligner as any
    // sound at all (Syllable::generic_speech).
    std::vector<Syllable> generic_syllables(const std::vector<std::string>& spelled) const {
        std::vector<Syllable> syllables;
        for (const auto& piece : spelled) {
            syllables.push_back(make_syllable(piece, kGenericSpeechPinyin));
            syllables.back().generic_speech = true;
        }
        return syllables;
    }

    // A word the dictionary lacks or with an acronym inside, by the parts its capitals mark
    // (WeChat, YouTube, iOS), or as two words it has (Facebook); a part still unknown is generic speech of about as many syllables
    // as its spelling has (or spelled, if it has no vowel), with a warning.
    std::vector<Syllable> read_word_parts(const std::string& word, const CodePoint& at) {
        std::vector<std::string> parts;
        for (std::size_t i = 0; i < word.size(); ++i) {
            const bool starts_part = i == 0 || (is_ascii_capital(static_cast<char32_t>(word[i])) &&
                                                !is_ascii_capital(static_cast<char32_t>(word[i - 1])));
            if (starts_part) parts.emplace_back();
            parts.back() += word[i];
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
                warn(at, "\"" + part + "\" is not in the English pronouncing dictionary; aligned as generic speech of about " +
                             std::to_string(spelled.size()) + (spelled.size() == 1 ? " syllable" : " syllables") +
                             " (fix it in place: " + part + "{...})");
                read = generic_syllables(spelled);
            } else {
                warn(at, "\"" + part + "\" is not in the English pronouncing dictionary and has no vowel; read letter by letter (fix it in place: " +
                             part + "{...})");
                read = said_syllables(detail::letter_syllables(part));
            }
            for (auto& syllable : read) syllables.push_back(std::move(syllable));
        }
        return syllables;
    }

    // A word the dictionary lacks as two words it has (facebook: face book, photoshop: photo shop):
    // closer in length and sound than spelling it. Of the splits, the one whose parts are nearest
    // in length, and among those the longer first part: photoshop is photo shop, not photos hop.
    static std::optional<std::vector<std::string>> read_compound(const std::string& word) {
        constexpr std::size_t kShortestPart = 2;
        std::optional<std::vector<std::string>> best;
        std::size_t best_imbalance = word.size();
        for (auto split = word.size() < kShortestPart ? 0 : word.size() - kShortestPart; split >= kShortestPart;
             --split) {
            const auto imbalance = split > word.size() - split ? 2 * split - word.size() : word.size() - 2 * split;
            if (best && imbalance >= best_imbalance) continue;
            auto first = detail::english_word_syllables(word.substr(0, split));
            if (!first) continue;
            auto second = detail::english_word_syllables(word.substr(split));
            if (!second) continue;
            first->insert(first->end(), second->begin(), second->end());
            best = std::move(first);
            best_imbalance = imbalance;
        }
        return best;
    }

    // 行{hang2}: overrides the reading of the character right before the brace; 2026{两千零二十六}
    // or iPhone{ai4 feng4}: the reading of the written form right before it.
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

    // Replaces the syllables of the last written form by the fix's: Chinese characters (read by
    // the tables), numbered pinyin syllables, or both, spaces between them ignored.
    void fix_form(const std::string& fix, const CodePoint& brace) {
        auto& form = timeline_.written_forms.back();
        const auto where = "reading fix \"{" + fix + "}\" for \"" + form.text + "\"";
        const auto fix_text = decode_utf8(fix, source_name_);
        std::vector<Syllable> syllables;
        std::vector<HanCharacter> run;
        auto flush = [&] {
            const auto pinyin = read_han(run);
            for (std::size_t k = 0; k < run.size(); ++k) syllables.push_back(make_syllable(std::string(run[k].text), pinyin[k]));
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
                for (const auto& syllable : *split) syllables.push_back(make_syllable(syllable.written, syllable.pinyin));
                i = end;
            } else {
                throw ParseError(source_name_, brace.line, brace.column, where,
                                 describe_character(c) +
                                     " is neither a Chinese character with a reading nor numbered pinyin");
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

    // The readings of a run of Chinese characters: the run is cut into its likeliest words, each
    // word read by the phrase table, or each of its characters by its most frequent reading;
    // fixes win over both.
    // `ends_clause`: a pause or end mark follows the run, or the text ends (return_verb.hpp).
    std::vector<std::string> read_han(const std::vector<HanCharacter>& run, bool ends_clause = false) const {
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
            const auto next_word = w + 1 < lengths.size() && lengths[w + 1] == 1 ? characters[first + length]
                                                                                  : std::string_view();
            auto in_context = detail::reading_before_particle(word, next_word);
            if (in_context.empty()) in_context = detail::return_verb_reading(words, w, ends_clause);
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

    void flush_run(bool ends_clause = false) {
        const auto readings = read_han(run_, ends_clause);
        for (std::size_t k = 0; k < run_.size(); ++k) add_syllable(std::string(run_[k].text), readings[k]);
        run_.clear();
    }

    // A dialled number's 1 is 幺 on the mainland (拨打119 幺幺九) and 一 in Taiwan (撥打119 一一九,
    // 1999市民熱線 一九九九, 0800 lines), where 幺 is the military's and radio's: a Traditional
    // transcript, mostly Taiwan's, gets 一 (a fix in place says 幺 where it is meant). A train's or a
    // flight's number keeps the announcers' 幺 (複興號G1次: the mainland's trains, as announced).
    std::string with_local_one(std::string words) const {
        if (!is_traditional_) return words;
        constexpr std::string_view kYao = "幺";
        for (auto at = words.find(kYao); at != std::string::npos; at = words.find(kYao, at)) words.replace(at, kYao.size(), "一");
        return words;
    }

    // The syllables of a form's reading in words (二零二六年), each character read by the tables.
    std::vector<Syllable> read_words(const std::string& words) const {
        const auto characters = decode_utf8(words, "<reading>");
        std::vector<HanCharacter> run;
        for (const auto& c : characters) {
            if (!tables_.has_readings(c.text)) {
                throw detail::internal_error("the reading \"" + words +
                                                     "\" holds \"" + std::string(c.text) + "\", which has no reading");
            }
            run.push_back({nullptr, c.text, {}});
        }
        const auto readings = read_han(run);
        std::vector<Syllable> syllables;
        // The readings are the tables' (Simplified); what a syllable shows follows the transcript.
        for (std::size_t k = 0; k < run.size(); ++k)
            syllables.push_back(make_syllable(is_traditional_ ? detail::traditional_form(run[k].text) : std::string(run[k].text),
                                              readings[k]));
        return syllables;
    }

    void check_table_reading(const HanCharacter& character, const std::string& pinyin) const {
        if (detail::normalise_pinyin(pinyin) != pinyin) {
            throw detail::internal_error("the reading table gives \"" +
                            std::string(character.text) + "\" the reading \"" + pinyin +
                            "\", not a Mandarin syllable");
        }
    }

    Syllable make_syllable(std::string text, std::string pinyin) const {
        Syllable syllable;
        syllable.text = std::move(text);
        syllable.pinyin = std::move(pinyin);
        syllable.sentence = timeline_.sentences.size();
        return syllable;
    }

    void add_syllable(std::string text, std::string pinyin) {
        timeline_.syllables.push_back(make_syllable(std::move(text), std::move(pinyin)));
    }

    // A written form text[start, end) read as `syllables`: its text goes into the sentence as
    // written, and the form is kept beside its syllables.
    void add_form(const std::vector<CodePoint>& text, std::size_t start, std::size_t end, std::vector<Syllable> syllables) {
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

    static std::string written_text(const std::vector<CodePoint>& text, std::size_t start, std::size_t end) {
        std::string written;
        for (auto k = start; k < end; ++k) written += text[k].text;
        return written;
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

    void warn_no_reading(const CodePoint& c) { warn(c, describe_character(c) + " has no Mandarin reading; skipped"); }

    void warn(const CodePoint& c, const std::string& message) {
        timeline_.warnings.push_back(source_name_ + ":" + std::to_string(c.line) + ":" + std::to_string(c.column) +
                                     ": " + message);
    }

    const TranscriptOptions& options_;
    bool is_traditional_ = false;  // the transcript is mostly Traditional (script_variant.hpp)
    std::map<int, bool> english_lines_;  // is_english_line's answers, by line
    bool has_han_ = false;         // the transcript has Chinese characters: a toneless Latin word may be English
    const std::string& source_name_;
    const detail::ReadingTables& tables_;
    Timeline timeline_;
    std::vector<HanCharacter> run_;  // Chinese characters not yet read, in order
    std::vector<std::size_t> drawing_ends_;     // where an emoji or a face drawn in signs starting there ends
    std::optional<std::size_t> last_form_end_;  // where the last written form ends in the text
    std::size_t form_warnings_ = 0;  // warnings before the last written form's own
    std::string sentence_text_;
    std::string pending_space_;
    bool sentence_ended_ = false;  // an end mark was seen; closing quotes may still follow
    bool starts_paragraph_ = false;  // a blank line stands between the last sentence and the next
};

}  // namespace

Timeline read_transcript(std::string_view utf8_text, const TranscriptOptions& options,
                         const std::string& source_name) {
    const auto code_points = decode_utf8(utf8_text, source_name);
    return TranscriptReader(options, source_name).read(code_points);
}

bool is_valid_pinyin(std::string_view syllable) {
    return !syllable.empty() && syllable.back() >= '1' && syllable.back() <= '5' &&
           detail::normalise_pinyin(syllable) == syllable;
}

}  // namespace v0
}  // namespace talkface

namespace talkface::detail {

Timeline read_transcript_cut(std::string_view utf8_text, const TranscriptOptions& options,
                             const std::string& source_name, const std::vector<int>& lines_ending_sentences) {
    return TranscriptReader(options, source_name)
        .read(decode_utf8(utf8_text, source_name), lines_ending_sentences);
}

}  // namespace talkface::detail

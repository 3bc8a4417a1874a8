#include "text/kana_words.hpp"

#include <iterator>
#include <string>
#include <string_view>
#include <utility>

#include "talkface/transcript.hpp"
#include "text/sorted_lines.hpp"

namespace talkface::detail {

namespace {

constexpr char32_t kFirstHiragana = 0x3041;  // ぁ
constexpr char32_t kLastHiragana = 0x3096;   // ゖ
constexpr char32_t kFirstKatakana = 0x30A1;  // ァ
constexpr char32_t kLastKatakana = 0x30F6;   // ヶ
constexpr char32_t kKatakanaOffset = kFirstKatakana - kFirstHiragana;
constexpr char32_t kLongMark = 0x30FC;   // ー
constexpr char32_t kSmallTsu = 0x3063;   // っ: the next consonant held, no mora of its own said
constexpr char32_t kSyllabicN = 0x3093;  // ん

// Each hiragana from ぁ (U+3041) on, in code point order: the syllable Mandarin transliterations of Japanese
// give it (あ 阿 a, い 伊 yi, う 宇 wu, え 诶 ei, お 奥 ao; か 卡 ka ... ん 恩 en), and the vowel it ends in,
// which a long vowel after it repeats. The small vowels and ゃ ゅ ょ are the glides of the kana before them.
struct Mora {
    std::string_view pinyin;  // toneless; "" for the small tsu
    char vowel;               // a i u e o, or 'n' for ん, '-' for the small tsu
};
constexpr Mora kHiragana[] = {
    {"a", 'a'},   {"a", 'a'},   {"yi", 'i'},  {"yi", 'i'},  {"wu", 'u'},  {"wu", 'u'},  {"ei", 'e'},
    {"ei", 'e'},  {"ao", 'o'},  {"ao", 'o'},  {"ka", 'a'},  {"ga", 'a'},  {"ji", 'i'},  {"ji", 'i'},
    {"ku", 'u'},  {"gu", 'u'},  {"ke", 'e'},  {"ge", 'e'},  {"ke", 'o'},  {"ge", 'o'},  {"sa", 'a'},
    {"za", 'a'},  {"xi", 'i'},  {"ji", 'i'},  {"si", 'u'},  {"zi", 'u'},  {"sai", 'e'}, {"ze", 'e'},
    {"suo", 'o'}, {"zuo", 'o'}, {"ta", 'a'},  {"da", 'a'},  {"qi", 'i'},  {"ji", 'i'},  {"", '-'},
    {"ci", 'u'},  {"zi", 'u'},  {"te", 'e'},  {"de", 'e'},  {"tuo", 'o'}, {"duo", 'o'}, {"na", 'a'},
    {"ni", 'i'},  {"nu", 'u'},  {"nei", 'e'}, {"nuo", 'o'}, {"ha", 'a'},  {"ba", 'a'},  {"pa", 'a'},
    {"xi", 'i'},  {"bi", 'i'},  {"pi", 'i'},  {"fu", 'u'},  {"bu", 'u'},  {"pu", 'u'},  {"hei", 'e'},
    {"bei", 'e'}, {"pei", 'e'}, {"huo", 'o'}, {"bo", 'o'},  {"po", 'o'},  {"ma", 'a'},  {"mi", 'i'},
    {"mu", 'u'},  {"mei", 'e'}, {"mo", 'o'},  {"ya", 'a'},  {"ya", 'a'},  {"you", 'u'}, {"you", 'u'},
    {"yue", 'o'}, {"yue", 'o'}, {"la", 'a'},  {"li", 'i'},  {"lu", 'u'},  {"lei", 'e'}, {"luo", 'o'},
    {"wa", 'a'},  {"wa", 'a'},  {"wei", 'i'}, {"wei", 'e'}, {"wo", 'o'},  {"en", 'n'},  {"wu", 'u'},
    {"ka", 'a'},  {"ke", 'e'},
};
static_assert(std::size(kHiragana) == kLastHiragana - kFirstHiragana + 1, "one mora for each hiragana");

char32_t as_hiragana(char32_t c) {
    return c >= kFirstKatakana && c <= kLastKatakana ? c - kKatakanaOffset : c;
}

bool is_kana(char32_t c) {
    const auto h = as_hiragana(c);
    return (h >= kFirstHiragana && h <= kLastHiragana) || c == kLongMark;
}

// Whether a vowel kana after a mora ending in `vowel` lengthens it: the same vowel, う after お (とう), い
// after え (せい).
bool lengthens(char32_t h, char vowel) {
    const auto& mora = kHiragana[h - kFirstHiragana];
    const bool is_vowel = std::u32string_view(U"あいうえお").find(h) != std::u32string_view::npos;
    return is_vowel && (mora.vowel == vowel || (vowel == 'o' && mora.vowel == 'u') ||
                        (vowel == 'e' && mora.vowel == 'i'));
}

// The final a small kana gives the mora before it: ゃ ゅ ょ its glide and vowel, as Mandarin transliterates
// きゃ きゅ きょ (恰 qia, 丘 qiu, 乔 qiao); the small vowels their vowel (ファ fa, ティ ti, フォ fo).
std::string_view glide_final(char32_t h) {
    switch (h) {
        case U'ゃ':
            return "ia";
        case U'ゅ':
            return "iu";
        case U'ょ':
            return "iao";
        case U'ぁ':
            return "a";
        case U'ぃ':
            return "i";
        case U'ぅ':
            return "u";
        case U'ぇ':
            return "ei";
        case U'ぉ':
            return "o";
        default:
            return "";
    }
}

// The syllable of the mora `before` (numbered pinyin) with a small kana's final after its initial (き ゃ:
// ji + ia, jia), or "" where Mandarin has no such syllable (にゃ: ni ya, two).
std::string glide_joined(const std::string& before, std::string_view final) {
    if (final.empty()) return "";
    const auto initial = before.substr(0, before.find_first_of("aeiouv"));
    auto joined = initial + std::string(final) + "1";
    return initial.empty() || !is_valid_pinyin(joined) ? "" : joined;
}

// The syllable of the mora `before` (numbered pinyin) closed by ん, as Mandarin transliterates a mora and
// its n as one syllable (ラーメン la men, ケン ken, サン san), or "" where Mandarin has no such syllable.
std::string nasal_joined(const std::string& before) {
    const auto toneless = before.substr(0, before.size() - 1);
    for (const auto& joined : {toneless + "n", toneless.substr(0, toneless.find_first_of("aeiouv")) + "en"}) {
        if (joined != "en" && is_valid_pinyin(joined + "1")) return joined + "1";
    }
    return "";
}

// Words of Japanese that Mandarin chat has taken in whole, written in kana and said as their settled
// transliterations are (すごい 斯国一, ありがとう 阿里嘎多, 八嘎, 达咩, 雅蠛蝶, 空尼奇瓦), where the mora
// table's gives other syllables (si ge yi, a li ga tuo; session 32 left すごい to a fix in place), as
// Mandarin's own words for English ones are kept (latin_words.cpp's email 伊妹儿). In hiragana.
struct SettledWord {
    std::u32string_view kana;
    std::string_view pinyin;  // numbered, the characters' tones
};
constexpr SettledWord kSettledWords[] = {
    {U"すごい", "si1 guo2 yi1"}, {U"ありがとう", "a1 li3 ga1 duo1"}, {U"ばか", "ba1 ga1"},
    {U"だめ", "da2 mie1"},       {U"やめて", "ya3 mie4 die2"},       {U"こんにちは", "kong1 ni2 qi2 wa3"},
};

std::optional<std::vector<std::string>> settled_syllables(const std::vector<CodePoint>& text,
                                                          std::size_t first, std::size_t end) {
    std::u32string kana;
    for (auto k = first; k < end; ++k) kana += as_hiragana(text[k].value);
    for (const auto& word : kSettledWords) {
        if (kana != word.kana) continue;
        std::vector<std::string> syllables;
        for (const auto syllable : split_words(word.pinyin)) syllables.emplace_back(syllable);
        return syllables;
    }
    return std::nullopt;
}

}  // namespace

std::optional<KanaWord> read_kana_word(const std::vector<CodePoint>& text, std::size_t i) {
    if (i >= text.size() || !is_kana(text[i].value) || text[i].value == kLongMark) return std::nullopt;
    const auto first = i;
    KanaWord word;
    char vowel = '-';  // the vowel the last mora said ends in
    for (; i < text.size() && is_kana(text[i].value); ++i) {
        const auto h = as_hiragana(text[i].value);
        if (text[i].value == kLongMark || h == kSmallTsu) continue;
        const auto& mora = kHiragana[h - kFirstHiragana];
        if (lengthens(h, vowel)) continue;
        if (!word.syllables.empty()) {
            auto& before = word.syllables.back();
            const auto joined = h == kSyllabicN ? nasal_joined(before) : glide_joined(before, glide_final(h));
            if (!joined.empty()) {
                before = joined;
                vowel = mora.vowel;
                continue;
            }
        }
        word.syllables.push_back(std::string(mora.pinyin) + "1");
        vowel = mora.vowel;
    }
    // っ alone (好っ) cuts a sound off and says nothing: no word.
    if (word.syllables.empty()) return std::nullopt;
    if (auto settled = settled_syllables(text, first, i)) word.syllables = std::move(*settled);
    word.end = i;
    return word;
}

}  // namespace talkface::detail

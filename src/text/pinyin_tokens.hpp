// Runs of Latin letters in a transcript that may be pinyin (ni3hao3, xi'an, lu:4, nihao): where such a
// token ends, what it spells in ASCII, and its split into Mandarin syllables, with the signs that it is
// a Latin word that happens to split (TV, team) rather than pinyin.
#ifndef TALKFACE_TEXT_PINYIN_TOKENS_HPP
#define TALKFACE_TEXT_PINYIN_TOKENS_HPP

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "text/code_points.hpp"

namespace talkface::detail {

bool is_pinyin_letter(char32_t c);

bool is_capital(char32_t c);

// Where a run of letters and digits that may be pinyin ends: "lu:4" and "xi'an" are one token,
// but a colon or apostrophe that does not continue a syllable is punctuation ("hao3:", "ni3'").
std::size_t end_of_token(const std::vector<CodePoint>& text, std::size_t start);

// What a run of Latin letters spells, in ASCII (ｉＰｈｏｎｅ: iPhone), for the tables.
std::string latin_spelling(const std::vector<CodePoint>& text, std::size_t start, std::size_t end);

struct WrittenSyllable {
    std::string written;
    std::string pinyin;
};

// Splits a pinyin token into syllables ("ni3hao3", "xi'an", "nihao"), or nullopt if it does
// not spell Mandarin. Among the splits with fewest syllables the one with the longer first
// syllables wins ("xian" is one syllable, as in pinyin's own spelling rule).
std::optional<std::vector<WrittenSyllable>> split_pinyin(const std::vector<CodePoint>& token);

// A pinyin token with capitals past its first letter ("TV", "ME") is taken for Latin text.
bool looks_like_pinyin(const std::vector<CodePoint>& token);

// Small letters that start as only pinyin starts a word, x or q before i, or zh (xinhua, qingdao,
// zhejiang): a Chinese name or place, read as pinyin, even where the English dictionary lists it
// among its names (xinhua, which it says jin wa). English words that start with x or q do so
// before other letters (xerox, quick).
bool starts_as_pinyin_only(std::string_view letters);

bool has_tone_digit(const std::vector<CodePoint>& token);

// Whether a pinyin split without tone digits holds a syllable only an interjection writes (m 呣, n 嗯,
// ng, hm, hng, lo 咯, yo 哟) beside others: no word or name spells one inside it, so the letters are a
// Latin word that happens to split (team te a m, Elon E lo n; session 26), not pinyin. A token that is
// that syllable alone (n, hm) is the interjection.
bool splits_into_interjection(const std::vector<WrittenSyllable>& split);

}  // namespace talkface::detail

#endif

// A Japanese word in kana inside a Mandarin transcript (超かわいい, すごい, ありがとう): said as Mandarin
// speakers say it, one syllable a mora, by the Chinese characters Mandarin transliterates kana with (か 卡
// ka, き 基 ji, す 斯 si, と 托 tuo ...), a long vowel one syllable (かわいい ka wa yi, 卡哇伊). A speaker
// says the word, so it is no drawing to leave unsaid (drawn_faces.hpp), and a table reads it as the
// dictionary reads an English word, so it is not warned of (session 31: each kana was skipped with a
// warning).
#ifndef TALKFACE_TEXT_KANA_WORDS_HPP
#define TALKFACE_TEXT_KANA_WORDS_HPP

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "text/code_points.hpp"

namespace talkface::detail {

struct KanaWord {
    std::vector<std::string> syllables;  // numbered pinyin
    std::size_t end = 0;                 // past the word's last kana
};

// The kana word starting at text[i] (hiragana, katakana and the long mark ー, as the reader folds them),
// or nullopt where none starts there.
std::optional<KanaWord> read_kana_word(const std::vector<CodePoint>& text, std::size_t i);

}  // namespace talkface::detail

#endif

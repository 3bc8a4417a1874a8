// talkface: reading a Mandarin transcript into sentences and syllables (SPEC "Transcript to
// syllables"), the input of the aligner.
//
//   auto timeline = talkface::read_transcript("長期下來，傷害不斷累積。銀行{hang2}");
//   for (const auto& syllable : timeline.syllables)   // 長 chang2, 期 qi1, ... 行 hang2
//       std::cout << syllable.text << ' ' << syllable.pinyin << '\n';
//   for (const auto& warning : timeline.warnings)     // what had no reading, and where
//       std::cerr << warning << '\n';
#ifndef TALKFACE_TRANSCRIPT_HPP
#define TALKFACE_TRANSCRIPT_HPP

#include <string>
#include <string_view>

#include "talkface/export.h"
#include "talkface/timeline.hpp"

namespace talkface {
inline namespace v0 {

/// How a transcript is read.
struct TranscriptOptions {
    /// Read runs of Latin letters that spell Mandarin syllables ("ni3 hao3", "ni3hao3", "nihao")
    /// as syllables; when false they are read as letters or English words like any other Latin.
    bool read_pinyin = true;
    /// Read stage directions and speaker labels as text. By default (false) they are not said:
    /// a bracket holding only sounds and actions, （笑） (掌声) [音乐] 【众人鼓掌】 [laughter], and,
    /// where two lines or more start with one and the text is a dialogue, a name and a colon at a
    /// line's start (主持人： A: 小明：), which also ends the sentence before it. Each is left out
    /// of the syllables and the sentence text with a Timeline::warnings entry (a label once, with
    /// how many lines it starts). docs/transcripts.md has the rules.
    bool keep_directions = false;
    /// load_transcript() only: the file's encoding when it has no byte order mark, any name
    /// glibc's iconv knows: "gb18030" (or "gbk", "gb2312"), "big5", "big5-hkscs", "utf-16le", ...;
    /// "" (the default) means UTF-8. A byte order mark (UTF-8, UTF-16 or UTF-32) always decides.
    std::string encoding;
};

/// Reads a transcript: UTF-8 text in Traditional or Simplified characters, or numbered pinyin.
///
/// - Sentences end at 。！？；… and . ! ? ; (closing quotes and brackets right after the mark
///   stay with the sentence); text after the last mark is a sentence too. A blank line ends one
///   and starts a paragraph. A line ending without a mark ends its sentence where the lines are
///   written one a sentence (a script, a subtitle's lines): not where it ends in a pause mark or
///   a dash, nor in a paragraph of running text, wrapped at a width (a full stop inside one of its
///   lines, or the line as wide as the paragraph's widest and 20 Chinese characters or more).
///   Spaces end nothing. docs/transcripts.md "Lines" has the rule.
/// - ，、：and , : mark a pause after the syllable before them (Syllable::pause_after).
/// - Each character with a reading is one syllable. A polyphonic character is read by the word
///   it stands in (首都 shou3 du1, 都是 dou1 shi4): a run of characters is cut into its likeliest
///   words by the built-in phrase list's word frequencies (亿人参加: 人 参加 can1 jia1, not 人参
///   ren2 shen1), otherwise by its most frequent reading. Tones are the most frequent tone for that toneless
///   reading: a best guess (lips do not depend on tone), not tone sandhi.
/// - A reading fix right after a character overrides it: 行{hang2}, 了{liao3}; the tone digit
///   may be left out (tone 5).
/// - A pinyin token gives one syllable per syllable it spells: text as written, pinyin
///   normalised ("lü4", "lu:4" -> "lv4"; no tone -> 5); an apostrophe separates syllables (xi'an).
/// - Written forms are read as a native reader says them (docs/written-forms.md): numbers,
///   dates, clock times, percentages, fractions, ranges, money, units and phone numbers
///   (2026年 二零二六年, 2本书 两本书, 3:30 三点三十分, 85% 百分之八十五, ¥199 一百九十九元,
///   13812345678 幺三八...), acronyms of up to four capitals letter by letter (AI ei ai), English
///   words by a pronouncing dictionary (iPhone ai feng). Each becomes a WrittenForm in
///   Timeline::written_forms beside its syllables. A fix right after a form replaces its reading,
///   in characters or numbered pinyin: 2026{两千零二十六}, OK{ou1 kei4}. A number of more than 16
///   digits is read digit by digit with a warning; a word the dictionary lacks (Zorblax) becomes
///   about as many Syllable::generic_speech syllables as its spelling has (Zor blax), which the
///   aligner fits as any speech, with a warning (one without a vowel is spelled).
/// - Characters without a reading (symbols, Han characters the table lacks) are not syllables:
///   each adds a Timeline::warnings entry `source:line:column: "★" (U+2605) has no Mandarin
///   reading; skipped`. Punctuation other than the marks above (quotes, brackets, dashes) stays
///   in Sentence::text silently, and so do emoji and faces drawn in signs ((^_^), (╯°□°)╯): nobody
///   says them.
/// Columns count characters (code points), not bytes; lines and columns are 1-based.
/// Sentence::text is the sentence as written, fixes removed; times are all 0.
///
/// \param utf8_text the transcript; a leading byte order mark is skipped
/// \param source_name names the text in messages (a path, or "<transcript>")
/// \throws talkface::ParseError on invalid UTF-8 (naming the byte offset and its line:column),
///         on a reading fix that is not a Mandarin syllable (行{hxng2}) or, after a written form,
///         neither characters nor pinyin (5{★}), on a fix with no character or form right before
///         it, or on an unclosed "{".
/// Thread safety: may be called from several threads at once (the tables are read-only).
TALKFACE_API Timeline read_transcript(std::string_view utf8_text, const TranscriptOptions& options = {},
                                      const std::string& source_name = "<transcript>");

/// Reads a transcript file; messages name `path`. The file is text as read_transcript() reads it,
/// in UTF-8, UTF-16 or UTF-32 with a byte order mark, or in options.encoding; or subtitles or a
/// TextGrid, whose text is read (docs/transcripts.md):
/// - SubRip (.srt: a cue number, then "00:00:01,000 --> 00:00:02,500") and WebVTT ("WEBVTT" first):
///   cue numbers, times, identifiers, notes and markup (<i>, {\an8}) are dropped; each cue ends a
///   sentence, unless its text runs on (ends with ， 、 ： , : or a dash). Cue times are not used:
///   pass the same file as a timing (time_transcript(), --timing) to keep each sentence in its cue.
/// - A Praat TextGrid: the intervals of its "sentences" tier, one sentence each; else those of its
///   "syllables" or "words" tier (or its only interval tier), a sentence ending at an empty
///   interval (a silence) of 0.3 s or more.
/// Warnings and errors name the file's own lines.
/// \throws talkface::FileError if the file cannot be read; talkface::InvalidArgument naming
///         "encoding" for an encoding iconv does not know; talkface::ParseError naming the line,
///         column and byte offset where the bytes stop being text in their encoding (when it is
///         not named and they are not UTF-8, the message says which encodings read them as Chinese,
///         GB18030, Big5 or UTF-16, with what each reads), for a subtitle or TextGrid that is
///         malformed (naming the line), and what read_transcript() throws.
TALKFACE_API Timeline load_transcript(const std::string& path, const TranscriptOptions& options = {});

/// True if `syllable` is a legal Mandarin syllable in numbered pinyin: a toneless syllable of
/// the built-in set (e.g. "zhuang", "lv", "ng") followed by a tone 1-5 ("hang2", "ma5").
TALKFACE_API bool is_valid_pinyin(std::string_view syllable);

}  // namespace v0
}  // namespace talkface

#endif

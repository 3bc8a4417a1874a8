// The transcript reader (SPEC "Transcript to syllables"): it walks a transcript's text into sentences
// and syllables, one item at a time. Its parts are one idea each: transcript_reader.cpp walks the text
// and keeps the sentences, transcript_reader_han.cpp reads runs of Chinese characters,
// transcript_reader_latin.cpp reads Latin words and web addresses, and transcript_reader_fixes.cpp
// applies the reading fixes written in braces (行{hang2}, 2026{两千零二十六}).
#ifndef TALKFACE_TEXT_TRANSCRIPT_READER_HPP
#define TALKFACE_TEXT_TRANSCRIPT_READER_HPP

#include <cstddef>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "talkface/transcript.hpp"
#include "text/code_points.hpp"
#include "text/reading_tables.hpp"
#include "text/script_marks.hpp"
#include "text/web_addresses.hpp"

namespace talkface::detail {

// The character as written: a full-width one (～) is named by its own code point, not the ASCII
// form it is read as.
std::string describe_character(const CodePoint& c);

struct HanCharacter {
    const CodePoint* code_point;  // where it stands in the transcript; nullptr in a form's reading
    std::string_view text;
    std::string fix;  // a reading fix, normalised; empty if none
};

class TranscriptReader {
public:
    TranscriptReader(const TranscriptOptions& options, const std::string& source_name)
        : options_(options), source_name_(source_name), tables_(detail::reading_tables()) {}

    // `lines_ending_sentences`: lines after which a sentence ends whatever its marks (a subtitle's
    // cues). With them, the lines between are the file's other lines blanked, no paragraph's end.
    Timeline read(const std::vector<CodePoint>& written,
                  const std::optional<std::vector<int>>& lines_ending_sentences = {});

private:
    // Each stage direction left out, and each speaker's label once, with how many lines it starts.
    void warn_script_marks(const std::vector<CodePoint>& text, const std::vector<detail::ScriptMark>& marks);

    // Ends the sentence here; a blank line before what follows still starts a paragraph.
    void break_sentence();

    // A written form read aloud at text[i] (a web address, a number with what it says, a unit per another,
    // a slash said 每 or 和, a number character, a power, a formula's sign, an ampersand between words, a
    // Japanese word in kana) added as its syllables, or a subtitle's timing kept unsaid: the index past it,
    // nullopt where none starts there.
    std::optional<std::size_t> read_written_form(const std::vector<CodePoint>& text, std::size_t i);

    // Reads the item starting at text[i]; returns where the next one starts.
    std::size_t read_item(const std::vector<CodePoint>& text, std::size_t i);

    std::size_t read_token(const std::vector<CodePoint>& text, std::size_t start);

    // Whether the line holding text[at] is English: more of its words are English words the dictionary
    // has that spell no pinyin (I, fix, it, no) than are pinyin it lacks (xiao, huan, Xiaoming), as in
    // "I can fix it", where a line of pinyin without tones holds a name or a brand at the most (wo xi
    // huan iPhone). A word that is both (can, man, long, you) or neither does not count, nor an acronym.
    // In such a line a word the dictionary has is English though it splits into syllables (can kan;
    // session 27: the pinyin can), as among Chinese characters. Known lines are kept, so that a long
    // line is scanned once.
    bool is_english_line(const std::vector<CodePoint>& text, std::size_t at);

    // Latin letters that are not pinyin: an acronym (a few capitals) letter by letter, a word by
    // the English dictionary, else by its parts (WeChat: we chat), else as generic speech of about
    // as many syllables as its spelling has, with a warning. A hyphenated word the dictionary has
    // whole (Wi-Fi) is one form.
    std::size_t read_latin(const std::vector<CodePoint>& text, std::size_t start);

    // names_with_number: a digit is written right after the word (Cas9), which makes it a name.
    std::vector<Syllable> latin_word_syllables(const std::string& word, const CodePoint& at,
                                               bool names_with_number = false);

    // An ampersand between two words (letters, digits or Chinese characters), a space on either side
    // allowed, is said as English says it, and (R&D a er an de di, AT&T, 早午餐＆咖啡; session 32: skipped
    // with a warning): a name the dictionary has whole is its word (S&P 标普, read_latin), and a sign alone
    // (价格＆) still has no reading.
    bool joins_two_words(const std::vector<CodePoint>& text, std::size_t i) const;

    // A chat's initials where one syllable of the phrase has no initial and is written by its vowel (awsl
    // 啊我死了): four to six small letters, the one vowel first or last and the consonants all
    // different, said as their letters as yyds is (session 31: generic speech of one syllable with a
    // warning). A word of a consonant repeated (emmm, ahhh) draws a sound out and is left as it was; one
    // that spells pinyin (ang, ao) is pinyin.
    bool is_initials_with_vowel_syllable(const std::string& word) const;

    // No.1 (No. 1, NO.1) is said the English way, "number one", as Mandarin speakers say it; the
    // end of the form and its syllables, or nullopt where `word` (ending at text[end]) is not No.
    std::optional<std::pair<std::size_t, std::vector<Syllable>>> number_sign(
        const std::vector<CodePoint>& text, const std::string& word, std::size_t end) const;

    // An address's parts as said: capitals as elsewhere (an acronym letter by letter), letters as
    // a word the dictionary has (com, news), one by one where they are three or fewer (cn, qq,
    // gov, www) or have no vowel (html), as pinyin (zhangwei); digits one by one (163).
    std::vector<Syllable> address_syllables(const detail::WebAddress& address, const CodePoint& at);

    // Small letters that spell Mandarin (zhangwei, baidu), as pinyin syllables; nullopt otherwise.
    std::optional<std::vector<Syllable>> address_pinyin(const std::string& letters) const;

    std::vector<Syllable> said_syllables(const std::vector<std::string>& pinyin) const;

    // Capitals: an acronym of up to three letters is spelled (USB, CEO, WHO: the dictionary's who,
    // led, pet are words written small); one of four is a word where the dictionary has it, as
    // English says NASA, NATO, OPEC and APEC, and as Mandarin speakers do after it (session 14; they
    // were spelled), and spelled where it lacks it (CCTV, HDMI). A longer run is a word where the
    // dictionary has it (NASDAQ) or its spelling can be said (a name in capitals), and spelled
    // where it cannot (HTTPS: no vowel, WCDMA: four consonants in a row).
    std::vector<Syllable> read_capitals(const std::string& word) const;

    // Syllables of a word no table reads: its spelling's share each, fitted by the aligner as any
    // sound at all (Syllable::generic_speech).
    std::vector<Syllable> generic_syllables(const std::vector<std::string>& spelled) const;

    // A word the dictionary lacks or with an acronym inside, by the parts its capitals mark
    // (WeChat, YouTube, iOS), or as two words it has (Facebook); a part still unknown is generic speech of
    // about as many syllables as its spelling has (or spelled, if it has no vowel), with a warning.
    std::vector<Syllable> read_word_parts(const std::string& word, const CodePoint& at);

    // A word the dictionary lacks as two words it has (facebook: face book, photoshop: photo shop):
    // closer in length and sound than spelling it. Of the splits, the one whose parts are nearest
    // in length, and among those the longer first part: photoshop is photo shop, not photos hop.
    static std::optional<std::vector<std::string>> read_compound(const std::string& word);

    // 行{hang2}: overrides the reading of the character right before the brace; 2026{两千零二十六}
    // or iPhone{ai4 feng4}: the reading of the written form right before it.
    std::size_t read_fix(const std::vector<CodePoint>& text, std::size_t open);

    // Replaces the syllables of the last written form by the fix's: Chinese characters (read by
    // the tables), numbered pinyin syllables, or both, spaces between them ignored.
    void fix_form(const std::string& fix, const CodePoint& brace);

    // The readings of a run of Chinese characters: the run is cut into its likeliest words, each
    // word read by the phrase table, or each of its characters by its most frequent reading;
    // fixes win over both.
    // `ends_clause`: a pause or end mark follows the run, or the text ends (return_verb.hpp).
    // `follows_number`: a written number ends right where the run starts (measure_or_verb.hpp);
    // `follows_attempts`: that number counts the shots made of a count of attempts (shots_made.hpp).
    // `written_after`: the first characters after the run where it ends before a written form, not a
    // pause (他得100分, 对手为45.1%: must_verb.hpp, quantity_copula.hpp).
    std::vector<std::string> read_han(const std::vector<HanCharacter>& run, bool ends_clause = false,
                                      bool follows_number = false, bool follows_attempts = false,
                                      std::string_view written_after = {}) const;

    // The last written form is a number whose last digit stands right before text[i], no space
    // between (2只: a measure word the number counts).
    bool follows_written_number(std::size_t i) const;

    void flush_run(bool ends_clause = false, std::string_view written_after = {});

    // A dialled number's 1 is 幺 on the mainland (拨打119 幺幺九) and 一 in Taiwan (撥打119 一一九,
    // 1999市民熱線 一九九九, 0800 lines), where 幺 is the military's and radio's: a Traditional
    // transcript, mostly Taiwan's, gets 一 (a fix in place says 幺 where it is meant). A train's or a
    // flight's number keeps the announcers' 幺 (複興號G1次: the mainland's trains, as announced).
    std::string with_local_one(std::string words) const;

    // The syllables of a form's reading in words (二零二六年), each character read by the tables, and a
    // Latin letter among them by its name (以三为底x的对数).
    std::vector<Syllable> read_words(const std::string& words) const;

    void check_table_reading(const HanCharacter& character, const std::string& pinyin) const;

    Syllable make_syllable(std::string text, std::string pinyin) const;

    void add_syllable(std::string text, std::string pinyin);

    // A written form text[start, end) read as `syllables`: its text goes into the sentence as
    // written, and the form is kept beside its syllables.
    void add_form(const std::vector<CodePoint>& text, std::size_t start, std::size_t end,
                  std::vector<Syllable> syllables);

    static std::string written_text(const std::vector<CodePoint>& text, std::size_t start, std::size_t end);

    // Whitespace between two Chinese characters is layout (a wrapped line), not text; elsewhere
    // a run of it becomes one space, or stays as written if it holds no line break.
    void append_text(std::string_view text);

    // A sentence without syllables (only punctuation, or only characters already warned about)
    // has nothing to align and is left out.
    void close_sentence();

    void warn_no_reading(const CodePoint& c);

    void warn(const CodePoint& c, const std::string& message);

    const TranscriptOptions& options_;
    bool is_traditional_ = false;        // the transcript is mostly Traditional (script_variant.hpp)
    std::map<int, bool> english_lines_;  // is_english_line's answers, by line
    bool has_han_ = false;  // the transcript has Chinese characters: a toneless Latin word may be English
    const std::string& source_name_;
    const detail::ReadingTables& tables_;
    Timeline timeline_;
    std::vector<HanCharacter> run_;             // Chinese characters not yet read, in order
    bool run_follows_number_ = false;           // a written number ends where run_ starts
    bool run_follows_attempts_ = false;         // and counts shots made after their attempts (12投7)
    std::vector<std::size_t> drawing_ends_;     // where an emoji or a face drawn in signs starting there ends
    std::optional<std::size_t> last_form_end_;  // where the last written form ends in the text
    std::size_t form_warnings_ = 0;             // warnings before the last written form's own
    std::string sentence_text_;
    std::string pending_space_;
    bool sentence_ended_ = false;    // an end mark was seen; closing quotes may still follow
    bool starts_paragraph_ = false;  // a blank line stands between the last sentence and the next
};

}  // namespace talkface::detail

#endif

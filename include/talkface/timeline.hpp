// talkface: the syllable timeline that joins the speech analyzer to the animation editor
// (SPEC "Contracts": the `align` JSON has the same shape).
#ifndef TALKFACE_TIMELINE_HPP
#define TALKFACE_TIMELINE_HPP

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace talkface {
inline namespace v0 {

/// A sentence of the transcript and, once aligned, when it is spoken.
struct Sentence {
    std::string text;    ///< the transcript's text of the sentence, UTF-8, punctuation included
    double start_s = 0.0;  ///< seconds from the start of the audio (0 before alignment)
    double end_s = 0.0;    ///< seconds; end_s >= start_s
    /// Whether a blank line of the transcript stands before it, so that it begins a new paragraph
    /// (the first sentence begins the first one without it). The audio book's page keeps them.
    bool starts_paragraph = false;
};

/// One syllable: one character of the transcript that has a reading, or one syllable of a form
/// read by rule (a number, letters, an English word: see WrittenForm).
struct Syllable {
    /// The character (or the pinyin syllable when the transcript is pinyin); for a syllable of a
    /// WrittenForm, what is said: the character of a number's reading ("二" of 2026), the toneless
    /// pinyin of a letter or an English syllable ("ei" of AI).
    std::string text;
    std::string pinyin;    ///< numbered pinyin, u-umlaut written v: "lv4", "hang2", "ma5"
    std::size_t sentence = 0;  ///< index into Timeline::sentences
    double start_s = 0.0;  ///< where its initial consonant starts (SPEC "Alignment")
    double end_s = 0.0;
    /// Where its final (vowel) starts, when the aligner measured it; key frames use it.
    std::optional<double> final_start_s;
    double confidence = 1.0;  ///< 0..1, how sure the aligner is of start_s and end_s (not a probability);
                              ///< below kLowAlignmentConfidence (speech_aligner.hpp: what it
                              ///< catches) it may be >100 ms off
    /// A pause the transcript marks right after this syllable (，、：), in which the mouth may rest.
    bool pause_after = false;
    /// Part of a word no table reads (an English word the dictionary lacks: "Zorblax"), said but
    /// not known: `text` is its share of the spelling ("Zor", "blax", about one syllable per group
    /// of vowels), `pinyin` is kGenericSpeechPinyin, which only shapes the mouth (a plain open and
    /// close), and the aligner fits it as any sound at all rather than as that pinyin. Last, so that
    /// aggregate initialisers of the members above keep their meaning.
    bool generic_speech = false;
};

/// The pinyin of a Syllable::generic_speech syllable: the light-tone 的, a neutral open and close
/// of the mouth.
inline constexpr const char* kGenericSpeechPinyin = "de5";

/// A stretch of the transcript read by rule rather than character by character (a number, a date,
/// a time, an amount, letters, an English word) and the syllables it became, so that a user can
/// check "2026年 -> 二零二六年 er4 ling2 er4 liu4 nian2" before aligning. Syllables that no form
/// covers are read from their own character.
struct WrittenForm {
    std::string text;                ///< as the page shows it, UTF-8: "2026年", "3:30", "iPhone"
    std::size_t first_syllable = 0;  ///< index into Timeline::syllables of its first syllable
    std::size_t syllable_count = 0;  ///< how many syllables it became (at least 1)
};

/// Time between two values of TextMismatch::loudness, seconds.
inline constexpr double kMismatchLoudnessStepS = 0.02;

/// A stretch where the speech does not say the transcript's text: found by lenient alignment
/// (AlignOptions::lenient) in place of a refusal. The syllables it stands for keep their place in
/// Timeline::syllables, spread over the stretch at its loudness dips with confidence 0; the mouth
/// there follows the audio's loudness (`loudness`, mouth_key_frames) rather than their shapes;
/// everything around it is aligned as usual.
struct TextMismatch {
    double start_s = 0.0;  ///< where the stretch starts, seconds from the start of the audio
    double end_s = 0.0;    ///< end_s >= start_s; equal where the speech leaves the text out
    std::size_t first_syllable = 0;  ///< index into Timeline::syllables of the first syllable it stands for
    /// How many of the transcript's syllables it stands for; 0 where the speech has words the
    /// transcript lacks (first_syllable is then the syllable after them).
    std::size_t syllable_count = 0;
    std::string expected_text;  ///< what the transcript says there (its syllables' text), UTF-8
    /// The audio's loudness over the stretch, one value per kMismatchLoudnessStepS from start_s
    /// (value k is the mean of [start_s + k step, start_s + (k + 1) step), the last one cut at
    /// end_s), in 0..1: 0 at or under the loudness the aligner takes for speech (silence, noise),
    /// 1 at the recording's loud speech (its 95th percentile) and above, linear in dB between;
    /// rounded to 0.01. Empty where the stretch is an instant, or where the timeline's source
    /// did not measure it: the mouth then shows the syllables' shapes.
    std::vector<double> loudness;
};

/// Sentences and syllables in transcript order, with what was skipped.
struct Timeline {
    std::vector<Sentence> sentences;
    std::vector<Syllable> syllables;
    /// What the transcript reader skipped or guessed (a character with no reading, say), one
    /// message per item naming it and where it stands; never silently dropped. After alignment,
    /// also what the aligner says of the recording (a damaged or cut file, a header whose length
    /// disagrees with its sound, each naming the file) and of the match (a finding of
    /// CheckMode::warn, a transcript with no Mandarin reading, which cannot be checked).
    std::vector<std::string> warnings;
    double duration_s = 0.0;  ///< length of the audio, seconds (0 before alignment)
    /// The written forms read by rule, in transcript order, none overlapping (empty for a
    /// timeline from a source that does not keep them). Last, so that aggregate initialisers of
    /// the members above keep their meaning.
    std::vector<WrittenForm> written_forms;
    /// Where the speech does not say the text, in time order (only from lenient alignment).
    std::vector<TextMismatch> mismatches;
};

}  // namespace v0
}  // namespace talkface

#endif

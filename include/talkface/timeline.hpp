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
};

/// One syllable: one character of the transcript that has a reading.
struct Syllable {
    std::string text;      ///< the character (or the pinyin syllable when the transcript is pinyin)
    std::string pinyin;    ///< numbered pinyin, u-umlaut written v: "lv4", "hang2", "ma5"
    std::size_t sentence = 0;  ///< index into Timeline::sentences
    double start_s = 0.0;  ///< where its initial consonant starts (SPEC "Alignment")
    double end_s = 0.0;
    /// Where its final (vowel) starts, when the aligner measured it; key frames use it.
    std::optional<double> final_start_s;
    double confidence = 1.0;  ///< 0..1, how sure the aligner is of start_s and end_s; below
                              ///< kLowAlignmentConfidence (speech_aligner.hpp) it may be >100 ms off
    /// A pause the transcript marks right after this syllable (，、：), in which the mouth may rest.
    bool pause_after = false;
};

/// Sentences and syllables in transcript order, with what was skipped.
struct Timeline {
    std::vector<Sentence> sentences;
    std::vector<Syllable> syllables;
    /// What the transcript reader skipped or guessed (a character with no reading, say), one
    /// message per item naming it and where it stands; never silently dropped.
    std::vector<std::string> warnings;
    double duration_s = 0.0;  ///< length of the audio, seconds (0 before alignment)
};

}  // namespace v0
}  // namespace talkface

#endif

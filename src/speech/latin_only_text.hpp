// A transcript none of whose words has a Mandarin reading of its own (issue 13, "Bad input"): every
// word English, read as a guess at how a Mandarin speaker says it (latin_words.hpp: The de, quick
// qi ke), or one no table reads, fitted as any speech at all (Syllable::generic_speech). The checks
// weigh how much better other sounds fit the speech than the text does, and such guesses fit
// speech loosely: an English transcript of Mandarin speech ("The quick brown fox ...", with
// one_sentence.wav) aligned, and espeak-ng's English "The quick brown fox ..." aligned with "She
// sells sea shells ..." as with its own text, and the reverse (bench/README.md, Session 28). So such
// a transcript cannot be confirmed, which the alignment says in a warning (AlignOptions::check off
// leaves it unsaid): no evidence against a text is no reason to refuse it. A transcript with one Mandarin
// word, or pinyin, is checked as any other.
#ifndef TALKFACE_SPEECH_LATIN_ONLY_TEXT_HPP
#define TALKFACE_SPEECH_LATIN_ONLY_TEXT_HPP

#include <optional>
#include <string>

#include "talkface/timeline.hpp"

namespace talkface::detail {

// Why `transcript` cannot be confirmed against any speech, if every one of its syllables is a
// generic-speech one or lies in a written form of Latin letters alone (an English word, letters
// said one by one): "none of its 17 syllables has a Mandarin reading: its words (The, quick,
// brown and 6 more) are English, read as ...". nullopt for any other transcript.
std::optional<std::string> describe_latin_only_text(const Timeline& transcript);

}  // namespace talkface::detail

#endif

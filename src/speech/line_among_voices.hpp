// A line said among quieter voices (issues 12 and 13): other people talking 10-20 dB under a
// short line (babble) fill the recording from its first frame, so the profile finds no pause
// before the line and its syllables were spread from the recording's start (bench/README.md,
// session 28: babble's first syllable 128 ms early in tuning, p-babble's 28 ms). The line is its
// speaker's loud voice; sound before it that never comes near that level is not the line's.
#ifndef TALKFACE_SPEECH_LINE_AMONG_VOICES_HPP
#define TALKFACE_SPEECH_LINE_AMONG_VOICES_HPP

#include <cstddef>
#include <optional>

#include "speech/sentence_cutter.hpp"
#include "talkface/timeline.hpp"

namespace talkface::detail {

// Where the line of `syllables` syllables starts inside `speech` (the recording's speech as
// measure_loudness finds it in `loudness`): at the foot of the rise of the run of frames whose
// activity stands most above kUnspokenSpeechBelowDb under the speech's loud level in sum. `speech`
// unchanged unless it runs from the recording's start (no pause before it: sound that never
// stopped, as other voices' does), is slower than its syllables could be said, and the sound left
// out is at least a pause long, never comes within kNearLoudVoiceDb of the loud level, and rises
// and falls by that much as a voice's syllables do (a gain's lift only climbs toward the line).
FrameSpan line_among_quieter_voices(const LoudnessProfile& loudness, const FrameSpan& speech,
                                    std::size_t syllables);

// `cut` (cut_sentences') with the span of `transcript`'s only spoken sentence started where its
// line starts (line_among_quieter_voices), for the syllables' placement; nothing where the
// transcript has several spoken sentences or the span stays as it is. The checks judge the text
// on `cut`: on the line alone a wrong text of as many syllables fits about as well as the right
// one (with the line's span for the checks too, short_kinds_bench caught 51 -> 42 of 760 wrong
// texts in tuning: bench/README.md, session 29).
std::optional<SentenceCut> line_cut_among_voices(const LoudnessProfile& loudness, const Timeline& transcript,
                                                 const SentenceCut& cut);

}  // namespace talkface::detail

#endif

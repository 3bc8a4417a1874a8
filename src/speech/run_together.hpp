// Sentences a speaker runs together (issue #4): where the transcript demands a sentence end that
// the pauses of the audio do not show, the cutter's choice of pause is a guess. Such neighbours are
// aligned as one block, a pause between them optional and of any length (as in a transcript
// without punctuation), and the syllables place the sentence end.
#ifndef TALKFACE_SPEECH_RUN_TOGETHER_HPP
#define TALKFACE_SPEECH_RUN_TOGETHER_HPP

#include <cstddef>
#include <utility>
#include <vector>

#include "speech/sentence_cutter.hpp"

namespace talkface::detail {

// Per spoken sentence (spans of the sentences with syllables, in order, and their syllable
// counts): whether its end is in doubt, so that it is aligned together with the next one. An end
// is in doubt when the pause it was cut at is no longer than a pause left inside the sentences on
// either side of it (a comma's pause, not a sentence's end), or when the two sentences' speaking
// rates, measured on the cut, disagree more than a speaker's do from one sentence to the next.
std::vector<bool> find_run_together(const std::vector<FrameSpan>& spans, const std::vector<std::size_t>& syllables,
                                    const LoudnessProfile& loudness);

// Whether the cut as a whole is in doubt: a pause it took for a sentence end is no longer than a
// pause it left inside a sentence, or a sentence's speaking rate on the cut is far from the
// recording's typical one. Then any sentence end may have been cut at a comma, and where the
// sentence-by-sentence alignment fails, the whole recording is aligned as one block before the
// transcript is called wrong.
bool are_sentence_ends_in_doubt(const std::vector<FrameSpan>& spans, const std::vector<std::size_t>& syllables,
                                const LoudnessProfile& loudness);

// Per sentence of `transcript`: whether it has a syllable.
std::vector<bool> spoken_sentences_of(const Timeline& transcript);

// How many blocks `cut` aligns: spoken sentences that do not continue the one before.
std::size_t block_count(const SentenceCut& cut, const Timeline& transcript);

// What a chain's alignment says of the cut. A sentence end that ran on keeps its chain only if the
// chain's syllables move it out of the pause the cutter chose and put that pause where the text
// has one: a sentence end they leave in its pause confirms the cut, and one they move off a pause
// the text does not account for is a wrong text's doing.
//
// Whether `aligned` ends spoken sentence `k`, or starts the next spoken one, `next`, outside the
// pause `cut` put between them, by more than the benchmark's tolerance for a sentence boundary.
bool moves_sentence_end(const SentenceCut& cut, const Timeline& aligned, std::size_t k, std::size_t next);

// Whether the pause `cut` put between spoken sentence `k` and the next lies, in `aligned`, between
// two syllables where the transcript marks a pause (a comma or a sentence end): a pause the text
// accounts for. A wrong text aligned as a chain can move a sentence end too, but it leaves the
// pause between the sentences heard between two syllables it does not mark.
bool is_cut_pause_in_text(const SentenceCut& cut, const Timeline& aligned, std::size_t k, std::size_t next);

// Whether `aligned` passes over the pause `cut` put between spoken sentence `k` and the next: its
// syllables run on through it (none of it lies between two of them) and it ends sentence `k` at a
// longer pause of its own. The cut's "pause" was then a dip in the speech (a lost packet, a stop's
// closure, the quiet between other voices a phone's gain lifted), and where it falls in the text
// says nothing of the text: four right passages of the phone kinds and one sung were refused for
// a dip of 0.12-0.17 s inside 明天, 起, 底下..., their syllables ending the sentence at a pause of
// 0.47-0.90 s (53-63 of 65-67 syllables within 50 ms). A wrong text bent over a real pause runs on
// through it too, but ends the sentence where it finds less of a pause, or none (bench/README.md,
// session 39 (vfast)).
bool is_cut_pause_passed_over(const SentenceCut& cut, const Timeline& aligned, std::size_t k,
                              std::size_t next);

// Pairs (k, next) of neighbouring spoken sentences.
std::vector<std::pair<std::size_t, std::size_t>> spoken_neighbours(const std::vector<bool>& is_spoken);

}  // namespace talkface::detail

#endif

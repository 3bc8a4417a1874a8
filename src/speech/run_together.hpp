// Sentences a speaker runs together (issue #4): where the transcript demands a sentence end that
// the pauses of the audio do not show, the cutter's choice of pause is a guess. Such neighbours are
// aligned as one block, a pause between them optional and of any length (as in a transcript
// without punctuation), and the syllables place the sentence end.
#ifndef TALKFACE_SPEECH_RUN_TOGETHER_HPP
#define TALKFACE_SPEECH_RUN_TOGETHER_HPP

#include <cstddef>
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

}  // namespace talkface::detail

#endif

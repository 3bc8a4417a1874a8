// Lenient alignment (issue 13): a transcript that differs from the speech by a word or two. Each
// syllable of a chain may be skipped and generic speech may stand between any two syllables, both
// at a cost, so that the search fits the text where the speech says it and generic speech where it
// does not; what the path leaves to generic speech is reported as a TextMismatch.
#ifndef TALKFACE_SPEECH_LENIENT_CHAIN_HPP
#define TALKFACE_SPEECH_LENIENT_CHAIN_HPP

#include <vector>

#include "speech/frame_features.hpp"
#include "speech/hsmm.hpp"
#include "speech/sentence_chains.hpp"
#include "speech/sentence_cutter.hpp"
#include "talkface/timeline.hpp"

namespace talkface::detail {

// `chain` with its states made lenient: every syllable's states skippable at a cost, and an
// optional generic-speech state after the leading silence and after every syllable.
SentenceChain lenient_chain(const SentenceChain& chain);

// Places the syllables of a lenient chain's `path` in `result` with their `evidence` (as
// place_syllables does), and for each stretch the path fits with generic speech or skips: a
// TextMismatch in result.mismatches and a warning, its syllables spread over the stretch at its
// loudness dips with confidence 0 (evidence NaN: set_confidences leaves them so).
void place_lenient(const SentenceChain& chain, const std::vector<StateSegment>& path, const EmissionScores& scores,
                   const FeatureTrack& track, const LoudnessProfile& loudness, Timeline& result,
                   std::vector<double>& evidence);

}  // namespace talkface::detail

#endif

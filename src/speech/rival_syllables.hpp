// How well a syllable's stretch fits its own text against unlike syllables fitted there instead
// (lenient alignment, issue 13): a right syllable that fits the broad-class models badly still fits
// better than nearly every unlike one, where a syllable the speech does not say is beaten by many.
// Relative to the recording's own models and to the stretch itself, it holds for voices and
// recordings whose fits lie higher or lower than the test clips'.
#ifndef TALKFACE_SPEECH_RIVAL_SYLLABLES_HPP
#define TALKFACE_SPEECH_RIVAL_SYLLABLES_HPP

#include <cstddef>

#include "speech/alignment_confidence.hpp"
#include "speech/hsmm.hpp"
#include "speech/sentence_chains.hpp"

namespace talkface::detail {

// The share of unlike syllables (kRivalPinyin in rival_syllables.cpp: one of each broad initial
// and final) that fit `frames` better than syllable `syllable` of `chain` does, each fitted alone
// over exactly those frames with its vowels stretched to them (emissions and duration priors, per
// frame); 0 for a stretch of no frames or a syllable of generic speech.
double rival_share(const SentenceChain& chain, std::size_t syllable, const SyllableFrames& frames,
                   const EmissionScores& scores);

}  // namespace talkface::detail

#endif

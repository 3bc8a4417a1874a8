// How well a chain's aligned speech fits its text: the measures the checks of alignment_checks.hpp
// judge (issue #4: a wrong text is reported, not aligned with confidence).
#ifndef TALKFACE_SPEECH_TEXT_FIT_HPP
#define TALKFACE_SPEECH_TEXT_FIT_HPP

#include <cstddef>
#include <utility>
#include <vector>

#include "speech/acoustic_model.hpp"
#include "speech/hsmm.hpp"
#include "speech/sentence_chains.hpp"

namespace talkface::detail {

// How well the speech of `path` (a sentence's, or its share of a block's) fits the models of the
// sounds its text says, per frame.
double speech_fit(const SentenceChain& chain, const std::vector<StateSegment>& path, const EmissionScores& scores);

// How much better, per frame, the speech of `path` fits the best sequence of sounds than the
// sequence its text says: a phone loop against the forced path, on the same models. A frame the
// path gives a stop's closure after speech scores as silence, raised towards the sound before it
// (a closure spoken through: the vowel or nasal run on into the burst) by at most
// `forgiven_run_on` (infinity: the better of the two; chain_measures.hpp's forgiven_closure_run_on
// says which where); 0 keeps every closure silent.
double text_fit_gap(const SentenceChain& chain, const std::vector<StateSegment>& path,
                    const EmissionScores& scores, double forgiven_run_on);

// text_fit_gap over the frames of `path`'s speech that `is_clear` (one per frame of `scores`) marks,
// per such frame: the frames left out count neither for the text nor for the free sounds. Where
// none is, text_fit_gap itself.
double clear_text_fit_gap(const SentenceChain& chain, const std::vector<StateSegment>& path,
                          const EmissionScores& scores, const std::vector<bool>& is_clear,
                          double forgiven_run_on);

// The share of the frames of `path`'s speech that `is_clear` does not mark; 0 where it has none.
double noise_covered_share(const SentenceChain& chain, const std::vector<StateSegment>& path,
                           const std::vector<bool>& is_clear);

// How much better, per frame, the sound before a stop's closure after speech fits the closure's
// frames on `path` than silence does (0 where silence fits better), one value per frame, appended
// to `losses`: how far this speaker speaks through closures.
void add_closure_run_on(const SentenceChain& chain, const std::vector<StateSegment>& path,
                        const EmissionScores& scores, std::vector<double>& losses);

// The typical closure's run-on of a recording, the median of add_closure_run_on's `losses` (0 for
// none): half the recording's closure frames sound more like the sound before than that, and it is
// above 0 only where most of them are spoken through. The median, not a mean, so that the closures
// of a wrong sentence among right ones (forced where the speech has a vowel) do not move it.
double typical_closure_run_on(std::vector<double> losses);

// The score of the best free sequence of sounds over frames [first, end) of `scores`, paying
// for each change of sound: what text_fit_gap compares a path with.
double free_sounds_score(const EmissionScores& scores, std::size_t first, std::size_t end);

// How much better, per frame, the chain's `path` fits `scores` than the chain's best path over the
// same frames with their halves swapped (the second half's speech first): the text against its own
// sounds in an order the speech does not have, on the same models. NaN if no path fits.
double order_margin(const SentenceChain& chain, const std::vector<StateSegment>& path, const EmissionScores& scores,
                    ViterbiWorkspace& workspace);

// How many frames of the chain's speech its best path gives to generic speech placed after its
// last syllable, before its closing silence (generic_speech_state, lenient alignment's price), on
// `scores`: speech after the text's end that the text does not account for. 0 if none.
std::size_t unspoken_tail_frames(const SentenceChain& chain, const EmissionScores& scores, ViterbiWorkspace& workspace);

// The path of a chain cut into its sentences' shares (a pause goes with the sentence before it),
// each with the index of its sentence in the transcript.
std::vector<std::pair<std::size_t, std::vector<StateSegment>>> split_by_sentence(const SentenceChain& chain,
                                                                                const std::vector<StateSegment>& path);

// The path of a chain cut between its syllables into each sentence's first and second half
// (pauses go with the syllable before them): half h of the chain's j-th sentence is 2 j + h.
std::vector<std::vector<StateSegment>> split_in_halves(const SentenceChain& chain, const std::vector<StateSegment>& path);

// text_fit_gap of each half (split_in_halves) scored with models learned from the rest of the
// recording only (leave one out); an empty half gives minus infinity. `half_estimators` holds the
// halves' shares of `whole`; `scores` is overwritten.
struct HeldOutGaps {
    std::vector<double> halves;     // per half, as split_in_halves numbers them
    std::vector<double> syllables;  // per syllable of the chain, on its half's models; NaN: not scored
};
HeldOutGaps held_out_fit_gaps(const SentenceChain& chain,
                              const std::vector<std::vector<StateSegment>>& halves,
                              const std::vector<float>& observations, const ModelEstimator& whole,
                              const std::vector<ModelEstimator>& half_estimators, EmissionScores& scores,
                              double forgiven_run_on);

}  // namespace talkface::detail

#endif

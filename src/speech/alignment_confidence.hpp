// How sure the aligner is of each syllable's place (issue 12: a syllable more than 100 ms off
// should come out with a low confidence, below talkface::kLowAlignmentConfidence).
#ifndef TALKFACE_SPEECH_ALIGNMENT_CONFIDENCE_HPP
#define TALKFACE_SPEECH_ALIGNMENT_CONFIDENCE_HPP

#include <cstddef>
#include <vector>

#include "speech/hsmm.hpp"
#include "speech/sentence_chains.hpp"

namespace talkface::detail {

// Frames [first_frame, end_frame) of a chain's search that a syllable holds on its path.
struct SyllableFrames {
    std::size_t first_frame = 0;
    std::size_t end_frame = 0;
};

// Per syllable of `chain` (holding `frames` on `path`), a confidence in 0..1. Two kinds of
// evidence, each of the syllable and of its neighbours (drift comes in runs: a syllable placed a
// syllable off pulls its neighbours with it): how probable the sound the path gives each frame is
// among all sounds (the mean posterior of its class), and how much better a free sequence of
// sounds fits the syllable's stretch than the path does (text_fit_gap's loop, per frame).
std::vector<double> syllable_confidences(const SentenceChain& chain, const std::vector<StateSegment>& path,
                                         const EmissionScores& scores, const std::vector<SyllableFrames>& frames);

}  // namespace talkface::detail

#endif

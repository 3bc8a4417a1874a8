// Lenient alignment's final pass (AlignOptions::lenient, lenient_chain.hpp): what each chain's plain
// path shows before it, and the chain made lenient, searched until no skip or generic stretch is
// unsupported, and placed.
#ifndef TALKFACE_SPEECH_LENIENT_PLACEMENT_HPP
#define TALKFACE_SPEECH_LENIENT_PLACEMENT_HPP

#include <cstddef>
#include <vector>

#include "speech/alignment_confidence.hpp"
#include "speech/alignment_passes.hpp"
#include "speech/frame_features.hpp"
#include "speech/hsmm.hpp"
#include "speech/sentence_chains.hpp"
#include "speech/sentence_cutter.hpp"
#include "talkface/timeline.hpp"

namespace talkface::detail {

// What lenient alignment measures of a chain on its plain path (the chain aligned without
// leniency) before its lenient pass: the chain's scores, each syllable's fit and frames on that
// path, and its held-out gap (lenient_chain.hpp), empty where the chain has no plain path; and its
// syllables' tone gaps (tone_gaps_of_chains), read on the plain paths of every chain.
struct LenientEvidence {
    EmissionScores scores;
    std::vector<double> plain_fits;
    std::vector<SyllableFrames> plain_frames;
    std::vector<double> held_out_gaps;
    std::vector<double> tone_gaps;
};

// Lenient alignment's evidence, chain by chain: every chain's plain path first, for the tones of
// the whole recording, and with it what the lenient pass judges its skips by; each chain's scores
// are kept for that pass, not measured twice. `observations` and `workspace` are scratch.
std::vector<LenientEvidence> measure_lenient_evidence(
    const FeatureTrack& track, const LoudnessProfile& loudness, const std::vector<SentenceChain>& chains,
    const Reestimation& learned, std::vector<float>& observations, ViterbiWorkspace& workspace);

// The final pass over plain chain `w` made lenient (lenient_chain.hpp) on what `found` measured on its
// plain path, its syllables placed in `result` and their evidence in `evidence`; `last_path` is
// the plain chain's path in the last round of re-estimation. `found`'s scores are given back.
void place_lenient_chain(const SentenceChain& plain_chain, std::size_t w, LenientEvidence& found,
                         const std::vector<StateSegment>& last_path, ViterbiWorkspace& workspace,
                         const Timeline& transcript, const FeatureTrack& track,
                         const LoudnessProfile& loudness, Timeline& result,
                         std::vector<SyllableEvidence>& evidence);

}  // namespace talkface::detail

#endif

// How sure the aligner is of each syllable's place (issue 12: a syllable more than 100 ms off
// should come out with a low confidence, below talkface::kLowAlignmentConfidence).
#ifndef TALKFACE_SPEECH_ALIGNMENT_CONFIDENCE_HPP
#define TALKFACE_SPEECH_ALIGNMENT_CONFIDENCE_HPP

#include <cstddef>
#include <vector>

#include "speech/hsmm.hpp"
#include "speech/sentence_chains.hpp"
#include "talkface/timeline.hpp"

namespace talkface::detail {

// Frames [first_frame, end_frame) of a chain's search that a syllable holds on its path.
struct SyllableFrames {
    std::size_t first_frame = 0;
    std::size_t end_frame = 0;
};

// Per syllable of `chain`, the frames its states hold on `path` (none: first_frame past end_frame).
std::vector<SyllableFrames> frames_on_path(const SentenceChain& chain, const std::vector<StateSegment>& path);

// The weight of the emissions (viterbi_align's emission_weight) in the second search whose
// disagreement syllable_steadiness weighs: with the sounds at half, a syllable the sounds hold
// stays where it was, and one the duration priors and its neighbours put there moves.
constexpr double kLightSoundsWeight = 0.5;

// Per syllable of `chain`, what other paths of it say of where `path` starts it, added to its
// evidence (not its neighbours': the disagreement is the syllable's own): less, the more frames
// (up to a cap) each of `other_paths` starts it earlier or later. A syllable whose start moves
// between the aligner's last two passes, or when the sounds weigh less (kLightSoundsWeight), is
// likely misplaced; unlike the fit, which a room or noise lowers for every syllable, the paths of
// a right syllable agree there too. A syllable an other path does not place counts nothing.
std::vector<double> syllable_steadiness(const SentenceChain& chain, const std::vector<StateSegment>& path,
                                        const std::vector<std::vector<StateSegment>>& other_paths);

// Per syllable of `chain` (holding `frames` on `path`), how well the path fits it: how probable
// the sound the path gives each frame is among all sounds (the mean posterior of its class), less
// how much better a free sequence of sounds fits the syllable's stretch than the path does
// (text_fit_gap's loop, per frame).
std::vector<double> syllable_fits(const SentenceChain& chain, const std::vector<StateSegment>& path,
                                  const EmissionScores& scores, const std::vector<SyllableFrames>& frames);

// Per syllable of `chain` (holding `frames` on `path`), what its timing says of its place, added to
// its fit: more where the spectrum changes at its start (EmissionScores::boundary), less the more
// its length departs from the pace of the syllables around it (its length against its duration
// prior's, relative to theirs) and the more the path squeezes or stretches its sounds against their
// priors (a drifted syllable is fitted to speech not its own by bending its lengths).
std::vector<double> syllable_timing(const SentenceChain& chain, const std::vector<StateSegment>& path,
                                    const EmissionScores& scores, const std::vector<SyllableFrames>& frames);

// Per syllable, the evidence that it is where the path put it: its fit (syllable_fits) and its
// neighbours' averaged (drift comes in runs: a syllable placed a syllable off pulls its neighbours
// with it).
std::vector<double> syllable_evidence(const std::vector<double>& fits);

// Each syllable's confidence in 0..1 from its evidence (per syllable of the transcript; NaN for one
// no chain placed), half as it is and half against the recording's median: in a room or in noise
// every syllable's evidence is lower, and a threshold on the evidence alone flagged half of the
// right syllables there and almost none in clean speech (issue 12: the threshold must hold across
// conditions); the absolute half keeps a recording aligned badly throughout from looking normal.
// A recording whose median is under a clean recording's has most of the shortfall given back
// besides: half was not enough to keep a room from flagging a fifth of its right syllables, and
// giving back more from every recording flagged more of the clean ones (espeak-ng's).
void set_confidences(const std::vector<double>& evidence, Timeline& result);

}  // namespace talkface::detail

#endif

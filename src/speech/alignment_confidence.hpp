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

// The weight of the emissions (viterbi_align's emission_weight) in the searches whose
// disagreement syllable_steadiness weighs (light_search): with the sounds light, a syllable the
// sounds hold stays where it was, and one the duration priors and its neighbours put there moves.
// The lighter, the more such a syllable moves, down to where right ones start to move too
// (bench/ Session 14 and 15, replayed from dumped starts of searches at 0.1-0.7, then measured):
// the person's tuning syllables >100 ms off caught at 0.7 163 of 296, 0.5 167, 0.25 204, 0.15
// 214 (the v- and w- voices gaining too), with no tuning condition of any voice over 9.5%; at 0.1
// 220 but a held-out condition at 10% and fewer of the w- voice's.
constexpr double kLightSoundsWeight = 0.15;
// The same for a lenient chain (lenient alignment), kept at session 14's quarter: its states weigh
// the duration priors at 1, not as a plain chain's, and at 0.15 the person's tuning syllables >100
// ms off caught with `--lenient` fell 264 -> 255 of 443, held out 43 -> 35 of 75.
constexpr double kLenientLightSoundsWeight = 0.25;

// Where `chain` searched again on `scores` with the sounds at `sounds_weight` (kLightSoundsWeight,
// or kLenientLightSoundsWeight for a lenient chain) places its syllables, with the landmarks'
// bonus (EmissionScores::boundary) or without it (set aside and restored before it returns).
// syllable_steadiness weighs both: the landmarks pull a boundary onto
// any frame where the spectrum changes, so a syllable drifted onto its neighbour's change stays
// there in the search with them; without them only the sounds and the duration priors hold it
// (bench/ Session 14: 167 of the person's 296 tuning syllables >100 ms off caught against 160, at
// fewer of the right ones flagged).
std::vector<SyllableFrames> light_search(const SentenceChain& chain, EmissionScores& scores, ViterbiWorkspace& workspace,
                                         double sounds_weight, bool with_landmarks);

// Per syllable placed at `placed` (frames of a chain's search), what other searches of the same
// frames say of where it starts, added to its evidence (not its neighbours': the disagreement is
// the syllable's own): less, the more frames (up to a cap) each of `others` starts it earlier or
// later. A syllable whose start moves between the aligner's last two passes, or when the sounds
// weigh less (kLightSoundsWeight), is likely misplaced; unlike the fit, which a room or noise
// lowers for every syllable, the paths of a right syllable agree there too. A syllable one of them
// does not place (end_frame 0) counts nothing.
std::vector<double> syllable_steadiness(const std::vector<SyllableFrames>& placed,
                                        const std::vector<std::vector<SyllableFrames>>& others);

// Per syllable of `chain`, how sure the search is of where `path` starts it, from the best whole
// path starting the syllable's first state on `path` at each frame (`marginals`): of the starts
// within 15 frames of the path's, each weighed by exp(its score less the best's, over 3), the
// share within a frame of it. A syllable whose start the search cannot
// decide (its sounds fit a start a few frames away as well) is as likely misplaced as one other
// searches move, and the share sees it without searching again with the sounds lighter (bench/
// Session 17 and 18: the person's tuning syllables >100 ms off caught 207 -> 214 of 290). 1 (sure)
// for every syllable where `marginals` is empty (a chain searched in windows).
std::vector<double> start_sureness(const SentenceChain& chain, const std::vector<StateSegment>& path,
                                   const EntryMaxMarginals& marginals);

// Per syllable of `chain`, how likely the search finds it that `path` starts it 100 ms or more from
// where it should: of every start of the syllable's first state that `marginals` holds (within 30
// frames of the path's), each weighed by exp(its score less the best's, over 10), the share 10
// frames or more from the path's. The near share of start_sureness sees a start the search cannot
// decide within a few frames; a syllable placed a syllable off is often sure of its start there
// and yet has a start 100-300 ms away nearly as good (a run the sounds fit either way), which this
// sees (bench/ Session 19: the person's tuning syllables >100 ms off caught 204 -> 217 of 276, no
// tuning condition of the three voices flagging more of its right ones than before, 7.8%). 0 for
// every syllable where `marginals` is empty (a chain searched in windows).
std::vector<double> far_start_share(const SentenceChain& chain, const std::vector<StateSegment>& path,
                                    const EntryMaxMarginals& marginals);

// How well a path fits a syllable's frames: how probable the sound the path gives each frame is
// among all sounds (the mean posterior of its class), and how much better a free sequence of sounds
// fits the syllable's stretch than the path does (text_fit_gap's loop, per frame).
struct SyllableFit {
    double posterior = 0.0;
    double free_gap = 0.0;
};

// Per syllable of `chain` (holding `frames` on `path`), its SyllableFit.
std::vector<SyllableFit> syllable_fit_parts(const SentenceChain& chain, const std::vector<StateSegment>& path,
                                            const EmissionScores& scores, const std::vector<SyllableFrames>& frames);

// Per syllable of `chain`, its fit as one number: the posterior less the free sounds' gap.
std::vector<double> syllable_fits(const SentenceChain& chain, const std::vector<StateSegment>& path,
                                  const EmissionScores& scores, const std::vector<SyllableFrames>& frames);

// Per syllable of `chain` (holding `frames` on `path`), what its timing says of its place, added to
// its fit: more where the spectrum changes at its start (EmissionScores::boundary), less the more
// its length departs from the pace of the syllables around it (its length against its duration
// prior's, relative to theirs) and the more the path squeezes or stretches its sounds against their
// priors (a drifted syllable is fitted to speech not its own by bending its lengths).
std::vector<double> syllable_timing(const SentenceChain& chain, const std::vector<StateSegment>& path,
                                    const EmissionScores& scores, const std::vector<SyllableFrames>& frames);

// What one syllable's place rests on, gathered per chain (place_syllables) and weighed together
// per recording (set_confidences).
struct SyllableEvidence {
    bool is_measured = false;  // false: no chain placed it, or lenient alignment fitted it as generic speech
    std::size_t chain = 0;     // its chain: its neighbours' evidence joins its own within one
    SyllableFit fit;
    double timing = 0.0;      // syllable_timing
    double steadiness = 0.0;  // syllable_steadiness
    double sureness = 1.0;    // start_sureness; 1 where not measured (lenient alignment)
    double far_start = 0.0;   // far_start_share; 0 where not measured (lenient alignment)
};

// Each measured syllable's confidence in 0..1 from its evidence (per syllable of the transcript;
// one not measured is left as it is).
//
// The free sounds' gap is first scaled to a clean recording's spread where the recording's own is
// wider: noise and music make the gap of every syllable, right or not, scatter more (its spread
// over a recording's syllables, 0.066 on the person's clean passages, 0.08-0.09 at 15-20 dB SNR),
// and unscaled it flagged up to 13% of the right syllables there against 3-6% in clean speech
// (issue 12: the threshold must hold in every condition). Then a syllable's fit (posterior less
// gap, plus its timing) is averaged with its neighbours' in its chain (drift comes in runs: a
// syllable placed a syllable off pulls its neighbours with it), its steadiness added and its
// unsureness (1 - sureness, weighed by kUnsureWeight) and far start share taken off, these three
// its own in part and its neighbours' averaged for the rest (a misplaced run disagrees together;
// lenient alignment: its own alone), and the sum
// weighed half as it is and half against the recording's median: in a room or in noise every
// syllable's evidence is lower, and a threshold on the evidence alone flagged half of the right
// syllables there and almost none in clean speech; the absolute half keeps a recording aligned
// badly throughout from looking normal. A recording whose median is under a clean recording's has
// most of the shortfall given back besides: half was not enough to keep a room from flagging a
// fifth of its right syllables, and giving back more from every recording flagged more of the
// clean ones (espeak-ng's). `is_lenient`: the evidence came from lenient alignment, whose light
// searches weigh the sounds otherwise (kLenientLightSoundsWeight) and which is calibrated on its own.
void set_confidences(const std::vector<SyllableEvidence>& evidence, bool is_lenient, Timeline& result);

}  // namespace talkface::detail

#endif

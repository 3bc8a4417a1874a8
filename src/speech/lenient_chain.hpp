// Lenient alignment (issue 13): a transcript that differs from the speech by a word or two. Each
// syllable of a chain may be skipped and generic speech may stand between any two syllables, both
// at a cost, so that the search fits the text where the speech says it and generic speech where it
// does not; what the path leaves to generic speech is reported as a TextMismatch.
#ifndef TALKFACE_SPEECH_LENIENT_CHAIN_HPP
#define TALKFACE_SPEECH_LENIENT_CHAIN_HPP

#include <vector>

#include "speech/alignment_confidence.hpp"
#include "speech/frame_features.hpp"
#include "speech/hsmm.hpp"
#include "speech/sentence_chains.hpp"
#include "speech/sentence_cutter.hpp"
#include "talkface/timeline.hpp"

namespace talkface::detail {

// An optional state of generic speech after syllable `syllable` (an index into the chain's
// syllables), at the price lenient alignment pays for speech the text does not say.
PhoneState generic_speech_state(std::size_t syllable);

// Per syllable, whether the speech says another syllable there by two measures that do not
// share their evidence: its held-out gap (held_out_fit_gaps, per syllable of the plain path) and
// its tone gap (tone_gaps, tone_contour.hpp) are both high (lenient_chain.cpp gives the bars).
// Missing or NaN: not.
std::vector<bool> heard_otherwise(const std::vector<double>& held_out_gaps, const std::vector<double>& tone_gaps);

// `chain` with its states made lenient: every syllable's states skippable at a cost (less for a
// syllable `is_heard_otherwise`, heard_otherwise), and an optional generic-speech state after the
// leading silence and after every syllable.
SentenceChain lenient_chain(const SentenceChain& chain, const std::vector<bool>& is_heard_otherwise = {});

// Per syllable of `chain`, its fit (syllable_fits) over the frames its states hold on `path`.
std::vector<double> fits_on_path(const SentenceChain& chain, const std::vector<StateSegment>& path,
                                 const EmissionScores& scores);

// `shares` (per syllable; NaN: not measured) with the rival_share of each syllable the lenient
// chain's `path` skips, over the frames it holds on the chain's plain path (`plain_frames`).
void add_rival_shares(const SentenceChain& lenient, const std::vector<StateSegment>& path,
                      const std::vector<SyllableFrames>& plain_frames, const EmissionScores& scores,
                      std::vector<double>& shares);

// The syllables of runs the lenient chain's `path` skips (neighbours skipped together) where
// neither one of them nor a neighbour of the run fits the chain's plain path (`plain_fits`:
// fits_on_path of the path without leniency) as an outlier of the chain's: more than
// kOutlierDeviations (lenient_chain.cpp) median absolute deviations under the median, and no
// syllable of the run has a held-out gap (`held_out_gaps`, below) above kMinHeldOutGapUnlike,
// which stands for an outlier where noise spreads the fits; or where no syllable of the run is
// beaten on its plain-path stretch by at least kMinRivalShare of the unlike
// syllables (`rival_shares`, per syllable, add_rival_shares; NaN or missing: not judged so); or
// where no syllable of the run has a held-out gap (`held_out_gaps`, per syllable: the syllables of
// held_out_fit_gaps on the plain path; NaN or missing: not judged so) of kMinHeldOutGapSkipped. A
// person's syllable that fits the models a little worse than most, in a right text, costs less
// skipped than fitted, yet on the plain path it fits within the chain's usual spread, or, where it
// is an outlier, still better than nearly every unlike syllable; a changed word does neither. Of
// a run kept, the syllables at its ends that gap under kMinHeldOutGapAtEdge (from each end inward)
// are returned too: right neighbours the path skipped with a changed word. A run that holds a
// syllable `is_heard_otherwise` (heard_otherwise) is kept, but for its edges.
std::vector<std::size_t> unsupported_skips(const SentenceChain& lenient, const std::vector<StateSegment>& path,
                                           const std::vector<double>& plain_fits, const std::vector<double>& rival_shares,
                                           const std::vector<double>& held_out_gaps, const std::vector<bool>& is_heard_otherwise = {});

// The generic-speech states of `lenient` that `path` holds for less than most of a syllable of the
// chain's plain path (`plain_frames`: frames_on_path of the path without leniency).
std::vector<std::size_t> short_generic(const SentenceChain& lenient, const std::vector<StateSegment>& path,
                                       const std::vector<SyllableFrames>& plain_frames);

// `lenient` with its states `states` (generic speech) no longer usable.
void forbid_states(SentenceChain& lenient, const std::vector<std::size_t>& states);

// `lenient` with `syllables` no longer skippable.
void forbid_skips(SentenceChain& lenient, const std::vector<std::size_t>& syllables);

// Whether the lenient chain's `path` says the text as written: every syllable whole and no
// generic speech.
bool takes_text_whole(const SentenceChain& lenient, const std::vector<StateSegment>& path);

// Places the syllables of a lenient chain's `path` (the `chain_index`th) in `result` with their
// `evidence`, as place_syllables does, its timing and the disagreement of `other_frames` (other
// searches' frames_on_path) included; and for each stretch the path fits with generic speech or
// skips: a TextMismatch in result.mismatches and a warning, its syllables spread over the stretch
// at its loudness dips with confidence 0 (not measured: set_confidences leaves them so). A
// syllable beside a skipped one whose fit on `path` is an outlier of the chain's and whose held-out
// gap (`held_out_gaps`, as unsupported_skips takes them) is not under kMinHeldOutGapAtEdge, or
// whose held-out gap is above kMinHeldOutGapBeside, joins its mismatch.
void place_lenient(const SentenceChain& chain, std::size_t chain_index, const std::vector<StateSegment>& path,
                   const std::vector<std::vector<SyllableFrames>>& other_frames, const std::vector<double>& held_out_gaps, const EmissionScores& scores,
                   const FeatureTrack& track, const LoudnessProfile& loudness, Timeline& result,
                   std::vector<SyllableEvidence>& evidence);

}  // namespace talkface::detail

#endif

// The alignment passes (SPEC "Alignment", thesis chapter 3): a chain's best path, and the rounds of
// models re-estimated on the recording that come before the final pass.
#ifndef TALKFACE_SPEECH_ALIGNMENT_PASSES_HPP
#define TALKFACE_SPEECH_ALIGNMENT_PASSES_HPP

#include <cstddef>
#include <vector>

#include "speech/acoustic_model.hpp"
#include "speech/alignment_progress.hpp"
#include "speech/frame_features.hpp"
#include "speech/hsmm.hpp"
#include "speech/sentence_chains.hpp"
#include "speech/sentence_cutter.hpp"
#include "talkface/timeline.hpp"

namespace talkface::detail {

// SPEC "Alignment": a first pass on hand-set models, then three rounds re-estimated on the audio
// (the first pass's paths give the first round's models, the third round's the final pass's).
inline constexpr int kReestimationRounds = 3;

// The passes over the chains that share the bar's alignment part: kReestimationRounds of
// estimation, as many again in a room on its features without the ringing (late_reverb.hpp) and
// as many again for the sentences clear of a music bed (bed_free_models.hpp), which take as long,
// and the final one.
int alignment_passes(bool is_reestimated_dry, bool is_reestimated_clear_of_bed);

// A chain's best path on `scores`; with `marginals`, over all frames, with its EntryMaxMarginals.
// \throws talkface::AlignmentError if its syllables do not fit in its stretch of speech.
std::vector<StateSegment> align_chain(const SentenceChain& chain, const EmissionScores& scores,
                                      ViterbiWorkspace& workspace, std::size_t stop_frame,
                                      const Timeline& transcript, EntryMaxMarginals* marginals = nullptr);

// What the re-estimation learned: the models of the last round, and what its last round saw in
// all and from each half of each sentence (per chain), for the leave-one-out check; and each
// chain's path in the last round, on the round before's models, whose disagreement with the final
// pass's path lowers a syllable's confidence (syllable_steadiness); and how far the last round's
// paths speak through their closures (typical_closure_run_on), read before any chain is measured.
struct Reestimation {
    AcousticModel model = AcousticModel::hand_set();
    ModelEstimator whole;
    std::vector<std::vector<ModelEstimator>> halves;
    std::vector<std::vector<StateSegment>> last_paths;
    double closure_run_on = 0.0;
};

// SPEC "Alignment": a first pass on the hand-set models, then kReestimationRounds rounds of
// models re-estimated on the paths of every chain, reported as passes `first_pass` on of `passes`.
// Where `is_learned_from` is given, every chain is aligned but the models learn from those it
// marks alone (and the leave-one-out halves of the others are empty).
Reestimation reestimate(const FeatureTrack& track, const LoudnessProfile& loudness,
                        const Timeline& transcript, const std::vector<SentenceChain>& chains,
                        ProgressReporter& progress, int first_pass, int passes,
                        const std::vector<bool>& is_learned_from = {});

}  // namespace talkface::detail

#endif

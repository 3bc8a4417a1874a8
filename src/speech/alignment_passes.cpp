#include "speech/alignment_passes.hpp"

#include <utility>

#include "speech/alignment_checks.hpp"
#include "speech/text_fit.hpp"
#include "talkface/errors.hpp"

namespace talkface::detail {

namespace {

// How much of a long sentence the first pass, on hand-set models, aligns: two minutes.
constexpr std::size_t kBootstrapFrames = 12000;

}  // namespace

int alignment_passes(bool is_reestimated_dry, bool is_reestimated_clear_of_bed) {
    return 1 +
           kReestimationRounds * (1 + (is_reestimated_dry ? 1 : 0) + (is_reestimated_clear_of_bed ? 1 : 0));
}

std::vector<StateSegment> align_chain(const SentenceChain& chain, const EmissionScores& scores,
                                      ViterbiWorkspace& workspace, std::size_t stop_frame,
                                      const Timeline& transcript, EntryMaxMarginals* marginals) {
    std::vector<StateSegment> path =
        marginals ? viterbi_align_with_marginals(chain.states, scores, workspace, *marginals)
                  : viterbi_align(chain.states, scores, workspace, stop_frame);
    if (path.empty()) {
        throw AlignmentError(describe_sentence(chain.first_sentence, chain.speech, transcript) + ": its " +
                             syllable_count(chain.syllables.size()) +
                             (chain.syllables.size() == 1 ? " does" : " do") +
                             " not fit in so short a stretch of speech; check the transcript");
    }
    return path;
}

Reestimation reestimate(const FeatureTrack& track, const LoudnessProfile& loudness,
                        const Timeline& transcript, const std::vector<SentenceChain>& chains,
                        ProgressReporter& progress, int first_pass, int passes,
                        const std::vector<bool>& is_learned_from) {
    Reestimation learned;
    std::vector<float> observations;
    EmissionScores scores;
    ViterbiWorkspace workspace;
    std::vector<double> closure_run_on;
    for (int pass = 0; pass < kReestimationRounds; ++pass) {
        const bool is_last_estimate = pass + 1 == kReestimationRounds;
        ModelEstimator estimator;
        if (is_last_estimate) {
            learned.halves.assign(chains.size(), {});
            learned.last_paths.reserve(chains.size());
        }
        for (std::size_t w = 0; w < chains.size(); ++w) {
            const SentenceChain& chain = chains[w];
            observe(track, loudness, chain.searched, observations);
            learned.model.score(observations.data(), chain.searched.length(), scores);
            // The hand-set models only start the re-estimation: on a sentence long enough to be
            // searched in windows (a transcript without punctuation), their weak evidence lets the
            // open-ended windows slip a syllable now and then, which adds up over an hour; its
            // first minutes teach the models every sound many times over.
            const auto path = align_chain(chain, scores, workspace,
                                          pass == 0 ? kBootstrapFrames : scores.frame_count, transcript);
            const bool is_learned = is_learned_from.empty() || is_learned_from[w];
            if (is_learned) estimator.add(observations, chain.states, path);
            if (is_last_estimate) {
                const auto halves = split_in_halves(chain, path);
                learned.halves[w].assign(halves.size(), ModelEstimator());
                for (std::size_t h = 0; h < halves.size() && is_learned; ++h)
                    learned.halves[w][h].add(observations, chain.states, halves[h]);
                learned.last_paths.push_back(path);
                add_closure_run_on(chain, path, scores, closure_run_on);
            }
            report_pass(progress, first_pass + pass, passes, w, chains.size());
        }
        learned.model = estimator.estimate(kReestimatedWeight);
        if (is_last_estimate) learned.whole = std::move(estimator);
    }
    learned.closure_run_on = typical_closure_run_on(std::move(closure_run_on));
    return learned;
}

}  // namespace talkface::detail

#include "speech/lenient_placement.hpp"

#include <utility>

#include "speech/lenient_chain.hpp"
#include "speech/text_fit.hpp"
#include "speech/tone_witness.hpp"

namespace talkface::detail {

std::vector<LenientEvidence> measure_lenient_evidence(
    const FeatureTrack& track, const LoudnessProfile& loudness, const std::vector<SentenceChain>& chains,
    const Reestimation& learned, std::vector<float>& observations, ViterbiWorkspace& workspace) {
    std::vector<LenientEvidence> lenient_evidence;
    std::vector<std::vector<StateSegment>> plain_paths;
    for (std::size_t w = 0; w < chains.size(); ++w) {
        observe(track, loudness, chains[w].searched, observations);
        LenientEvidence& found = lenient_evidence.emplace_back();
        learned.model.score(observations.data(), chains[w].searched.length(), found.scores);
        plain_paths.push_back(
            viterbi_align(chains[w].states, found.scores, workspace, found.scores.frame_count));
        // A text with more syllables than the speech holds may have no plain path: no fits.
        const auto& plain = plain_paths.back();
        if (plain.empty()) continue;
        found.plain_fits = fits_on_path(chains[w], plain, found.scores);
        found.plain_frames = frames_on_path(chains[w], plain);
        // Each syllable's held-out gap on the plain path (lenient_chain.hpp judges skips and
        // grows mismatches by it): models re-estimated on a wrong text learn its sounds from
        // the speech that does not say them, those learned without its half have not.
        // Closures scored as silence: lenient_chain.cpp's limits on these gaps were set so.
        EmissionScores held_out_scores;
        found.held_out_gaps = held_out_fit_gaps(chains[w], split_in_halves(chains[w], plain), observations,
                                                learned.whole, learned.halves[w], held_out_scores, 0.0)
                                  .syllables;
    }
    std::vector<std::vector<double>> tone_gaps = tone_gaps_of_chains(chains, plain_paths, track);
    for (std::size_t w = 0; w < chains.size(); ++w) lenient_evidence[w].tone_gaps = std::move(tone_gaps[w]);
    return lenient_evidence;
}

void place_lenient_chain(const SentenceChain& plain_chain, std::size_t w, LenientEvidence& found,
                         const std::vector<StateSegment>& last_path, ViterbiWorkspace& workspace,
                         const Timeline& transcript, const FeatureTrack& track,
                         const LoudnessProfile& loudness, Timeline& result,
                         std::vector<SyllableEvidence>& evidence) {
    EmissionScores& chain_scores = found.scores;
    const std::vector<bool> is_heard_otherwise = heard_otherwise(found.held_out_gaps, found.tone_gaps);
    SentenceChain chain = lenient_chain(plain_chain, is_heard_otherwise);
    auto path = align_chain(chain, chain_scores, workspace, chain_scores.frame_count, transcript);
    // Each round forbids at least one more skip or generic stretch: it ends. Rival shares
    // are measured only for the syllables a path skips (50 small searches each).
    std::vector<double> rival_shares;
    for (;;) {
        add_rival_shares(chain, path, found.plain_frames, chain_scores, rival_shares);
        const auto skips = unsupported_skips(chain, path, found.plain_fits, rival_shares, found.held_out_gaps,
                                             is_heard_otherwise);
        const auto generic = short_generic(chain, path, found.plain_frames);
        if (skips.empty() && generic.empty()) break;
        forbid_skips(chain, skips);
        forbid_states(chain, generic);
        path = align_chain(chain, chain_scores, workspace, chain_scores.frame_count, transcript);
    }
    // The other searches whose starts weigh in (syllable_steadiness), as for a plain chain:
    // the lenient chain searched again with the sounds weighing less, and, where the path
    // takes the text whole (no mismatch), the same without the landmarks' bonus and the
    // last round's path of the plain chain, the same text on the models one round older.
    // Beside a mismatch the plain path is another reading of the speech (the text said
    // whole), not an opinion on the lenient one; and generic speech has no duration prior
    // of a syllable's, so without the landmarks its edges wander with the sounds light
    // and move the right syllables beside it (tests/speech/lenient_test.cpp: 里 after the
    // word the transcript lacks).
    std::vector<std::vector<SyllableFrames>> other_frames = {
        light_search(chain, chain_scores, workspace, kLenientLightSoundsWeight, true)};
    if (takes_text_whole(chain, path)) {
        other_frames.push_back(
            light_search(chain, chain_scores, workspace, kLenientLightSoundsWeight, false));
        other_frames.push_back(frames_on_path(plain_chain, last_path));
    }
    place_lenient(chain, w, path, other_frames, found.held_out_gaps, chain_scores, track, loudness, result,
                  evidence);
    // Its scores are not needed again: the memory goes back chain by chain.
    chain_scores = EmissionScores();
}

}  // namespace talkface::detail

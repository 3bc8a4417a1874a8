#include "speech/chain_alignment.hpp"

#include <algorithm>
#include <cstddef>

#include "speech/alignment_confidence.hpp"
#include "speech/alignment_passes.hpp"
#include "speech/bed_free_models.hpp"
#include "speech/chain_measures.hpp"
#include "speech/hsmm.hpp"
#include "speech/lenient_placement.hpp"
#include "speech/phone_chain.hpp"
#include "speech/room_closures.hpp"
#include "speech/room_fall.hpp"
#include "speech/room_placement.hpp"
#include "speech/run_together.hpp"
#include "speech/sentence_chains.hpp"
#include "speech/syllable_placement.hpp"
#include "speech/tone_witness.hpp"

namespace talkface::detail {

namespace {

// Whether `path` holds a pause the text does not mark longer than kMaxUnmarkedPauseFrames, where
// the chain's text marks some.
bool has_long_unmarked_pause(const SentenceChain& chain, const std::vector<StateSegment>& path) {
    if (!has_marked_pause(chain.states)) return false;
    return std::any_of(path.begin(), path.end(), [&](const StateSegment& segment) {
        return chain.states[segment.state].role == StateRole::short_pause &&
               segment.end_frame - segment.first_frame > kMaxUnmarkedPauseFrames;
    });
}

// The chains of `cut`'s sentences on `spans` (group_chains) in their search spans, their states set
// as align_chains' flags ask.
std::vector<SentenceChain> chains_to_align(const FeatureTrack& track, const LoudnessProfile& loudness,
                                           const Timeline& transcript, const SentenceCut& cut,
                                           const std::vector<FrameSpan>& spans, bool is_lenient,
                                           bool is_kept_to_marks, bool is_nasal_release_allowed) {
    std::vector<SentenceChain> chains = group_chains(transcript, cut, spans);
    set_search_spans(track, loudness, chains);
    // Lenient alignment's prices of a skipped syllable and of generic speech were set against the
    // duration priors at weight 1 (lenient_chain.cpp, bench/ lenient_bench.py): it keeps them so.
    if (is_lenient)
        for (auto& chain : chains)
            for (auto& state : chain.states) state.duration_weight = 1.0;
    if (is_kept_to_marks)
        for (auto& chain : chains) keep_pauses_to_marks(chain.states);
    if (is_nasal_release_allowed)
        for (auto& chain : chains) let_closures_after_nasals_be_skipped(chain.states);
    return chains;
}

// The final pass's scratch, reused chain by chain (a chain's observations and scores, the path
// search's tables and its start's marginals, as given out and in a room), and what it gathers of
// each syllable for its confidence (set_confidences): as given out and, in a room, as placed with
// the closures ringing.
struct FinalPass {
    FinalPass(std::size_t syllables, bool in_room)
        : evidence(syllables), room_evidence(in_room ? syllables : 0) {}
    std::vector<float> observations;
    EmissionScores scores;
    ViterbiWorkspace workspace;
    EntryMaxMarginals marginals, room_marginals;
    std::vector<SyllableEvidence> evidence, room_evidence;
};

// Chain `w`'s final pass on the re-estimated models `learned` (measure_chain, checked when
// `is_checked`): its syllables, sentences' spans and metrics into `aligned`, their evidence into
// `pass`, and its path into `checked_path` when the tones' witness reads it. In a room
// (aligned.room_result) the chain is also placed with its closures ringing (place_in_room), on
// `dry`'s features and models where the room's ringing was taken off, else on the recorded ones.
void align_final_chain(const SentenceChain& chain, std::size_t w, const FeatureTrack& track,
                       const LoudnessProfile& loudness, const Timeline& transcript,
                       const Reestimation& learned, DryRoom* dry, std::size_t spoken_sentences,
                       bool is_checked, bool is_on_bed_free_models, FinalPass& pass, CutAlignment& aligned,
                       std::vector<StateSegment>* checked_path) {
    observe(track, loudness, chain.searched, pass.observations);
    learned.model.score(pass.observations.data(), chain.searched.length(), pass.scores);
    // In a room the syllables given out are those placed with the closures ringing, with their
    // confidences (align_cut): the confidences of this placement, which the checks read, are
    // read by nothing, and the searches that weigh them are left out (the start's marginals,
    // those with the sounds lighter: 6% of a room's instructions, bench/README.md Session 28).
    const bool is_given_out = !aligned.room_result;
    const auto path = align_chain(chain, pass.scores, pass.workspace, pass.scores.frame_count, transcript,
                                  is_given_out ? &pass.marginals : nullptr);
    aligned.has_long_unmarked_pause = aligned.has_long_unmarked_pause || has_long_unmarked_pause(chain, path);
    if (checked_path) *checked_path = path;
    // The last round's path, and the searches again with the sounds weighing less, with and
    // without the landmarks' bonus: where they start a syllable elsewhere, the sounds did not
    // hold it there.
    std::vector<std::vector<SyllableFrames>> other_frames;
    if (is_given_out)
        other_frames = {light_search(chain, pass.scores, pass.workspace, kLightSoundsWeight, true),
                        light_search(chain, pass.scores, pass.workspace, kLightSoundsWeight, false),
                        frames_on_path(chain, learned.last_paths[w])};
    // Before measure_chain, which leaves held-out models' scores in `scores`.
    if (aligned.room_result)
        place_in_room(chain, w, dry, (dry ? dry->learned : learned).last_paths[w], dry ? dry->track : track,
                      loudness, transcript, pass.scores, pass.workspace, pass.room_marginals,
                      *aligned.room_result, pass.room_evidence);
    const ChainMeasureInputs measured{
        chain,
        w,
        path,
        pass.observations,
        other_frames,
        learned,
        spoken_sentences,
        forgiven_closure_run_on(learned, spoken_sentences, aligned.room_result.has_value()),
        track,
        loudness,
        transcript,
        is_checked,
        is_on_bed_free_models,
        aligned.room_result.has_value()};
    measure_chain(measured, pass.scores, pass.workspace, aligned.result, pass.evidence, aligned.spans,
                  aligned.metrics);
    if (const auto voiced_end = voiced_end_past_path(chain, track, aligned.result))
        aligned.voiced_ends.push_back(*voiced_end);
    if (is_given_out) set_start_evidence(chain, path, pass.marginals, pass.evidence);
}

}  // namespace

CutAlignment align_chains(const FeatureTrack& track, const LoudnessProfile& loudness,
                          const Timeline& transcript, const SentenceCut& cut, ProgressReporter& progress,
                          bool is_checked, bool is_lenient, bool is_kept_to_marks,
                          bool is_nasal_release_allowed) {
    CutAlignment aligned;
    // Where sentences run together the cutter's spans are guesses: the syllables place them, and
    // the sentences' lengths are checked on where the syllables put them.
    aligned.spans = cut.spans;
    std::vector<SentenceChain> chains =
        chains_to_align(track, loudness, transcript, cut, aligned.spans, is_lenient, is_kept_to_marks,
                        is_nasal_release_allowed);
    const std::vector<bool> is_spoken = spoken_sentences_of(transcript);
    const auto spoken_sentences =
        static_cast<std::size_t>(std::count(is_spoken.begin(), is_spoken.end(), true));

    // Lenient alignment places its syllables on chains of its own (lenient_chain.hpp). The room is
    // read before the first re-estimation, so that the bar gives the second its own share: at the
    // sentence ends (is_room), or where the noise covers their tails, from how fast the level
    // falls anywhere (falls_as_room); the sentence ends stay is_room's.
    const bool in_room = !is_lenient && (is_room(chains) || falls_as_room(track, loudness, spoken_sentences));
    const std::optional<RoomRinging> room_ringing =
        in_room ? measure_room_ringing(track, chains) : std::nullopt;
    const std::vector<bool> clear_of_bed =
        is_lenient ? std::vector<bool>{} : chains_clear_of_bed(chains, loudness);
    const int passes = alignment_passes(room_ringing.has_value(), !clear_of_bed.empty());
    const Reestimation learned = reestimate(track, loudness, transcript, chains, progress, 0, passes);
    aligned.result = transcript;
    aligned.result.duration_s = track.duration_s;
    if (in_room) aligned.room_result = aligned.result;
    std::optional<DryRoom> dry =
        dry_room(track, loudness, transcript, chains, room_ringing, progress, passes);
    const std::optional<Reestimation> learned_clear_of_bed =
        clear_of_bed.empty()
            ? std::nullopt
            : std::optional<Reestimation>(reestimate(track, loudness, transcript, chains, progress,
                                                     passes - 1 - kReestimationRounds, passes, clear_of_bed));
    aligned.metrics.assign(aligned.spans.size(), SentenceMetrics());
    FinalPass pass(transcript.syllables.size(), aligned.room_result.has_value());
    // The checks' paths of a room's chains, for the tones' witness.
    const bool is_tone_witnessed = aligned.room_result && is_checked &&
                                   spoken_sentences >= kMinToneWitnessSentences && !track.pitch.empty();
    std::vector<std::vector<StateSegment>> checked_paths(is_tone_witnessed ? chains.size() : 0);
    std::vector<LenientEvidence> lenient_evidence;
    if (is_lenient)
        lenient_evidence =
            measure_lenient_evidence(track, loudness, chains, learned, pass.observations, pass.workspace);
    for (std::size_t w = 0; w < chains.size(); ++w) {
        if (is_lenient)
            place_lenient_chain(chains[w], w, lenient_evidence[w], learned.last_paths[w], pass.workspace,
                                transcript, track, loudness, aligned.result, pass.evidence);
        else {
            const bool is_on_bed_free_models = learned_clear_of_bed && clear_of_bed[w];
            align_final_chain(chains[w], w, track, loudness, transcript,
                              is_on_bed_free_models ? *learned_clear_of_bed : learned, dry ? &*dry : nullptr,
                              spoken_sentences, is_checked, is_on_bed_free_models && !in_room, pass, aligned,
                              is_tone_witnessed ? &checked_paths[w] : nullptr);
        }
        report_pass(progress, passes - 1, passes, w, chains.size());
    }
    if (is_tone_witnessed) set_tone_gaps(chains, checked_paths, track, aligned.metrics);
    set_confidences(pass.evidence, is_lenient, aligned.result);
    if (aligned.room_result) set_confidences(pass.room_evidence, false, *aligned.room_result);
    return aligned;
}

}  // namespace talkface::detail

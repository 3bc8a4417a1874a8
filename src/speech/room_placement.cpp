#include "speech/room_placement.hpp"

#include <cstddef>

#include "speech/room_closures.hpp"
#include "speech/syllable_placement.hpp"

namespace talkface::detail {

std::optional<DryRoom> dry_room(const FeatureTrack& track, const LoudnessProfile& loudness,
                                const Timeline& transcript, const std::vector<SentenceChain>& chains,
                                const std::optional<RoomRinging>& room_ringing, ProgressReporter& progress,
                                int passes) {
    if (!room_ringing) return std::nullopt;
    DryRoom dry;
    dry.track = without_late_ringing(track, *room_ringing);
    dry.learned = reestimate(dry.track, loudness, transcript, chains, progress, kReestimationRounds, passes);
    return dry;
}

void place_in_room(const SentenceChain& plain_chain, std::size_t w, DryRoom* dry,
                   const std::vector<StateSegment>& last_path, const FeatureTrack& placed_track,
                   const LoudnessProfile& loudness, const Timeline& transcript, EmissionScores& scores,
                   ViterbiWorkspace& workspace, EntryMaxMarginals& room_marginals, Timeline& room_result,
                   std::vector<SyllableEvidence>& room_evidence) {
    EmissionScores& room_scores = dry ? dry->scores : scores;
    SentenceChain ringing = plain_chain;
    if (dry) {
        ringing.searched = plain_chain.searched_in_room;
        observe(dry->track, loudness, ringing.searched, dry->observations);
        dry->learned.model.score(dry->observations.data(), ringing.searched.length(), room_scores);
    }
    let_closures_ring(ringing.states);
    const auto room_path =
        align_chain(ringing, room_scores, workspace, room_scores.frame_count, transcript, &room_marginals);
    const std::vector<std::vector<SyllableFrames>> room_other_frames = {
        light_search(ringing, room_scores, workspace, kLightSoundsWeight, true),
        light_search(ringing, room_scores, workspace, kLightSoundsWeight, false),
        frames_on_path(plain_chain, last_path)};
    place_syllables(ringing, w, room_path, room_other_frames, room_scores, placed_track, room_result,
                    room_evidence);
    set_start_evidence(ringing, room_path, room_marginals, room_evidence);
}

Timeline with_room_placement(Timeline checked, const Timeline& room) {
    for (std::size_t i = 0; i < checked.syllables.size(); ++i) {
        const Syllable& placed = room.syllables[i];
        Syllable& syllable = checked.syllables[i];
        syllable.start_s = placed.start_s;
        syllable.final_start_s = placed.final_start_s;
        syllable.end_s = placed.end_s;
        syllable.confidence = placed.confidence;
    }
    return checked;
}

}  // namespace talkface::detail

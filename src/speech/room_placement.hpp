// Where a room's syllables are given out (issue 12, room_closures.hpp): placed with their closures
// ringing, on the recording without its ringing (late_reverb.hpp) and models re-estimated on it
// where the ringing was measured, else on the recorded features.
#ifndef TALKFACE_SPEECH_ROOM_PLACEMENT_HPP
#define TALKFACE_SPEECH_ROOM_PLACEMENT_HPP

#include <cstddef>
#include <optional>
#include <vector>

#include "speech/alignment_confidence.hpp"
#include "speech/alignment_passes.hpp"
#include "speech/alignment_progress.hpp"
#include "speech/frame_features.hpp"
#include "speech/hsmm.hpp"
#include "speech/late_reverb.hpp"
#include "speech/sentence_chains.hpp"
#include "speech/sentence_cutter.hpp"
#include "talkface/timeline.hpp"

namespace talkface::detail {

// A room's recording without its ringing (late_reverb.hpp), where the syllables given out are
// placed: its features, the models re-estimated on them, and a chain's observations and scores.
struct DryRoom {
    FeatureTrack track;
    Reestimation learned;
    std::vector<float> observations;
    EmissionScores scores;
};

// In a room whose ringing was measured (`room_ringing`), the recording without it (late_reverb.hpp)
// and models re-estimated on it, reported as the passes after the first re-estimation's of
// `passes`: the syllables given out are placed there, where a quiet onset after a vowel is no
// longer the vowel ringing on. Every check judges the recorded features: on the dry ones a wrong
// text fits its speech about as well as a right one (bench/README.md Sessions 24 and 25).
std::optional<DryRoom> dry_room(const FeatureTrack& track, const LoudnessProfile& loudness,
                                const Timeline& transcript, const std::vector<SentenceChain>& chains,
                                const std::optional<RoomRinging>& room_ringing, ProgressReporter& progress,
                                int passes);

// Chain `w` placed in a room with its closures ringing (let_closures_ring), its syllables into
// `room_result` and their evidence into `room_evidence`: on `dry`'s features and models where the
// room's ringing was taken off (late_reverb.hpp), searched only to where the voice stopped before
// the ringing (SentenceChain::searched_in_room), else on the recorded ones, whose scores of the
// chain's `searched` `scores` holds. `last_path` is the placing models' last round's path of the plain chain.
void place_in_room(const SentenceChain& plain_chain, std::size_t w, DryRoom* dry,
                   const std::vector<StateSegment>& last_path, const FeatureTrack& placed_track,
                   const LoudnessProfile& loudness, const Timeline& transcript, EmissionScores& scores,
                   ViterbiWorkspace& workspace, EntryMaxMarginals& room_marginals, Timeline& room_result,
                   std::vector<SyllableEvidence>& room_evidence);

// `checked`'s syllables with the times and confidences `room` gives them: as a room's are given out.
Timeline with_room_placement(Timeline checked, const Timeline& room);

}  // namespace talkface::detail

#endif

// A voice in a reverberant room (issue 12): the vowel before a stop or affricate rings on through
// the stop's closure, which then holds no silence for the closure's model to fit, and the path
// waits for a closure long enough to fall silent, a syllable or a run of them late (bench/README.md
// Session 17, "a room's closures"). Told by the recording, a room's final pass scores the closures
// as any sound at all, at a price per frame; the models and every check keep the silent closures.
#ifndef TALKFACE_SPEECH_ROOM_CLOSURES_HPP
#define TALKFACE_SPEECH_ROOM_CLOSURES_HPP

#include <vector>

#include "speech/phone_chain.hpp"
#include "speech/sentence_chains.hpp"

namespace talkface::detail {

// A recording is a room when the median over its chains of SentenceChain::tail_frames (how far
// end_before_tail moved each end) is at least this many frames: a voice's own fade moves an end
// 0-8 frames at the median of a recording, a room's tail 12-15 (bench/README.md Session 17).
inline constexpr double kRoomMedianTailFrames = 9.0;

// What a room's closure pays per frame held, scored as the class that fits the frame best: of
// 0.3, 0.5 and 1.0, 0.5 placed the rooms' tuning rows best (bench/README.md Session 18).
inline constexpr double kRoomClosureFrameLogPenalty = -0.5;

// Whether `chains` (with their search spans set, set_search_spans) are a room's: the median of
// their tail_frames is at least kRoomMedianTailFrames.
bool is_room(const std::vector<SentenceChain>& chains);

// `states` with each closure of a stop or affricate scored as generic speech (kGenericSpeech) at
// kRoomClosureFrameLogPenalty a frame, its duration prior and its skip as they were.
void let_closures_ring(std::vector<PhoneState>& states);

}  // namespace talkface::detail

#endif

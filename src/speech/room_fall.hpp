// A room bounds how fast a recording's level can fall (issue 12): wherever the voice stops, at a
// sentence's end or in a stop's closure after a vowel, the room's ringing goes on from the level the
// voice left and decays at the room's own rate, while in a dry recording the level falls from the
// vowel to the noise within a few frames. A recording has one room, so the fastest fall anywhere
// in it measures the room, where each sentence end alone may not: a noise 20-25 dB under the voice
// covers a small room's tail a few frames after it starts, and end_before_tail's move stays under
// is_room's bar (the phone kinds' p-speaker, bench/README.md Session 38 (pspeaker)).
#ifndef TALKFACE_SPEECH_ROOM_FALL_HPP
#define TALKFACE_SPEECH_ROOM_FALL_HPP

#include <cstddef>

#include "speech/frame_features.hpp"
#include "speech/sentence_cutter.hpp"

namespace talkface::detail {

// A line of one sentence may hold no stop where its voice ends at once, and end in a quiet voice's
// slow fade: its fastest fall says nothing of a room. (bench/README.md Session 39 (pspeaker2): the
// first sentence alone of the dry noisy and coded passages, 13 of 144 fall as a room's, the first
// two 1 of 144; a short kinds' dry line of 1-8 syllables 92 of 232.)
inline constexpr std::size_t kMinRoomFallSentences = 2;

// Whether the recording of `track`, which holds `spoken_sentences` sentences of the transcript,
// is a room by how fast its level falls: it holds at least kMinRoomFallSentences, and over
// kRoomFallFrames its fastest fall from a frame kRoomFallOverFloorDb or more over its floor
// (`loudness`'s energy_sound_floor_db) is less than kMaxRoomFallShare of the span from that floor
// to its loud frames.
bool falls_as_room(const FeatureTrack& track, const LoudnessProfile& loudness, std::size_t spoken_sentences);

}  // namespace talkface::detail

#endif

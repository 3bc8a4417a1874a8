// A voice in a reverberant room (issue 12): the room's late ringing taken out of the features,
// so that a quiet onset after a vowel is heard as itself and not as the vowel ringing on over it
// (bench/README.md Session 24, "a person's voice in a room"; Session 25). The room is the
// recording's own, read at its sentence ends, where the voice stops and only the ringing is left;
// the ringing is then followed frame by frame through the speech (Lebart, Boucher and Denbigh's
// late reverberation, per band), and what a frame holds above it is the voice.
#ifndef TALKFACE_SPEECH_LATE_REVERB_HPP
#define TALKFACE_SPEECH_LATE_REVERB_HPP

#include <optional>
#include <vector>

#include "speech/frame_features.hpp"
#include "speech/sentence_chains.hpp"

namespace talkface::detail {

// What a recording's sentence ends tell of its room.
struct RoomRinging {
    double decay_db_per_frame = 0.0;  // how fast the ringing falls once the voice has stopped
    // The share of a frame's voice power that rings on into the next frame, to decay from there.
    double voice_share = 0.0;
};

// What is left of a frame where the ringing takes it all, below the frame: 15 and 5 dB placed the
// rooms' tuning rows a little worse (bench/README.md Session 24).
inline constexpr double kDryFloorDb = 10.0;

// The room of the recording of `track`, read at the ends of `chains` (their search spans set,
// set_search_spans) that ring on (SentenceChain::ends_in_tail), from the least-squares line of
// each tail's level: the median over the tails of the line's fall a frame, and then of the line's
// level where the tail starts against the voice before it, each of the chain's frames weighed by
// the decay since (what the ringing is made of: where the voice fades before it stops, its last
// frames alone leave less ringing than the louder ones before them did). None where no tail falls.
std::optional<RoomRinging> measure_room_ringing(const FeatureTrack& track,
                                                const std::vector<SentenceChain>& chains);

// `track` with `room`'s ringing taken out of the levels the models read (the mel bands behind the
// cepstra, as the cepstra keep them, and the band levels), each followed frame by frame: the
// ringing decays at the room's rate, and each frame's voice adds RoomRinging::voice_share of its
// power to it; what a frame holds above the ringing is the voice, at least kDryFloorDb under the
// frame. The other columns and the pitch are the track's.
FeatureTrack without_late_ringing(const FeatureTrack& track, const RoomRinging& room);

}  // namespace talkface::detail

#endif

#include "speech/room_fall.hpp"

#include <algorithm>
#include <utility>
#include <vector>

#include "common/order_statistics.hpp"

namespace talkface::detail {

namespace {

// How far the level may fall, and over how many frames: a dry voice stopping falls from its vowel to
// the recording's floor within 40 ms (a 25 ms window passing the stop), a room lets it fall by its
// decay a frame over that time. A frame only just over the floor falls to it in any room; the
// falls that tell are those from kRoomFallOverFloorDb or more over it.
constexpr std::size_t kRoomFallFrames = 4;
constexpr float kRoomFallOverFloorDb = 15.0f;
// The recording's loud frames: its 95th percentile, as the loudness profile's speech level.
constexpr double kLoudShare = 0.95;
// A dry voice's fastest fall spans about the whole way from its loud frames to its floor, a room's
// ringing holds it to a share: of that span, per recording (the engine's levels copied offline,
// bench/README.md Session 39 (pspeaker2)), every passage of the dry rows of the corpora (noise,
// codecs, music, espeak-ng, the phone kinds but p-speaker) falls 0.68 or more (p-mp3; the others
// 0.75 and up, most near 1), the reverb rows 0.2-0.5, p-speaker's small room 0.44-0.63.
constexpr double kMaxRoomFallShare = 0.66;

}  // namespace

bool falls_as_room(const FeatureTrack& track, const LoudnessProfile& loudness, std::size_t spoken_sentences) {
    if (spoken_sentences < kMinRoomFallSentences) return false;
    std::vector<float> levels;
    levels.reserve(track.frame_count);
    for (std::size_t t = 0; t < track.frame_count; ++t)
        if (track.at(t, kEnergyDb) > kDigitalSilenceDb) levels.push_back(track.at(t, kEnergyDb));
    if (levels.size() <= kRoomFallFrames) return false;
    const float floor_db = loudness.energy_sound_floor_db;
    const float loud_db = percentile_of(std::move(levels), kLoudShare);
    // A fall into digital silence is an edit's or a lost packet's, not the voice's.
    float fastest_db = 0.0f;
    for (std::size_t t = 0; t + kRoomFallFrames < track.frame_count; ++t) {
        const float from_db = track.at(t, kEnergyDb);
        const float to_db = track.at(t + kRoomFallFrames, kEnergyDb);
        if (from_db >= floor_db + kRoomFallOverFloorDb && to_db > kDigitalSilenceDb)
            fastest_db = std::max(fastest_db, from_db - to_db);
    }
    return fastest_db < kMaxRoomFallShare * (loud_db - floor_db);
}

}  // namespace talkface::detail

// A room read from how fast the recording's level falls anywhere (falls_as_room, issue 12): a small
// room whose tails a noise covers, against a dry voice that fades slowly at its sentence ends but
// stops at once before a stop's closure.
#include <doctest/doctest.h>

#include <algorithm>
#include <vector>

#include "common/level_track.hpp"
#include "speech/room_fall.hpp"

using namespace talkface::detail;
using talkface::test::track_of;

namespace {

constexpr float kNoiseDb = -45.0f;
constexpr float kVowelDb = -20.0f;

// Sentences of two vowels of 20 frames with a closure of 6 frames between them, between pauses of
// 40 frames in a steady noise 25 dB under the vowels. Where the voice stops (at the closure and at
// the sentence's end) the level falls `closure_fall_db` and `end_fall_db` a frame down to the noise.
FeatureTrack recording_of(float closure_fall_db, float end_fall_db) {
    std::vector<float> levels(40, kNoiseDb);
    auto fall = [&](float step_db, std::size_t frames) {
        for (std::size_t k = 1; k <= frames; ++k)
            levels.push_back(std::max(kNoiseDb, kVowelDb - step_db * static_cast<float>(k)));
    };
    for (int sentence = 0; sentence < 4; ++sentence) {
        levels.insert(levels.end(), 20, kVowelDb);
        fall(closure_fall_db, 6);
        levels.insert(levels.end(), 20, kVowelDb);
        fall(end_fall_db, 40);
    }
    return track_of(levels);
}

LoudnessProfile noise_floor() {
    LoudnessProfile loudness;
    loudness.energy_sound_floor_db = kNoiseDb;
    return loudness;
}

}  // namespace

TEST_SUITE("room fall") {
    TEST_CASE("a small room ringing into the noise is a room, a slow fade at the ends is not") {
        // The room rings 1.2 dB a frame after the closure and at the ends: 5 dB in 4 frames, 25 over
        // the noise.
        CHECK(falls_as_room(recording_of(1.2f, 1.2f), noise_floor(), 4));
        // A dry voice: it falls to the noise in two frames wherever it stops.
        CHECK_FALSE(falls_as_room(recording_of(15.0f, 15.0f), noise_floor(), 4));
        // A quiet voice's own slow fade at its sentence ends falls as slowly as the room's ringing,
        // but before the closure the voice stops at once: no room lets it fall so fast.
        CHECK_FALSE(falls_as_room(recording_of(15.0f, 1.2f), noise_floor(), 4));
        // One sentence is too little of the voice to tell by.
        CHECK_FALSE(falls_as_room(recording_of(1.2f, 1.2f), noise_floor(), 1));
    }
}

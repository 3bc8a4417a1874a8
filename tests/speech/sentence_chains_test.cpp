// Where a sentence's voice ends before a room's tail (end_before_tail, issue 12: a quiet last
// syllable is speech, not a tail), and before the tail's ringing (end_before_ringing).
#include <doctest/doctest.h>

#include <vector>

#include "speech/sentence_chains.hpp"

using namespace talkface::detail;

namespace {

// A feature track whose whole-band level per frame is `levels_db` (the other columns 0).
FeatureTrack track_of(const std::vector<float>& levels_db) {
    FeatureTrack track;
    track.frame_count = levels_db.size();
    track.values.assign(levels_db.size() * kFeatureCount, 0.0f);
    for (std::size_t t = 0; t < levels_db.size(); ++t) track.values[t * kFeatureCount + kEnergyDb] = levels_db[t];
    return track;
}

}  // namespace

TEST_SUITE("sentence chains") {
    TEST_CASE("a room's tail, falling from the last vowel, is cut off") {
        std::vector<float> levels(30, -20.0f);  // the voice
        for (int k = 1; k <= 30; ++k) levels.push_back(-20.0f - 1.5f * static_cast<float>(k));  // the tail
        const FeatureTrack track = track_of(levels);
        // The voice ends after the last frame within 18 dB of its loudest: 12 frames into the fall.
        CHECK(end_before_tail(track, 0, levels.size()) == 42);
    }

    TEST_CASE("a large room's slow ringing is followed back to where the voice stopped") {
        std::vector<float> levels(30, -20.0f);  // the voice
        // The ringing, 12 dB under the voice where it stops, falls 0.3 dB a frame with a 1 dB ripple:
        // it passes 18 dB under the voice 23 frames after the voice stopped.
        for (int k = 0; k < 40; ++k)
            levels.push_back(-32.0f - 0.3f * static_cast<float>(k) + (k % 2 == 0 ? 1.0f : -1.0f));
        const FeatureTrack track = track_of(levels);
        const std::size_t mark = end_before_tail(track, 0, levels.size());
        CHECK(mark == 53);
        CHECK(end_before_ringing(track, 0, mark, levels.size()) == 30);
    }

    TEST_CASE("a ringing longer than the reference window is measured from the last vowel's peak") {
        std::vector<float> levels(30, -20.0f);  // the last vowel
        // The ringing of a large room, 6 dB under the vowel where the voice stops, falls 0.35 dB a
        // frame with a 1 dB ripple for 0.7 s: the last 0.6 s hold none of the vowel, and their
        // loudest frame, their first, is already ringing.
        for (int k = 0; k < 70; ++k)
            levels.push_back(-26.0f - 0.35f * static_cast<float>(k) + (k % 2 == 0 ? 1.0f : -1.0f));
        const FeatureTrack track = track_of(levels);
        const std::size_t mark = end_before_tail(track, 0, levels.size());
        // 18 dB under the vowel, not under the ringing's first frame in the window (91).
        CHECK(mark == 67);
        CHECK(end_before_ringing(track, 0, mark, levels.size()) == 30);
    }

    TEST_CASE("a fade that passes under the ringing's line drawn back keeps the mark") {
        // The last vowel fades 1 dB a frame to 20 dB under the voice, while what the louder frames
        // before it left rings on over it, falling 0.3 dB a frame: followed back, the level leaves the
        // line under it, and where in the fade the voice stopped cannot be told.
        std::vector<float> levels(30, -20.0f);
        for (int k = 1; k <= 20; ++k) levels.push_back(-20.0f - 1.0f * static_cast<float>(k));
        for (int k = 0; k < 40; ++k) levels.push_back(-34.0f - 0.3f * static_cast<float>(k));
        const FeatureTrack track = track_of(levels);
        const std::size_t mark = end_before_tail(track, 0, levels.size());
        REQUIRE(mark > 50);
        CHECK(end_before_ringing(track, 0, mark, levels.size()) == mark);
    }

    TEST_CASE("a quiet last syllable after a closure is kept, though far under the one before") {
        std::vector<float> levels(30, -20.0f);                      // a loud syllable
        levels.insert(levels.end(), 5, -70.0f);                      // a stop's closure
        levels.insert(levels.end(), 20, -42.0f);                     // a quiet third tone, 22 dB under
        const FeatureTrack track = track_of(levels);
        CHECK(end_before_tail(track, 0, levels.size()) == levels.size());
    }
}

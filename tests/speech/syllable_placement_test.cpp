// Where a voiced join starts (issue 12): a syllable whose initial is voiced (m n l r, none) runs on
// from the vowel before; the path's boundary lies where the two sounds fit alike, the middle of
// the transition, and the syllable starts where the transition does.
#include <doctest/doctest.h>

#include <cstddef>

#include "speech/hsmm.hpp"
#include "speech/syllable_placement.hpp"

using namespace talkface::detail;

namespace {

// Emissions where every class scores -20 but a and i: a scores 0 and i `rise` (a frame's rise,
// from a towards i).
void add_frame(EmissionScores& emissions, float rise) {
    for (int c = 0; c < kPhoneClassCount; ++c)
        emissions.values.push_back(c == kVowelA ? 0.0f : c == kVowelI ? rise : -20.0f);
    ++emissions.frame_count;
}

}  // namespace

TEST_SUITE("speech") {
    TEST_CASE("a voiced join starts where the sound begins to turn, not where the two sounds fit alike") {
        // 啊衣: 16 frames of a, 8 of a linear turn to i (frames 16-23, the rise from -10 to +10,
        // crossing 0 between frames 19 and 20), 16 of i. The path's boundary is at the crossing.
        EmissionScores emissions;
        for (int t = 0; t < 16; ++t) add_frame(emissions, -10.0f);
        for (int t = 0; t < 8; ++t) add_frame(emissions, -10.0f + 20.0f * (static_cast<float>(t) + 0.5f) / 8.0f);
        for (int t = 0; t < 16; ++t) add_frame(emissions, 10.0f);
        const StateSegment before{0, 0, 20}, first{1, 20, 40};
        const std::size_t start = voiced_join_start(before, kVowelA, first, kVowelI, emissions);
        CAPTURE(start);
        // A quarter of the way up the turn (frame 18): 20 ms after its first frame, 20 ms before the crossing.
        CHECK(start >= 16);
        CHECK(start <= 18);
    }

    TEST_CASE("a voiced join the classes do not bear out stays where the path put it") {
        // The frames after the boundary fit a no worse than those before it (the duration priors
        // put it there): there is no turn towards i to follow back.
        EmissionScores emissions;
        for (int t = 0; t < 20; ++t) add_frame(emissions, 5.0f);
        for (int t = 0; t < 20; ++t) add_frame(emissions, -5.0f);
        const StateSegment before{0, 0, 20}, first{1, 20, 40};
        CHECK(voiced_join_start(before, kVowelA, first, kVowelI, emissions) == 20);
    }
}

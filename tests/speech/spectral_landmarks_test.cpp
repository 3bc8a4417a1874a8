#include <doctest/doctest.h>

#include <vector>

#include "speech/acoustic_model.hpp"
#include "speech/spectral_landmarks.hpp"

using namespace talkface::detail;

TEST_SUITE("spectral landmarks") {
    TEST_CASE("the bonus peaks where the cepstra jump and is never a loss") {
        // 60 frames whose deltas are small and steady but for a jump over frames 29-30.
        constexpr std::size_t frames = 60;
        std::vector<float> observations(frames * kObservationCount, 0.0f);
        for (std::size_t t = 0; t < frames; ++t) {
            const float delta = t == 29 || t == 30 ? 0.4f : 0.1f + 0.01f * static_cast<float>(t % 3);
            for (int c = 0; c < 12; ++c) observations[t * kObservationCount + kDeltaCepstrum1 + c] = delta;
        }
        EmissionScores scores;
        set_boundary_bonus(observations.data(), frames, scores);
        REQUIRE(scores.boundary.size() == frames + 1);
        std::size_t best = 0;
        for (std::size_t t = 0; t <= frames; ++t) {
            CAPTURE(t);
            CHECK(scores.boundary[t] >= 0.0f);
            if (scores.boundary[t] > scores.boundary[best]) best = t;
        }
        CHECK(best == 30);
        CHECK(scores.boundary[30] > 2.0f);
        CHECK(scores.boundary[10] < 0.2f);
    }
}

#include <doctest/doctest.h>

#include <cmath>
#include <vector>

#include "common/chain_state.hpp"
#include "speech/duration_tables.hpp"

using namespace talkface::detail;

namespace {

using talkface::test::chain_state;

// The prior's score of d frames against its median's, as the search weighs it: a log-normal's log
// density (less the log of its spread, shared by every duration).
double prior_score(const PhoneState& state, double frames) {
    auto log_density = [&](double d) {
        const double z = (std::log(d) - std::log(state.median_frames)) / state.log_sigma;
        return -std::log(d) - 0.5 * z * z;
    };
    return state.duration_weight * (log_density(frames) - log_density(state.median_frames));
}

TEST_SUITE("duration_tables") {
    TEST_CASE("a state's scores run from its longest duration down, as its prior weighs each") {
        DurationTables tables;
        PhoneState vowel = chain_state(kVowelA, StateRole::final, 0, 8.0, 30, false);
        vowel.min_frames = 3;
        const std::vector<float>& scores = tables.of(vowel, 500);
        REQUIRE(scores.size() == 28);
        CHECK(scores.front() == doctest::Approx(prior_score(vowel, 30.0)).epsilon(1e-6));
        CHECK(scores[30 - 8] == doctest::Approx(0.0).epsilon(1e-6));
        CHECK(scores.back() == doctest::Approx(prior_score(vowel, 3.0)).epsilon(1e-6));
        // A search shorter than the longest duration scores only the durations it holds, alike.
        const std::vector<float> cut = tables.of(vowel, 12);
        REQUIRE(cut.size() == 10);
        for (std::size_t k = 0; k < cut.size(); ++k) CHECK(cut[k] == scores[30 - 12 + k]);
    }

    TEST_CASE("a state searched again reads the table made the first time, and one that differs gets its own") {
        DurationTables tables;
        PhoneState vowel = chain_state(kVowelA, StateRole::final, 0, 8.0, 30, false);
        const std::vector<float>* first = &tables.of(vowel, 400);
        const std::vector<float> made = *first;
        PhoneState same = chain_state(kVowelE, StateRole::final, 3, 8.0, 30, false);
        CHECK(&tables.of(same, 400) == first);
        // A window's pace scales its vowels: the scaled state's scores are its own.
        PhoneState scaled = vowel;
        scaled.median_frames = 8.0 * 1.25;
        const std::vector<float>& other = tables.of(scaled, 400);
        CHECK(&other != first);
        CHECK(other != made);
        CHECK(*first == made);
    }

    TEST_CASE("an edge silence scores every duration alike, its penalties apart") {
        DurationTables tables;
        PhoneState edge = chain_state(kSilence, StateRole::edge_silence, 0, 1.0, 110, true);
        edge.frame_log_penalty = -0.5;
        const std::vector<float>& scores = tables.of(edge, 50);
        REQUIRE(scores.size() == 50);
        for (std::size_t k = 0; k < scores.size(); ++k)
            CHECK(scores[k] == doctest::Approx(-0.5 * static_cast<double>(50 - k)));
    }
}

}  // namespace

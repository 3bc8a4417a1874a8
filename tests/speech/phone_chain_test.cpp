// The phone chain's pauses (issue 12): in noise a weak fricative's start sounds like the noise of a
// pause, and a pause the text does not mark must not take it.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <initializer_list>
#include <utility>
#include <vector>

#include "speech/hsmm.hpp"
#include "speech/phone_chain.hpp"
#include "talkface/transcript.hpp"

using namespace talkface;
using namespace talkface::detail;

namespace {

// Emissions of planted stretches: each frame favours its class by `margin` over `runner_up`
// (every other class 5 below the best).
struct Planted {
    EmissionScores emissions;
    void add(std::size_t frames, PhoneClass best, PhoneClass runner_up = kSilence, float margin = 5.0f) {
        for (std::size_t t = 0; t < frames; ++t) {
            for (int c = 0; c < kPhoneClassCount; ++c)
                emissions.values.push_back(c == best ? 0.0f : c == runner_up ? -margin : -5.0f);
            ++emissions.frame_count;
        }
    }
    // Stretches one after another, each (frames, its class) as add() plants it.
    void add_runs(std::initializer_list<std::pair<std::size_t, PhoneClass>> runs) {
        for (const auto& [frames, best] : runs) add(frames, best);
    }
};

// The syllables of `text`'s transcript as build_phone_chain takes them; `transcript` keeps them.
std::vector<const Syllable*> syllables_of(const char* text, Timeline& transcript) {
    transcript = read_transcript(text);
    std::vector<const Syllable*> syllables;
    for (const auto& syllable : transcript.syllables) syllables.push_back(&syllable);
    return syllables;
}

// Where the path starts the first state of syllable `syllable`.
std::size_t syllable_start(const std::vector<PhoneState>& states, const std::vector<StateSegment>& path, std::size_t syllable) {
    for (const auto& segment : path)
        if (states[segment.state].syllable == syllable && !is_pause(states[segment.state].role)) return segment.first_frame;
    FAIL("syllable " << syllable << " not on the path");
    return 0;
}

}  // namespace

TEST_SUITE("speech") {
    TEST_CASE("a fricative's start that sounds like a pause's noise is the fricative's, a long silence a pause") {
        // 他是: t a, then sh and the apical vowel.
        const Timeline transcript = read_transcript("他是。");
        std::vector<const Syllable*> syllables;
        for (const auto& syllable : transcript.syllables) syllables.push_back(&syllable);
        REQUIRE(syllables.size() == 2);
        Planted planted;
        planted.add(20, kSilence);
        planted.add(2, kBurst);
        planted.add(6, kAspiration);
        planted.add(16, kVowelA);
        std::size_t true_start = 0;
        SUBCASE("the first 60 ms of sh under noise: silence fits them better than frication") {
            true_start = planted.emissions.frame_count;
            planted.add(6, kSilence, kSibilant, 2.0f);
            planted.add(5, kSibilant);
        }
        SUBCASE("a stop of 0.3 s before sh, which is heard whole") {
            planted.add(30, kSilence);
            true_start = planted.emissions.frame_count;
            planted.add(11, kSibilant);
        }
        planted.add(16, kVowelApical);
        planted.add(20, kSilence);
        const std::size_t frames = planted.emissions.frame_count;
        const std::vector<PhoneState> states = build_phone_chain(syllables, frames, frames - 40);
        ViterbiWorkspace workspace;
        const auto path = viterbi_align(states, planted.emissions, workspace);
        REQUIRE_FALSE(path.empty());
        CHECK(syllable_start(states, path, 1) == true_start);
    }
}

TEST_SUITE("speech") {
    TEST_CASE("kept to the text's marks, a chain gives no long pause to a place its text does not mark") {
        // 啊衣，啊衣。 said with no stop at the comma and 0.4 s of silence inside its second phrase.
        Planted planted;
        planted.add(20, kSilence);
        planted.add(16, kVowelA);
        planted.add(16, kVowelI);
        planted.add(16, kVowelA);
        planted.add(40, kSilence);
        planted.add(16, kVowelI);
        planted.add(20, kSilence);
        const std::size_t frames = planted.emissions.frame_count;
        auto longest_unmarked_pause = [&](const char* text, bool is_kept_to_marks) {
            const Timeline transcript = read_transcript(text);
            std::vector<const Syllable*> syllables;
            for (const auto& syllable : transcript.syllables) syllables.push_back(&syllable);
            std::vector<PhoneState> states = build_phone_chain(syllables, frames, frames - 80);
            if (is_kept_to_marks) keep_pauses_to_marks(states);
            ViterbiWorkspace workspace;
            const auto path = viterbi_align(states, planted.emissions, workspace);
            REQUIRE_FALSE(path.empty());
            std::size_t longest = 0;
            for (const auto& segment : path)
                if (states[segment.state].role == StateRole::short_pause)
                    longest = std::max(longest, segment.end_frame - segment.first_frame);
            return longest;
        };
        // The audio's own path takes the silence where it is; kept to the marks it may not.
        CHECK(longest_unmarked_pause("啊衣，啊衣。", false) >= 35);
        CHECK(longest_unmarked_pause("啊衣，啊衣。", true) <= kMaxUnmarkedPauseFrames);
        // A text that marks no pause (no comma, one sentence) keeps its speaker's pauses.
        CHECK(longest_unmarked_pause("啊衣啊衣。", true) >= 35);
    }
}

TEST_SUITE("speech") {
    TEST_CASE("a stop after a nasal may release from the nasal's closure, with no silence between, where it is let") {
        // 天都在: the n of 天 runs straight into the burst of 都 (the tongue already closed at the
        // ridge), while 在's z has a closure of its own.
        Timeline transcript;
        const std::vector<const Syllable*> syllables = syllables_of("天都在。", transcript);
        REQUIRE(syllables.size() == 3);
        Planted planted;
        planted.add_runs({{20, kSilence}, {2, kBurst}, {6, kAspiration}, {4, kVowelI}, {14, kVowelA}, {6, kNasal}});
        const std::size_t burst_of_du = planted.emissions.frame_count;
        planted.add_runs({{2, kBurst}, {14, kVowelU}, {5, kSilence}, {5, kSibilant}, {14, kVowelA}, {6, kVowelI}, {20, kSilence}});
        const std::size_t frames = planted.emissions.frame_count;
        auto start_of_du = [&](bool is_released) {
            std::vector<PhoneState> states = build_phone_chain(syllables, frames, frames - 40);
            if (is_released) let_closures_after_nasals_be_skipped(states);
            ViterbiWorkspace workspace;
            const auto path = viterbi_align(states, planted.emissions, workspace);
            REQUIRE_FALSE(path.empty());
            return syllable_start(states, path, 1);
        };
        // Made to pass a closure, the path takes one out of the nasal's frames; let release, it
        // starts 都 at its burst.
        CHECK(start_of_du(false) < burst_of_du);
        CHECK(start_of_du(true) == burst_of_du);
    }

    TEST_CASE("only a closure right after a nasal may be skipped") {
        Timeline transcript;
        const std::vector<const Syllable*> syllables = syllables_of("他都天在三。", transcript);
        std::vector<PhoneState> states = build_phone_chain(syllables, 200, 160);
        let_closures_after_nasals_be_skipped(states);
        std::vector<std::size_t> skippable, unskippable;
        for (const auto& state : states) {
            if (state.role != StateRole::closure) continue;
            (std::isfinite(state.skip_log_penalty) ? skippable : unskippable).push_back(state.syllable);
        }
        // 都 after 他's a and 天 after 都's u keep their closures; 在 after 天's n may release from it.
        CHECK(skippable == std::vector<std::size_t>{3});
        CHECK(unskippable == std::vector<std::size_t>{1, 2});
    }
}

// The phone chain's pauses (issue 12): in noise a weak fricative's start sounds like the noise of a
// pause, and a pause the text does not mark must not take it.
#include <doctest/doctest.h>

#include <algorithm>
#include <cstddef>
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
};

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

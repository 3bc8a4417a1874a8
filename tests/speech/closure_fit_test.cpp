// text_fit_gap (issues 12 and 13): at a fast pace a stop after a vowel is often said with no
// silence before its burst, and the frame the path must give its closure sounds like the vowel
// it follows; a short line dense in stops (我就带了两块钱, 12点整开抢: four closures in six or
// seven syllables) was refused as the wrong text on those frames alone (bench/ espeak-ng fast).
#include <doctest/doctest.h>

#include <cmath>
#include <cstddef>
#include <vector>

#include "common/chain_state.hpp"
#include "common/speech_clips.hpp"
#include "speech/alignment_checks.hpp"
#include "speech/text_fit.hpp"
#include "talkface/speech_aligner.hpp"
#include "talkface/transcript.hpp"

using namespace talkface;
using namespace talkface::detail;

namespace {

using talkface::test::chain_state;

// What closure_spoken_through's run-on frames lose to the vowel before them: a speaker who speaks
// through every closure so.
constexpr double kRunOnOfSpeaker = 8.0;

// A vowel of 20 frames run on through 3 frames where the text has a stop's closure, the stop's
// burst (2 frames) and another vowel (20 frames): each frame favours its own sound by 4 over the
// others, and silence fits the run-on frames worst of all.
EmissionScores closure_spoken_through() {
    EmissionScores scores;
    const PhoneClass said[] = {kVowelA, kVowelA, kBurst, kVowelI};
    const std::size_t frames[] = {20, 3, 2, 20};
    for (std::size_t part = 0; part < 4; ++part)
        for (std::size_t t = 0; t < frames[part]; ++t, ++scores.frame_count)
            for (int c = 0; c < kPhoneClassCount; ++c)
                scores.values.push_back(c == said[part] ? -1.0f : c == kSilence ? -9.0f : -5.0f);
    return scores;
}

// A chain whose path gives each of `text`'s states its part of closure_spoken_through's frames.
struct ForcedText {
    SentenceChain chain;
    std::vector<StateSegment> path;
};

ForcedText forced(PhoneClass first_vowel) {
    ForcedText text;
    text.chain.states = {chain_state(first_vowel, StateRole::final, 0, 20.0, 60, false),
                         chain_state(kSilence, StateRole::closure, 1, 5.0, 20, false),
                         chain_state(kBurst, StateRole::initial, 1, 2.0, 6, false),
                         chain_state(kVowelI, StateRole::final, 1, 20.0, 60, false)};
    text.path = {{0, 0, 20}, {1, 20, 23}, {2, 23, 25}, {3, 25, 45}};
    return text;
}

}  // namespace

TEST_SUITE("speech") {
    TEST_CASE("a stop's closure spoken through with no silence is no evidence against the text") {
        const EmissionScores scores = closure_spoken_through();
        // The right text: its closure's frames sound like the vowel before it, as the text allows.
        const ForcedText right = forced(kVowelA);
        CHECK(text_fit_gap(right.chain, right.path, scores, kRunOnOfSpeaker) <= 0.0);
        // A wrong vowel before the stop still gaps far over check_text_fit's limit.
        const ForcedText wrong = forced(kVowelU);
        CHECK(text_fit_gap(wrong.chain, wrong.path, scores, kRunOnOfSpeaker) > 1.0);
        // Where the closure must be silent (a file of one or two sentences, a speaker who keeps
        // closures), the run-on frames gap.
        CHECK(text_fit_gap(right.chain, right.path, scores, 0.0) > kMaxTextFitGap);
        // A speaker whose closures run on by less is forgiven only that much.
        CHECK(text_fit_gap(right.chain, right.path, scores, kRunOnOfSpeaker / 4) >
              text_fit_gap(right.chain, right.path, scores, kRunOnOfSpeaker));
    }

    TEST_CASE("a stop's closure in silence scores as silence") {
        EmissionScores scores = closure_spoken_through();
        // The closure's frames silent: a vowel's model fits them no better than silence's.
        for (std::size_t t = 20; t < 23; ++t)
            for (int c = 0; c < kPhoneClassCount; ++c)
                scores.values[t * kPhoneClassCount + static_cast<std::size_t>(c)] =
                    c == kSilence ? -1.0f : -9.0f;
        const ForcedText right = forced(kVowelA);
        CHECK(text_fit_gap(right.chain, right.path, scores, kRunOnOfSpeaker) <= 0.0);
    }

    TEST_CASE("a recording's closures run on as far as its typical closure frame does") {
        const EmissionScores scores = closure_spoken_through();
        std::vector<double> losses;
        const ForcedText right = forced(kVowelA);
        add_closure_run_on(right.chain, right.path, scores, losses);
        // Each of the three closure frames sounds like the vowel before it by 8 over silence.
        CHECK(losses == std::vector<double>{kRunOnOfSpeaker, kRunOnOfSpeaker, kRunOnOfSpeaker});
        // A speaker who keeps most closures silent: the closures of one sentence run on do not
        // move the typical one, and none is forgiven.
        CHECK(typical_closure_run_on({0.0, 0.0, 0.0, 0.5, kRunOnOfSpeaker, kRunOnOfSpeaker}) == 0.5);
        CHECK(typical_closure_run_on({}) == 0.0);
    }

    TEST_CASE("a passage of dialogue said fast aligns its short line dense in stops") {
        // espeak-ng says five chat lines at 240-300 words a minute (tests/data/speech/make_clips.sh);
        // the last, 这根雪糕才5毛钱？, has four stops after speech in eight syllables and gapped 0.25
        // with its closures scored as silence: refused as the wrong text.
        const Timeline aligned = SpeechAligner().align_file(
            test::clip_path("dialogue_fast.flac"), load_transcript(test::clip_path("dialogue_fast.txt")));
        const std::vector<double> truth = test::true_starts("dialogue_fast");
        REQUIRE(aligned.syllables.size() == truth.size());
        for (std::size_t i = 0; i < truth.size(); ++i) {
            CAPTURE(i);
            CHECK(std::fabs(aligned.syllables[i].start_s - truth[i]) < 0.05);
        }
    }
}

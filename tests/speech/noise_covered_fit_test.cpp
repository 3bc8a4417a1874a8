// clear_text_fit_gap and check_text_fit (issue 12): where noise covers part of a sentence's speech,
// the free sounds of text_fit_gap fit the noise there better than any text does, and a right
// sentence said quieter than the others under pink noise was refused as the wrong text
// (bench/ w-fast-pink15 tuning-015, 請把窗戶打開，讓新鮮空氣進來。: 0.15-0.25 per frame).
#include <doctest/doctest.h>

#include <cstddef>
#include <string>
#include <vector>

#include "common/chain_state.hpp"
#include "speech/alignment_checks.hpp"
#include "speech/text_fit.hpp"
#include "talkface/errors.hpp"
#include "talkface/transcript.hpp"

using namespace talkface;
using namespace talkface::detail;

namespace {

using talkface::test::chain_state;

constexpr std::size_t kClearFrames = 30;

// A vowel a of kClearFrames frames clear of the noise, then a vowel i of `covered` frames under
// it: there the noise fits a sibilant and silence in turns, four frames each, 3 better than the
// vowel, and the vowel only 1 better than the rest. Each clear frame favours its own sound by 4.
EmissionScores half_under_noise(std::size_t covered) {
    EmissionScores scores;
    for (std::size_t t = 0; t < kClearFrames + covered; ++t, ++scores.frame_count) {
        const bool is_clear = t < kClearFrames;
        const int noise = (t / 4) % 2 == 0 ? kSibilant : kSilence;
        for (int c = 0; c < kPhoneClassCount; ++c) {
            float score = -6.0f;
            if (is_clear)
                score = c == kVowelA ? -1.0f : -5.0f;
            else if (c == noise)
                score = -2.0f;
            else if (c == kVowelI)
                score = -5.0f;
            scores.values.push_back(score);
        }
    }
    return scores;
}

std::vector<bool> clear_frames(std::size_t covered) {
    std::vector<bool> clear(kClearFrames + covered, false);
    for (std::size_t t = 0; t < kClearFrames; ++t) clear[t] = true;
    return clear;
}

struct ForcedText {
    SentenceChain chain;
    std::vector<StateSegment> path;
};

// A text of two vowels, the first `first_vowel`, forced on half_under_noise's frames.
ForcedText forced(PhoneClass first_vowel, std::size_t covered) {
    ForcedText text;
    text.chain.states = {chain_state(first_vowel, StateRole::final, 0, 30.0, 90, false),
                         chain_state(kVowelI, StateRole::final, 1, 30.0, 90, false)};
    text.path = {{0, 0, kClearFrames}, {1, kClearFrames, kClearFrames + covered}};
    return text;
}

}  // namespace

TEST_SUITE("speech") {
    TEST_CASE("noise over part of a right sentence's speech is no evidence against its text") {
        for (const std::size_t covered : {std::size_t{10}, std::size_t{30}, std::size_t{60}}) {
            CAPTURE(covered);
            const EmissionScores scores = half_under_noise(covered);
            const ForcedText right = forced(kVowelA, covered);
            // On every frame, the right text gaps past check_text_fit's limit, the more the more of
            // its speech the noise covers.
            CHECK(text_fit_gap(right.chain, right.path, scores, 0.0) > kMaxTextFitGap);
            // Over the frames clear of the noise it fits as well as free sounds do, however many
            // the noise covers.
            CHECK(clear_text_fit_gap(right.chain, right.path, scores, clear_frames(covered), 0.0) <= 0.0);
            CHECK(
                noise_covered_share(right.chain, right.path, clear_frames(covered)) ==
                doctest::Approx(static_cast<double>(covered) / static_cast<double>(kClearFrames + covered)));
            // A wrong vowel where the speech is clear still gaps far past the limit.
            const ForcedText wrong = forced(kVowelU, covered);
            CHECK(clear_text_fit_gap(wrong.chain, wrong.path, scores, clear_frames(covered), 0.0) > 1.0);
        }
        // With every frame under the noise, the gap is text_fit_gap's.
        const EmissionScores scores = half_under_noise(30);
        const ForcedText right = forced(kVowelA, 30);
        CHECK(clear_text_fit_gap(right.chain, right.path, scores, std::vector<bool>(60, false), 0.0) ==
              doctest::Approx(text_fit_gap(right.chain, right.path, scores, 0.0)));
    }

    TEST_CASE("check_text_fit judges a far quieter sentence where its speech is clear of the noise") {
        const Timeline transcript =
            read_transcript("今天天气很好。\n我们去公园散步吧。\n医生建议他多喝水。\n电影七点半开始。\n");
        const std::vector<FrameSpan> spans = {{0, 100}, {120, 220}, {240, 340}, {360, 460}};
        std::vector<SentenceMetrics> metrics(4);
        for (auto& sentence : metrics) {
            sentence.fit_gap = sentence.clear_fit_gap = -0.1;
            sentence.noise_covered_share = 0.3;
        }
        // Said quieter than the others, two thirds of it under the noise, over the limit only there:
        // aligned.
        metrics[1].fit_gap = 0.25;
        metrics[1].noise_covered_share = 0.65;
        CHECK_NOTHROW(check_text_fit(metrics, spans, transcript));
        // Over it where its speech is clear too: the wrong text.
        metrics[1].clear_fit_gap = 0.25;
        CHECK_THROWS_AS(check_text_fit(metrics, spans, transcript), AlignmentError);
        metrics[1].clear_fit_gap = -0.1;
        // Every sentence in the same noise: judged over all its frames, as in clear speech.
        for (auto& sentence : metrics) sentence.noise_covered_share = 0.65;
        CHECK_THROWS_AS(check_text_fit(metrics, spans, transcript), AlignmentError);
        // The noise covering less than half of it, however little of the others: the same.
        for (auto& sentence : metrics) sentence.noise_covered_share = 0.05;
        metrics[1].noise_covered_share = 0.45;
        CHECK_THROWS_AS(check_text_fit(metrics, spans, transcript), AlignmentError);
    }
}

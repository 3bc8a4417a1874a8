// A short line refused on weak evidence (issue 13: "it refuses only on strong evidence, which a line
// of a few syllables rarely gives"): the refusal says how far past its limit its measure lay, and
// CheckMode::refuse aligns a line of one sentence under kMinHeldOutSyllables with the finding
// as a warning where that is short of the check's strong bar (bench/README.md, session 44 (short44)).
#include <doctest/doctest.h>

#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "speech/alignment_checks.hpp"
#include "speech/weak_evidence.hpp"
#include "talkface/errors.hpp"
#include "talkface/transcript.hpp"

using namespace talkface;
using namespace talkface::detail;

namespace {

const std::vector<FrameSpan> kSpans = {{0, 148}};

// What the aligner makes of `check`'s refusal of `transcript` in refuse mode: the warning that stands
// for it, or nothing where it stands.
template <typename Check>
std::optional<std::string> weak_finding_of(const Timeline& transcript, Check check) {
    try {
        check();
    } catch (const AlignmentError& refusal) {
        return describe_weak_evidence(refusal, transcript);
    }
    FAIL("the check passed the line");
    return std::nullopt;
}

}  // namespace

TEST_SUITE("speech") {
    TEST_CASE("a short line's own fit a little past its limit is a warning naming the line and how sure") {
        // 我先走。 through a phone's fast codec chain, a right line main refused at 0.14 per frame.
        const Timeline line = read_transcript("我先走。");
        std::vector<SentenceMetrics> metrics(1);
        metrics[0].own_fit_gap = 0.14;
        const auto finding = weak_finding_of(line, [&] { check_own_fit(metrics, kSpans, line); });
        REQUIRE(finding);
        CHECK(finding->rfind("the transcript may not match the audio (aligned anyway", 0) == 0);
        CHECK(finding->find(
                  "weak evidence on a line of 3 syllables, 0.09 past its limit, where 0.1 past refuses") !=
              std::string::npos);
        CHECK(finding->find("sentence 1 (0-1.48 s, \"我先走。\")") != std::string::npos);
        CHECK(finding->find("0.14 per frame better than the text's, at most 0.05") != std::string::npos);

        // Strong evidence on the same line still refuses it.
        metrics[0].own_fit_gap = 0.16;
        CHECK_FALSE(weak_finding_of(line, [&] { check_own_fit(metrics, kSpans, line); }));
    }

    TEST_CASE("a short line's rhythm and typical syllable are weighed, and strong evidence refuses") {
        // 快來幫我啊！ under a gain's lifted babble, a right line main refused at a spread of 2.42.
        const Timeline line = read_transcript("快來幫我啊！");
        std::vector<SentenceMetrics> metrics(1);
        metrics[0].length_spread = std::log(2.42);
        CHECK(weak_finding_of(line, [&] { check_syllable_lengths(metrics, kSpans, line); }));
        metrics[0].length_spread = std::log(2.6);
        CHECK_FALSE(weak_finding_of(line, [&] { check_syllable_lengths(metrics, kSpans, line); }));

        metrics[0].order_margin = 0.16;
        metrics[0].held_out_median = 0.37;
        CHECK(weak_finding_of(line, [&] { check_typical_syllable_off_noise(metrics, kSpans, line); }));
        metrics[0].held_out_median = 0.45;
        CHECK_FALSE(weak_finding_of(line, [&] { check_typical_syllable_off_noise(metrics, kSpans, line); }));
    }

    TEST_CASE(
        "weak evidence refuses a line of 6 syllables, a sentence of a passage, and any other check's "
        "finding") {
        // From 6 syllables on, texts that lack their last words are refused on evidence as weak.
        const Timeline six = read_transcript("明天早上見吧。");
        REQUIRE(six.syllables.size() == 6);
        std::vector<SentenceMetrics> metrics(1);
        metrics[0].order_margin = 0.16;
        metrics[0].held_out_median = 0.37;
        metrics[0].held_out_end_median = 0.2;
        std::vector<std::string> warnings;
        CHECK_FALSE(weak_finding_of(six, [&] { check_held_out_fit(metrics, kSpans, six, warnings); }));

        const Timeline two = read_transcript("我先走。明天見。");
        std::vector<SentenceMetrics> both(2);
        both[0].own_fit_gap = 0.12;
        const std::vector<FrameSpan> spans = {{0, 148}, {200, 300}};
        CHECK_FALSE(weak_finding_of(two, [&] { check_own_fit(both, spans, two); }));

        // The text fitting worse than free sounds was never a right short line's finding: it stands.
        const Timeline line = read_transcript("收到。");
        metrics[0].fit_gap = 0.2;
        CHECK_FALSE(weak_finding_of(line, [&] { check_text_fit(metrics, kSpans, line); }));
    }
}

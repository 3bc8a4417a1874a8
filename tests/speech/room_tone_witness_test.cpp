// check_text_fit in a room (issue 12): a right sentence whose speech rings into the next gaps over
// the limit as a wrong one does (bench/ v-fast-reverb tuning-011, 0.155); its pitch, which the room
// smears less than the spectrum, is the second witness that lets it through.
#include <doctest/doctest.h>

#include <cstddef>
#include <limits>
#include <vector>

#include "speech/alignment_checks.hpp"
#include "talkface/errors.hpp"
#include "talkface/transcript.hpp"

using namespace talkface;
using namespace talkface::detail;

TEST_SUITE("speech") {
    TEST_CASE("a sentence over the text fit gap's limit passes only where its pitch says its text's tones") {
        const Timeline transcript = read_transcript("今天很好。我们走吧。他们来了。天气很冷。明天再见。");
        REQUIRE(transcript.sentences.size() == 5);
        const std::vector<FrameSpan> spans = {{0, 100}, {150, 250}, {300, 400}, {450, 550}, {600, 700}};
        std::vector<SentenceMetrics> metrics(5);
        for (auto& sentence : metrics) sentence.fit_gap = -0.03;
        metrics[3].fit_gap = 0.155;
        // Not measured (a dry recording, a file of one or two sentences): the gap decides.
        CHECK_THROWS_WITH_AS(check_text_fit(metrics, spans, transcript),
                             doctest::Contains("sentence 4 (4.5-5.5 s"), AlignmentError);
        // Its syllables' pitch fits another tone as well as their own: no witness.
        metrics[3].tone_gap = 0.4;
        CHECK_THROWS_AS(check_text_fit(metrics, spans, transcript), AlignmentError);
        metrics[3].tone_gap = -0.6;
        CHECK_THROWS_AS(check_text_fit(metrics, spans, transcript), AlignmentError);
        // As much as a person's wrong sentence in a room had (bench/ h-reverb tuning-009, two swapped).
        metrics[3].tone_gap = -1.4;
        CHECK_THROWS_AS(check_text_fit(metrics, spans, transcript), AlignmentError);
        // Each syllable's own tone fits its pitch far better than any other.
        metrics[3].tone_gap = -3.2;
        CHECK_NOTHROW(check_text_fit(metrics, spans, transcript));
        // The witness speaks for its own sentence only.
        metrics[1].fit_gap = 0.2;
        CHECK_THROWS_WITH_AS(check_text_fit(metrics, spans, transcript),
                             doctest::Contains("sentence 2 (1.5-2.5 s"), AlignmentError);
    }
}

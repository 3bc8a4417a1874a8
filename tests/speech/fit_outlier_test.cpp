// check_fit (issue 13): a sentence that fits the models of its sounds far worse than the passage's
// others is the wrong text only if free sounds fit it better than its text; a right sentence said
// twice as fast as its neighbours, under a hum or room noise, fits its sounds as badly but its text
// as well as free sounds (bench/ r-hum and r-longsil tuning-018 were refused).
#include <doctest/doctest.h>

#include <cstddef>
#include <vector>

#include "speech/alignment_checks.hpp"
#include "talkface/errors.hpp"
#include "talkface/transcript.hpp"

using namespace talkface;
using namespace talkface::detail;

TEST_SUITE("speech") {
    TEST_CASE("a sentence that fits its sounds far worse than the others is the wrong text only if free sounds fit it better") {
        // Five sentences; the second fits 1.6 per frame worse than the rest (a right one said twice as
        // fast as the others, under a hum).
        const Timeline transcript = read_transcript("今天很好。我们走吧。他们来了。天气很冷。明天再见。");
        REQUIRE(transcript.sentences.size() == 5);
        const std::vector<FrameSpan> spans = {{0, 100}, {150, 250}, {300, 400}, {450, 550}, {600, 700}};
        std::vector<SentenceMetrics> metrics(5);
        for (std::size_t k = 0; k < 5; ++k) {
            metrics[k].fit = -10.0 - 0.05 * static_cast<double>(k);
            metrics[k].fit_gap = -0.15;
        }
        metrics[1].fit = -11.7;
        metrics[1].fit_gap = -0.05;  // its text fits it as well as free sounds do: its audio is to blame
        CHECK_NOTHROW(check_fit(metrics, spans, transcript));
        metrics[1].fit_gap = 0.05;
        CHECK_THROWS_WITH_AS(check_fit(metrics, spans, transcript), doctest::Contains("sentence 2 (1.5-2.5 s"), AlignmentError);
    }
}

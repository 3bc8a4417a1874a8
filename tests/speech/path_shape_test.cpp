// A refusal read off a path's shape (issue 13): a short line's syllables spread past one voice's
// rhythm, or its typical held-out syllable past its order margin, on a cut whose span holds the
// noise around the voice, is a PathShapeRefusal, which the line's own reading may answer where its
// order margin vouches for the text (bench/README.md, session 39 (short7)); the other refusals are
// not.
#include <doctest/doctest.h>

#include <cstddef>
#include <limits>
#include <string>
#include <vector>

#include "speech/alignment_checks.hpp"
#include "talkface/errors.hpp"
#include "talkface/transcript.hpp"

using namespace talkface;
using namespace talkface::detail;

TEST_SUITE("speech") {
    TEST_CASE("a line refused for its path's shape is a refusal its own reading may answer") {
        // 我們去2樓看看吧 through a phone's fast codec chain, on its cut: 我們去 drawn over the hiss
        // before the voice, the typical syllable 1.07 against a margin of 0.45, the spread 1.91.
        const Timeline transcript = read_transcript("我們去2樓看看吧。");
        const std::vector<FrameSpan> spans = {{0, 152}};
        std::vector<SentenceMetrics> metrics(1);
        metrics[0].order_margin = 0.45;
        metrics[0].held_out_median = 1.07;
        metrics[0].held_out_end_median = 0.2;
        std::vector<std::string> warnings;
        CHECK_THROWS_WITH_AS(check_held_out_fit(metrics, spans, transcript, warnings),
                             doctest::Contains("other sounds fit its typical syllable 1.07"),
                             PathShapeRefusal);
        metrics[0].length_spread = 0.88;
        CHECK_THROWS_WITH_AS(check_syllable_lengths(metrics, spans, transcript),
                             doctest::Contains("squeezed and drawn out"), PathShapeRefusal);
        // A text that lacks its last words is no path's shape: its own reading does not answer it.
        metrics[0].held_out_median = 0.2;
        metrics[0].held_out_end_median = 0.6;
        try {
            check_held_out_fit(metrics, spans, transcript, warnings);
            FAIL("the second half's typical syllable should refuse");
        } catch (const PathShapeRefusal&) {
            FAIL("a text short of its last words is not a path's shape");
        } catch (const AlignmentError& error) {
            CHECK(std::string(error.what()).find("the typical syllable of its second half 0.6") !=
                  std::string::npos);
        }
    }

    TEST_CASE("a line's own reading vouches for its text only with a right text's order margin") {
        std::vector<SentenceMetrics> metrics(2);
        // On the line alone the right 我們去2樓看看吧 gains 0.58 over its halves swapped; the wrong
        // texts whose cut a path's shape refused reached 0.27-0.49 there.
        metrics[0].order_margin = 0.58;
        CHECK(is_vouched_by_order(metrics));
        metrics[0].order_margin = 0.49;
        CHECK_FALSE(is_vouched_by_order(metrics));
        // A sentence with no margin measured (no speech of its own) neither vouches nor denies.
        metrics[0].order_margin = std::numeric_limits<double>::quiet_NaN();
        CHECK_FALSE(is_vouched_by_order(metrics));
        metrics[1].order_margin = 1.01;
        CHECK(is_vouched_by_order(metrics));
    }
}

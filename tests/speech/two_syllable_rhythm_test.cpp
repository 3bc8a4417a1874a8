// check_syllable_lengths (issue 13): two syllables' lengths are one ratio, not a rhythm. A light
// particle after its syllable is said 4-6 times shorter (誰啊: 0.3 s and 0.06 s), which spread the
// two as far as a wrong text squeezes a longer line's syllables, and the right line was refused.
#include <doctest/doctest.h>

#include <cstddef>
#include <vector>

#include "speech/alignment_checks.hpp"
#include "talkface/errors.hpp"
#include "talkface/transcript.hpp"

using namespace talkface;
using namespace talkface::detail;

namespace {

// A sentence's metrics whose syllables, from frame 0 on, last `frames` each.
std::vector<SentenceMetrics> spread_of(const std::vector<std::size_t>& frames) {
    std::vector<AlignedStretch> stretches;
    std::size_t first = 0;
    for (std::size_t i = 0; i < frames.size(); ++i) {
        stretches.push_back({first, first + frames[i], false, i});
        first += frames[i];
    }
    std::vector<SentenceMetrics> metrics(1);
    metrics[0].length_spread = syllable_length_spread(stretches);
    return metrics;
}

}  // namespace

TEST_SUITE("speech") {
    TEST_CASE("a line of two syllables is not refused for its syllables' lengths") {
        const std::vector<FrameSpan> spans = {{0, 36}};
        CHECK_NOTHROW(check_syllable_lengths(spread_of({30, 6}), spans, read_transcript("誰啊？")));
        CHECK_NOTHROW(check_syllable_lengths(spread_of({9, 38}), spans, read_transcript("加油！")));
    }

    TEST_CASE("a line of three syllables still is") {
        const std::vector<FrameSpan> spans = {{0, 66}};
        CHECK_THROWS_WITH_AS(
            check_syllable_lengths(spread_of({30, 6, 30}), spans, read_transcript("誰啊誰？")),
            doctest::Contains("rhythm"), AlignmentError);
    }
}

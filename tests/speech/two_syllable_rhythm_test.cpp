// check_syllable_lengths (issue 13): two syllables' lengths are one ratio, not a rhythm. A light
// particle after its syllable is said 4-6 times shorter (誰啊: 0.3 s and 0.06 s), which spread the
// two as far as a wrong text squeezes a longer line's syllables, and the right line was refused.
// Nor, in a line of a few syllables, is a syllable with no initial run on from the voiced end of the
// one before judged alone: a right 慢一點 in noise or a room gets 5-8 frames for its 一 between
// 慢's and 點's 18-41, and the line was refused.
#include <doctest/doctest.h>

#include <cstddef>
#include <vector>

#include "common/chain_state.hpp"
#include "speech/alignment_checks.hpp"
#include "speech/hsmm.hpp"
#include "speech/phone_chain.hpp"
#include "speech/syllable_placement.hpp"
#include "talkface/errors.hpp"
#include "talkface/transcript.hpp"

using namespace talkface;
using namespace talkface::detail;

namespace {

// A sentence's metrics whose syllables, from frame 0 on, last `frames` each; the syllable at
// `joined_on`, if any, runs on from the one before.
std::vector<SentenceMetrics> spread_of(const std::vector<std::size_t>& frames, std::size_t joined_on = 0) {
    std::vector<AlignedStretch> stretches;
    std::size_t first = 0;
    for (std::size_t i = 0; i < frames.size(); ++i) {
        stretches.push_back({first, first + frames[i], false, i, i > 0 && i == joined_on});
        first += frames[i];
    }
    std::vector<SentenceMetrics> metrics(1);
    metrics[0].length_spread = syllable_length_spread(stretches);
    return metrics;
}

struct PathPart {
    PhoneClass phone_class;
    StateRole role;
    std::size_t syllable;
    std::size_t frames;
};

// A sentence's metrics whose path, from frame 0 on, passes `parts` in order.
std::vector<SentenceMetrics> spread_of_path(const std::vector<PathPart>& parts) {
    SentenceChain chain;
    std::vector<StateSegment> path;
    std::size_t frame = 0;
    for (const PathPart& part : parts) {
        chain.states.push_back(talkface::test::chain_state(part.phone_class, part.role, part.syllable,
                                                           static_cast<double>(part.frames), 100, false));
        path.push_back({chain.states.size() - 1, frame, frame + part.frames});
        frame += part.frames;
    }
    chain.syllable_indices = {0, 1, 2};
    chain.speech = chain.searched = chain.limit = {0, frame};
    std::vector<SentenceMetrics> metrics(1);
    metrics[0].length_spread = syllable_length_spread(stretches_of(chain, path));
    return metrics;
}

// 慢一點 with 一 (yi1: its final alone) `between` 慢 and 點: 慢 28 frames, 一 6, 點 35.
std::vector<SentenceMetrics> light_yi(const std::vector<PathPart>& between) {
    std::vector<PathPart> parts = {{kSilence, StateRole::edge_silence, 0, 10},
                                   {kNasal, StateRole::initial, 0, 6},
                                   {kVowelA, StateRole::final, 0, 16},
                                   {kNasal, StateRole::final, 0, 6}};
    parts.insert(parts.end(), between.begin(), between.end());
    parts.insert(parts.end(), {{kSilence, StateRole::closure, 2, 3},
                               {kBurst, StateRole::initial, 2, 2},
                               {kVowelA, StateRole::final, 2, 30},
                               {kSilence, StateRole::edge_silence, 2, 10}});
    return spread_of_path(parts);
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

    TEST_CASE("a syllable with no initial run on from the voiced sound before counts with it") {
        const std::vector<FrameSpan> spans = {{10, 79}};
        const Timeline line = read_transcript("慢一點。");
        CHECK_NOTHROW(check_syllable_lengths(light_yi({{kVowelI, StateRole::final, 1, 6}}), spans, line));
        CHECK_THROWS_WITH_AS(check_syllable_lengths(light_yi({{kSilence, StateRole::short_pause, 0, 4},
                                                              {kVowelI, StateRole::final, 1, 6}}),
                                                    spans, line),
                             doctest::Contains("rhythm"), AlignmentError);
        CHECK_THROWS_WITH_AS(check_syllable_lengths(light_yi({{kBurst, StateRole::initial, 1, 2},
                                                              {kVowelI, StateRole::final, 1, 4}}),
                                                    spans, line),
                             doctest::Contains("rhythm"), AlignmentError);
    }

    TEST_CASE("only a short line counts a joined syllable with the one before") {
        const std::vector<FrameSpan> spans = {{0, 160}};
        CHECK_NOTHROW(
            check_syllable_lengths(spread_of({28, 4, 35, 30}, 1), spans, read_transcript("慢一點吧。")));
        CHECK_THROWS_WITH_AS(check_syllable_lengths(spread_of({28, 4, 35, 30, 30, 30}, 1), spans,
                                                    read_transcript("慢一點吧慢走。")),
                             doctest::Contains("rhythm"), AlignmentError);
    }

    TEST_CASE("a short line is refused only where both readings of a joined syllable spread too far") {
        const std::vector<FrameSpan> spans = {{0, 82}};
        // Alone 12 / 30 / 28 / 12 spread by a factor of 1.55; 同 and 意 as one length, 12 / 58 / 12, by 2.10.
        CHECK_NOTHROW(
            check_syllable_lengths(spread_of({12, 30, 28, 12}, 2), spans, read_transcript("我同意了。")));
    }
}

// A line's syllables kept on its cut to the voice its own reading finds (issue 13, own_reading_bound.hpp):
// the edge pauses hold the noise outside the bound, the order margin's rival keeps those frames where
// they are, and the path so held is judged by its typical syllable whatever its length
// (bench/README.md, session 40 (short8)); only a short line alone in its own reading is so held
// (session 41 (short9)).
#include <doctest/doctest.h>

#include <cmath>
#include <string>
#include <vector>

#include "common/level_track.hpp"
#include "speech/alignment_checks.hpp"
#include "speech/hsmm.hpp"
#include "speech/own_reading_bound.hpp"
#include "speech/sentence_chains.hpp"
#include "speech/sentence_cutter.hpp"
#include "speech/text_fit.hpp"
#include "talkface/errors.hpp"
#include "talkface/transcript.hpp"

using namespace talkface;
using namespace talkface::detail;
using talkface::test::track_of;

namespace {

// One line of three syllables: 30 frames at the floor, 60 of voice (its cut span), 30 at the floor.
struct Line {
    FeatureTrack track = track_of([] {
        std::vector<float> levels(30, -70.0f);
        levels.insert(levels.end(), 60, -20.0f);
        levels.insert(levels.end(), 30, -70.0f);
        return levels;
    }());
    Timeline transcript = read_transcript("我先走。");
    SentenceCut cut{{{30, 90}}, {false}, false, {}, {}};
};

// Scores of `frames` frames where the frames before `voice_first` and from `voice_end` on sound like
// the noise a gain lifted (any speech class fits them as well as the voice), and silence fits no
// frame well: a path free to do so lays its edge syllables on that noise.
EmissionScores lifted_noise_scores(std::size_t frames, std::size_t voice_first, std::size_t voice_end) {
    EmissionScores scores;
    scores.frame_count = frames;
    scores.values.assign(frames * kPhoneClassCount, -1.0f);
    for (std::size_t t = 0; t < frames; ++t) {
        const bool is_noise = t < voice_first || t >= voice_end;
        scores.values[t * kPhoneClassCount + kSilence] = is_noise ? -1.5f : -6.0f;
    }
    return scores;
}

// The first frame of the first syllable state on `path`, and one past the last one's last.
FrameSpan syllables_on(const SentenceChain& chain, const std::vector<StateSegment>& path) {
    FrameSpan held{0, 0};
    bool is_first = true;
    for (const StateSegment& segment : path) {
        if (!is_syllable_state(chain.states[segment.state])) continue;
        if (is_first) held.first_frame = segment.first_frame;
        is_first = false;
        held.end_frame = segment.end_frame;
    }
    return held;
}

// `peaks` voiced peaks of the low band, 20 frames each: 5 dB over its floor rising to 30 and back.
FeatureTrack voiced_peaks(std::size_t peaks) {
    FeatureTrack track;
    track.frame_count = 20 * peaks;
    track.values.assign(track.frame_count * kFeatureCount, 0.0f);
    for (std::size_t t = 0; t < track.frame_count; ++t) {
        const auto from_top = static_cast<float>(t % 20 > 10 ? t % 20 - 10 : 10 - t % 20);
        track.values[t * kFeatureCount + kLowBandDb] = 30.0f - 2.5f * from_top;
    }
    return track;
}

}  // namespace

TEST_SUITE("speech") {
    TEST_CASE("a line's syllables bounded on its cut leave the noise outside the bound to the edge pauses") {
        Line line;
        std::vector<SentenceChain> chains = group_chains(line.transcript, line.cut, line.cut.spans);
        set_search_spans(line.track, LoudnessProfile(), chains);
        const SentenceChain free_chain = chains[0];
        REQUIRE(free_chain.searched.first_frame == 0);
        CHECK(free_chain.states.front().is_optional);
        // The own reading finds the voice in frames 45-80 of the cut's 30-90.
        line.cut.syllable_bounds = {{45, 80}};
        chains = group_chains(line.transcript, line.cut, line.cut.spans);
        set_search_spans(line.track, LoudnessProfile(), chains);
        const SentenceChain& bounded = chains[0];
        CHECK(bounded.searched.first_frame == free_chain.searched.first_frame);
        CHECK(bounded.searched.end_frame == free_chain.searched.end_frame);
        CHECK_FALSE(bounded.states.front().is_optional);
        CHECK(bounded.states.front().min_frames == 45);
        CHECK(bounded.states.back().min_frames == bounded.searched.end_frame - 80);

        const std::size_t frames = free_chain.searched.length();
        const EmissionScores scores = lifted_noise_scores(frames, 45, 80);
        ViterbiWorkspace workspace;
        const FrameSpan free_held =
            syllables_on(free_chain, viterbi_align(free_chain.states, scores, workspace, frames));
        CHECK(free_held.first_frame < 45);
        const std::vector<StateSegment> path = viterbi_align(bounded.states, scores, workspace, frames);
        REQUIRE_FALSE(path.empty());
        const FrameSpan held = syllables_on(bounded, path);
        CHECK(held.first_frame >= 45);
        CHECK(held.end_frame <= 80);
    }

    TEST_CASE("the order margin's rival keeps the frames a bounded line's edge pauses hold") {
        Line line;
        line.cut.syllable_bounds = {{45, 80}};
        std::vector<SentenceChain> chains = group_chains(line.transcript, line.cut, line.cut.spans);
        set_search_spans(line.track, LoudnessProfile(), chains);
        const SentenceChain& bounded = chains[0];
        // Every frame of the voice alike: in any order its sounds fit as well, and the margin is 0.
        // Swapped into the voice, the noise's frames would hold the rival's edge pause on speech.
        const std::size_t frames = bounded.searched.length();
        const EmissionScores scores = lifted_noise_scores(frames, 45, 80);
        ViterbiWorkspace workspace;
        const std::vector<StateSegment> path = viterbi_align(bounded.states, scores, workspace, frames);
        REQUIRE_FALSE(path.empty());
        CHECK(std::fabs(order_margin(bounded, path, scores, workspace)) < 1e-6);
    }

    TEST_CASE("a line held off the noise is judged by its typical syllable whatever its length") {
        // 記得帶裝備 read for 晚上一起玩 through a phone's gain, held to its voice: the typical syllable
        // 0.48 against a margin of 0.45; the right 快來幫我啊 through a fast codec chain 0.26 against 0.45.
        const Timeline wrong = read_transcript("記得帶裝備。");
        const std::vector<FrameSpan> spans = {{0, 176}};
        std::vector<SentenceMetrics> metrics(1);
        metrics[0].order_margin = 0.45;
        metrics[0].held_out_median = 0.48;
        CHECK_THROWS_WITH_AS(check_typical_syllable_off_noise(metrics, spans, wrong),
                             doctest::Contains("other sounds fit its typical syllable 0.48"), AlignmentError);
        metrics[0].held_out_median = 0.26;
        CHECK_NOTHROW(check_typical_syllable_off_noise(metrics, spans, wrong));
        // Unmeasured (a line of one or two syllables), it refuses nothing.
        metrics[0].held_out_median = std::nan("");
        CHECK_NOTHROW(check_typical_syllable_off_noise(metrics, spans, wrong));
        // From kMinHeldOutSyllables on, check_held_out_fit asks it already.
        metrics[0].held_out_median = 0.48;
        CHECK_NOTHROW(check_typical_syllable_off_noise(metrics, spans, read_transcript("把那個箱子打開。")));
    }

    TEST_CASE("a line is held to its own reading only where it is short and alone there") {
        const LoudnessProfile loudness;
        // 7 syllables, 7 voiced peaks (快來幫我啊 through a fast codec chain: 5 or 6 for 5 syllables).
        const FeatureTrack seven = voiced_peaks(7);
        REQUIRE(count_nuclei(seven, loudness, {0, seven.frame_count}) == 7);
        CHECK(is_held_to_own_reading(seven, loudness, {0, seven.frame_count}, 7));
        // Other voices' peaks inside the reading as well (我去拿一下外賣 among voices: 11), but under
        // kMaxNucleiPerSyllable a syllable.
        const FeatureTrack eleven = voiced_peaks(11);
        CHECK(is_held_to_own_reading(eleven, loudness, {0, eleven.frame_count}, 7));
        // A clip of two sentences given the text of one: twice the peaks of its syllables.
        const FeatureTrack fourteen = voiced_peaks(14);
        CHECK_FALSE(is_held_to_own_reading(fourteen, loudness, {0, fourteen.frame_count}, 7));
        // From kMinEndClauseSyllables on, the checks on the cut stand: a sentence of 12 with 12 peaks.
        const FeatureTrack twelve = voiced_peaks(12);
        CHECK_FALSE(is_held_to_own_reading(twelve, loudness, {0, twelve.frame_count}, 12));
    }
}

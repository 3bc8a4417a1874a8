// check_sentence_lengths and the voiced peaks it counts (issue 12): a person may say a sentence
// more than twice as slowly as the others, a sentence missing from the transcript leaves one as
// slow but with two sentences' syllables in it; check_missing_text finds such a sentence on the syllables
// as aligned, on every placement the alignment made of them (check_missing_text_as_placed).
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "speech/alignment_checks.hpp"
#include "speech/placed_missing_text.hpp"
#include "talkface/errors.hpp"
#include "talkface/transcript.hpp"

using namespace talkface;
using namespace talkface::detail;

namespace {

// A track whose low band (voicing) rises to `peak_db` in `peaks` evenly spaced bumps over each
// span, at `dip_db` between them; 0 dB (the floor) elsewhere.
struct BumpyTrack {
    FeatureTrack track;
    LoudnessProfile loudness;

    explicit BumpyTrack(std::size_t frames) {
        track.frame_count = frames;
        track.values.assign(frames * kFeatureCount, 0.0f);
        loudness.low_floor_db = 0.0f;
        loudness.activity_db.assign(frames, 0.0f);
    }
    // The activity over `span`: `db`, at or above the speech threshold (0 dB) or under it.
    void activity(const FrameSpan& span, float db) {
        std::fill(loudness.activity_db.begin() + static_cast<std::ptrdiff_t>(span.first_frame),
                  loudness.activity_db.begin() + static_cast<std::ptrdiff_t>(span.end_frame), db);
    }
    void bumps(const FrameSpan& span, std::size_t peaks, float peak_db, float dip_db,
               int column = kLowBandDb) {
        const double width = static_cast<double>(span.length()) / static_cast<double>(peaks);
        for (std::size_t t = span.first_frame; t < span.end_frame; ++t) {
            const double phase = (static_cast<double>(t - span.first_frame) + 0.5) / width;
            const double within = phase - static_cast<double>(static_cast<std::size_t>(phase));  // 0..1 in a bump
            const double rise = 1.0 - std::abs(2.0 * within - 1.0);                              // a triangle
            track.values[t * kFeatureCount + static_cast<std::size_t>(column)] =
                static_cast<float>(dip_db + (peak_db - dip_db) * rise);
        }
    }
};

// Syllables of `aligned` from `first` on placed at `times` (seconds), one pair each.
void place(Timeline& aligned, std::size_t first, const std::vector<std::pair<double, double>>& times) {
    for (std::size_t i = 0; i < times.size(); ++i) {
        aligned.syllables[first + i].start_s = times[i].first;
        aligned.syllables[first + i].end_s = times[i].second;
    }
}

// Four syllables of 0.2 s from `start`, a voiced peak each.
void said_evenly(Timeline& aligned, BumpyTrack& bumpy, std::size_t first, double start) {
    place(aligned, first, {{start, start + 0.2}, {start + 0.2, start + 0.4}, {start + 0.4, start + 0.6}, {start + 0.6, start + 0.8}});
    const auto frame = static_cast<std::size_t>(std::lround(start / 0.01));
    bumpy.bumps({frame, frame + 80}, 4, 30.0f, 15.0f);
}

}  // namespace

TEST_SUITE("speech") {
    TEST_CASE("voiced peaks: one per bump that stands out of its dips and its floor") {
        BumpyTrack bumpy(400);
        bumpy.bumps({0, 200}, 8, 30.0f, 15.0f);
        CHECK(count_nuclei(bumpy.track, bumpy.loudness, {0, 200}) == 8);
        // A ripple of 2 dB is one peak, not eight.
        bumpy.bumps({0, 200}, 8, 30.0f, 28.0f);
        CHECK(count_nuclei(bumpy.track, bumpy.loudness, {0, 200}) == 1);
        // Bumps in a pause, under the floor's margin, are no syllables.
        bumpy.bumps({200, 400}, 8, 8.0f, 0.0f);
        CHECK(count_nuclei(bumpy.track, bumpy.loudness, {200, 400}) == 0);
    }

    TEST_CASE("voiced peaks through a telephone band: counted on the low and mid bands together") {
        // Four syllables whose first formant dips inside each (two low-band bumps a syllable, as
        // jian's i to a reads through 300-3400 Hz) under a second formant's one bump a syllable.
        BumpyTrack bumpy(200);
        bumpy.bumps({0, 200}, 8, 30.0f, 20.0f);
        bumpy.bumps({0, 200}, 4, 40.0f, 20.0f, kMidBandDb);
        bumpy.track.fundamental_share = 0.03;
        CHECK(count_nuclei(bumpy.track, bumpy.loudness, {0, 200}) == 4);
        // With its fundamental the low band is the voicing, read alone.
        bumpy.track.fundamental_share = 0.4;
        CHECK(count_nuclei(bumpy.track, bumpy.loudness, {0, 200}) == 8);
    }

    TEST_CASE("a sentence far slower than the others passes when its voiced peaks fit its syllables") {
        // Four syllables each; the third sentence 2.25 times as slow as the others.
        const Timeline transcript = read_transcript("今天很好。我们走吧。他们来了。");
        REQUIRE(transcript.syllables.size() == 12);
        const std::vector<FrameSpan> spans = {{20, 100}, {150, 230}, {280, 460}};
        BumpyTrack bumpy(500);
        bumpy.bumps(spans[0], 4, 30.0f, 15.0f);
        bumpy.bumps(spans[1], 4, 30.0f, 15.0f);
        SUBCASE("a peak per syllable: said slowly") {
            bumpy.bumps(spans[2], 4, 30.0f, 15.0f);
            CHECK_NOTHROW(check_sentence_lengths(spans, bumpy.track, bumpy.loudness, transcript));
        }
        SUBCASE("two peaks per syllable: a sentence the transcript lacks") {
            bumpy.bumps(spans[2], 8, 30.0f, 15.0f);
            CHECK_THROWS_WITH_AS(check_sentence_lengths(spans, bumpy.track, bumpy.loudness, transcript),
                                 doctest::Contains("sentence 3 (2.8-4.6 s"), AlignmentError);
        }
        SUBCASE("a sentence as much faster than the others is refused, whatever its peaks") {
            const std::vector<FrameSpan> fast = {{20, 200}, {250, 430}, {480, 560}};
            BumpyTrack quick(600);
            for (const auto& span : fast) quick.bumps(span, 4, 30.0f, 15.0f);
            CHECK_THROWS_AS(check_sentence_lengths(fast, quick.track, quick.loudness, transcript), AlignmentError);
        }
    }

    TEST_CASE("a one-syllable line alone passes however short, and beside another sentence is refused in the singular") {
        // 嗯。 as espeak-ng says it: 0.05 s of sound (/work/corpus/sweep-short/espeak-en-bare.wav).
        const Timeline alone = read_transcript("嗯。");
        BumpyTrack bumpy(13);
        bumpy.bumps({1, 6}, 1, 30.0f, 15.0f);
        CHECK_NOTHROW(check_sentence_lengths({{1, 6}}, bumpy.track, bumpy.loudness, alone));
        const Timeline beside = read_transcript("嗯。今天很好。");
        BumpyTrack two(120);
        two.bumps({1, 6}, 1, 30.0f, 15.0f);
        two.bumps({30, 110}, 4, 30.0f, 15.0f);
        CHECK_THROWS_WITH_AS(check_sentence_lengths({{1, 6}, {30, 110}}, two.track, two.loudness, beside),
                             doctest::Contains("): 1 syllable in 0.05 s of speech (0.05 s each"), AlignmentError);
    }

    TEST_CASE("a line's last syllable may be drawn out before the pause as long as any syllable") {
        // A line alone whose speech is `span`, a voiced peak per syllable.
        const auto check_alone = [](const char* text, const FrameSpan& span) {
            const Timeline line = read_transcript(text);
            BumpyTrack bumpy(span.end_frame + 50);
            bumpy.bumps(span, line.syllables.size(), 30.0f, 15.0f);
            check_sentence_lengths({span}, bumpy.track, bumpy.loudness, line);
        };
        // 誰？ said alone by speaker 3 made lower (bench/short_lines_bench.py, kind voice): 0.74 s of
        // speech, more than 0.7 s a syllable, under the 1.2 s a syllable lasts at most.
        CHECK_NOTHROW(check_alone("誰？", {50, 124}));
        CHECK_THROWS_WITH_AS(check_alone("誰？", {50, 180}), doctest::Contains("1 syllable in 1.3 s of speech"), AlignmentError);
        // Two syllables: 0.7 s and a last one of 1.1 s pass; 0.7 s and 1.3 s do not.
        CHECK_NOTHROW(check_alone("當然。", {20, 200}));
        CHECK_THROWS_WITH_AS(check_alone("當然。", {20, 220}), doctest::Contains("2 syllables in 2 s of speech (1 s each"),
                             AlignmentError);
    }

    TEST_CASE("a sentence fast only because quiet syllables were taken for a pause passes when its voiced peaks are there") {
        // Four syllables each, 1 s a sentence; 0.7 s of the third measured as a pause, so that its
        // speech frames give 0.075 s a syllable against the others' 0.25 s.
        const Timeline transcript = read_transcript("今天很好。我们走吧。他们来了。");
        const std::vector<FrameSpan> spans = {{20, 120}, {170, 270}, {320, 420}};
        BumpyTrack bumpy(500);
        bumpy.loudness.pauses = {{120, 170}, {270, 320}, {330, 400}};
        bumpy.bumps(spans[0], 4, 30.0f, 15.0f);
        bumpy.bumps(spans[1], 4, 30.0f, 15.0f);
        SUBCASE("a peak per syllable: its quiet syllables are there") {
            bumpy.bumps(spans[2], 4, 30.0f, 15.0f);
            CHECK_NOTHROW(check_sentence_lengths(spans, bumpy.track, bumpy.loudness, transcript));
        }
        SUBCASE("a peak for two syllables: the audio lacks some of its text") {
            bumpy.bumps(spans[2], 2, 30.0f, 15.0f);
            CHECK_THROWS_WITH_AS(check_sentence_lengths(spans, bumpy.track, bumpy.loudness, transcript),
                                 doctest::Contains("sentence 3 (3.2-4.2 s"), AlignmentError);
        }
    }

    TEST_CASE("a sentence said quieter than the others keeps its voiced peaks quieter too") {
        // As above, 0.7 s of the third sentence measured as a pause; its loud frames 6 dB under the
        // others' (bench/ p-street tuning-018: 4.7 dB), its syllables' peaks 7 dB above the floor.
        const Timeline transcript = read_transcript("今天很好。我们走吧。他们来了。");
        const std::vector<FrameSpan> spans = {{20, 120}, {170, 270}, {320, 420}};
        BumpyTrack bumpy(500);
        bumpy.loudness.activity_threshold_db = 6.0f;
        bumpy.loudness.pauses = {{120, 170}, {270, 320}, {330, 400}};
        for (std::size_t k = 0; k < 2; ++k) {
            bumpy.bumps(spans[k], 4, 30.0f, 15.0f);
            bumpy.activity(spans[k], 20.0f);
        }
        bumpy.activity({320, 330}, 14.0f);
        bumpy.activity({400, 420}, 14.0f);
        SUBCASE(
            "a peak per syllable 7 dB above the floor, said 6 dB quieter: its quiet syllables are there") {
            bumpy.bumps(spans[2], 4, 7.0f, 2.0f);
            CHECK_NOTHROW(check_sentence_lengths(spans, bumpy.track, bumpy.loudness, transcript));
        }
        SUBCASE("the same peaks in a sentence as loud as the others: too faint for its syllables") {
            bumpy.bumps(spans[2], 4, 7.0f, 2.0f);
            bumpy.activity({320, 330}, 20.0f);
            bumpy.activity({400, 420}, 20.0f);
            CHECK_THROWS_WITH_AS(check_sentence_lengths(spans, bumpy.track, bumpy.loudness, transcript),
                                 doctest::Contains("sentence 3 (3.2-4.2 s"), AlignmentError);
        }
        SUBCASE("ripples 5 dB above the floor, however quiet the sentence: the noise's, no syllables") {
            bumpy.bumps(spans[2], 4, 5.0f, 1.0f);
            CHECK_THROWS_WITH_AS(check_sentence_lengths(spans, bumpy.track, bumpy.loudness, transcript),
                                 doctest::Contains("sentence 3 (3.2-4.2 s"), AlignmentError);
        }
    }

    TEST_CASE("a sentence whose syllables hold another sentence's speech: its voiced peaks and a pause the text lacks") {
        // Four sentences of four syllables, 0.6 s apart; the third, from 3 s on, is what varies.
        Timeline aligned = read_transcript("今天很好。我们走吧。他们来了。明天见吧。");
        REQUIRE(aligned.syllables.size() == 16);
        BumpyTrack bumpy(700);
        said_evenly(aligned, bumpy, 0, 0.2);
        said_evenly(aligned, bumpy, 4, 1.6);
        said_evenly(aligned, bumpy, 12, 5.8);
        std::vector<std::string> findings;
        SUBCASE("two syllables, a sentence's pause, two more, and two sentences' peaks: a sentence missing") {
            place(aligned, 8, {{3.0, 3.4}, {3.4, 3.8}, {4.4, 4.8}, {4.8, 5.2}});
            bumpy.bumps({300, 380}, 4, 30.0f, 15.0f);
            bumpy.bumps({440, 520}, 4, 30.0f, 15.0f);
            std::string message;
            try {
                check_missing_text(aligned, bumpy.track, bumpy.loudness, findings);
            } catch (const AlignmentError& error) {
                message = error.what();
            }
            CHECK(message.find("sentence 3 (3-5.2 s") != std::string::npos);
            CHECK(message.find("a pause of 0.6 s (3.8-4.4 s)") != std::string::npos);
            CHECK(message.find("is a sentence missing") != std::string::npos);
        }
        SUBCASE("the same pause with a peak per syllable: a hesitation, reported and aligned") {
            place(aligned, 8, {{3.0, 3.2}, {3.2, 3.4}, {4.0, 4.2}, {4.2, 4.4}});
            bumpy.bumps({300, 340}, 2, 30.0f, 15.0f);
            bumpy.bumps({400, 440}, 2, 30.0f, 15.0f);
            CHECK_NOTHROW(check_missing_text(aligned, bumpy.track, bumpy.loudness, findings));
            REQUIRE(findings.size() == 1);
            CHECK(findings[0].find("a pause of 0.6 s") != std::string::npos);
        }
        SUBCASE("no pause, but said twice as slowly with two peaks a syllable") {
            place(aligned, 8, {{3.0, 3.4}, {3.4, 3.8}, {3.8, 4.2}, {4.2, 4.6}});
            bumpy.bumps({300, 460}, 8, 30.0f, 15.0f);
            CHECK_THROWS_WITH_AS(check_missing_text(aligned, bumpy.track, bumpy.loudness, findings),
                                 doctest::Contains("2 times as slowly"), AlignmentError);
        }
        SUBCASE("said like the others: nothing found") {
            said_evenly(aligned, bumpy, 8, 3.0);
            CHECK_NOTHROW(check_missing_text(aligned, bumpy.track, bumpy.loudness, findings));
            CHECK(findings.empty());
        }
    }

    TEST_CASE("a long pause where the text has a comma is not missing text") {
        Timeline aligned = read_transcript("今天很好。我们走吧。他们，来了。明天见吧。");
        REQUIRE(aligned.syllables.size() == 16);
        BumpyTrack bumpy(700);
        said_evenly(aligned, bumpy, 0, 0.2);
        said_evenly(aligned, bumpy, 4, 1.6);
        said_evenly(aligned, bumpy, 12, 5.8);
        place(aligned, 8, {{3.0, 3.2}, {3.2, 3.4}, {4.0, 4.2}, {4.2, 4.4}});
        bumpy.bumps({300, 340}, 2, 30.0f, 15.0f);
        bumpy.bumps({400, 440}, 2, 30.0f, 15.0f);
        std::vector<std::string> findings;
        CHECK_NOTHROW(check_missing_text(aligned, bumpy.track, bumpy.loudness, findings));
        CHECK(findings.empty());
    }

    TEST_CASE("a missing sentence's pause looked for on the room's and the first alignment's placements") {
        // Sentence 3's speech from 3 s on holds two sentences' peaks with a sentence's pause inside
        // (3.8-4.4 s). The checked placement keeps its syllables to the first half, passing over the
        // rest as the pause before sentence 4 (an alignment kept to the text's marks has no pause
        // the text does not mark over 0.25 s); the other placement spreads them over both halves.
        Timeline checked = read_transcript("今天很好。我们走吧。他们来了。明天见吧。");
        BumpyTrack bumpy(700);
        said_evenly(checked, bumpy, 0, 0.2);
        said_evenly(checked, bumpy, 4, 1.6);
        said_evenly(checked, bumpy, 12, 5.8);
        bumpy.bumps({300, 380}, 4, 30.0f, 15.0f);
        bumpy.bumps({440, 520}, 4, 30.0f, 15.0f);
        Timeline spread = checked;
        place(checked, 8, {{3.0, 3.2}, {3.2, 3.4}, {3.4, 3.6}, {3.6, 3.8}});
        place(spread, 8, {{3.0, 3.4}, {3.4, 3.8}, {4.4, 4.8}, {4.8, 5.2}});
        std::vector<std::string> findings;
        REQUIRE_NOTHROW(check_missing_text(checked, bumpy.track, bumpy.loudness, findings));
        CutAlignment aligned;
        aligned.result = checked;
        SUBCASE("spread so in a room's placement: refused") {
            aligned.room_result = spread;
            CHECK_THROWS_WITH_AS(
                check_missing_text_as_placed(aligned, nullptr, bumpy.track, bumpy.loudness, findings),
                doctest::Contains("a pause of 0.6 s (3.8-4.4 s)"), AlignmentError);
        }
        SUBCASE("spread so in a room by the first alignment, the kept one having won: refused") {
            aligned.room_result = checked;
            CutAlignment unkept = aligned;
            unkept.result = spread;
            CHECK_THROWS_WITH_AS(
                check_missing_text_as_placed(aligned, &unkept, bumpy.track, bumpy.loudness, findings),
                doctest::Contains("a pause of 0.6 s (3.8-4.4 s)"), AlignmentError);
        }
        SUBCASE("the first alignment outside a room, where it slid a syllable: not read") {
            CutAlignment unkept;
            unkept.result = spread;
            CHECK_NOTHROW(
                check_missing_text_as_placed(aligned, &unkept, bumpy.track, bumpy.loudness, findings));
        }
        SUBCASE("placed so everywhere: passed, with nothing found") {
            aligned.room_result = checked;
            CutAlignment unkept = aligned;
            CHECK_NOTHROW(
                check_missing_text_as_placed(aligned, &unkept, bumpy.track, bumpy.loudness, findings));
            CHECK(findings.empty());
        }
    }
}

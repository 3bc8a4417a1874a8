// A line of one syllable the cutter found no pause around (issue 13): a codec's hiss or other voices
// as loud as a pause allows fill the file before and after it, its span and its syllable on the path
// hold them, and its rate and its syllable's length are judged on its voice's own extent
// (own_voice_extent, lead_noise.hpp); a voice as long as the span, or a line of more syllables, is
// judged on every frame as before.
#include <doctest/doctest.h>

#include <cstddef>
#include <vector>

#include "speech/alignment_checks.hpp"
#include "speech/hsmm.hpp"
#include "speech/lead_noise.hpp"
#include "talkface/errors.hpp"
#include "talkface/transcript.hpp"

using namespace talkface;
using namespace talkface::detail;

namespace {

// 走！ through a lossy stream (bench/short_kinds_bench.py, p-loss): 1.32 s of hiss at 25 dB, above
// the threshold for speech, and the voice at 57 dB over `voice`.
struct HissedLine {
    FeatureTrack track;
    LoudnessProfile loudness;
    EmissionScores scores;

    HissedLine(std::size_t frames, const FrameSpan& voice) {
        track.frame_count = frames;
        track.values.assign(frames * kFeatureCount, 0.0F);
        loudness.activity_threshold_db = 21.0F;
        loudness.activity_db.assign(frames, 25.0F);
        for (std::size_t t = voice.first_frame; t < voice.end_frame; ++t) loudness.activity_db[t] = 57.0F;
        scores.frame_count = frames;
        scores.values.assign(frames * kPhoneClassCount, -10.0F);
    }
};

}  // namespace

TEST_SUITE("speech") {
    TEST_CASE("a one-syllable line in a file of hiss is as slow as its voice, not its span") {
        const Timeline line = read_transcript("走！");
        const HissedLine hissed(132, {52, 90});
        CHECK(own_voice_extent(hissed.loudness, {0, 132}).first_frame == 52);
        CHECK(own_voice_extent(hissed.loudness, {0, 132}).end_frame == 90);
        CHECK_NOTHROW(check_sentence_lengths({{0, 132}}, hissed.track, hissed.loudness, line));
        // A voice over the whole span: a sentence the text lacks, refused as before.
        const HissedLine spoken(132, {5, 130});
        CHECK_THROWS_WITH_AS(check_sentence_lengths({{0, 132}}, spoken.track, spoken.loudness, line),
                             doctest::Contains("1 syllable in 1.32 s of speech"), AlignmentError);
    }

    TEST_CASE("a lone syllable drawn over the hiss around its voice is as long as its voice") {
        const Timeline line = read_transcript("走！");
        const HissedLine hissed(132, {52, 90});
        const std::vector<AlignedStretch> drawn{{0, 132, false, 0}};
        CHECK_NOTHROW(check_path(drawn, hissed.loudness, hissed.scores, 0, 0, {0, 132}, line));
        const HissedLine spoken(132, {5, 130});
        CHECK_THROWS_WITH_AS(check_path(drawn, spoken.loudness, spoken.scores, 0, 0, {0, 132}, line),
                             doctest::Contains("would last 0-1.32 s, longer than any syllable"),
                             AlignmentError);
    }

    TEST_CASE("a line's last syllable drawn over the noise after its voice keeps every frame") {
        // 快跑 read over 3號！ among other voices: 跑 drawn from 0.44 s over the voice's end (1.36 s)
        // and the voices after it to 1.66 s.
        const Timeline line = read_transcript("快跑！");
        const HissedLine among(168, {47, 136});
        const std::vector<AlignedStretch> drawn{{2, 44, false, 0}, {44, 166, false, 1}};
        CHECK_THROWS_WITH_AS(check_path(drawn, among.loudness, among.scores, 0, 0, {0, 168}, line),
                             doctest::Contains("would last 0.44-1.66 s, longer than any syllable"),
                             AlignmentError);
    }
}

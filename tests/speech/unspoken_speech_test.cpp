// check_path's speech the transcript has no syllable for (issue 13): music between sentences is as
// loud as the speech (a person under a tune: drums within 12 dB of the syllables for 0.4-0.6 s after
// a sentence's last syllable were refused as a missing phrase), but it does not sound like the
// sentence's syllables on the recording's own models; speech the text lacks does.
#include <doctest/doctest.h>

#include <cstddef>
#include <vector>

#include "speech/alignment_checks.hpp"
#include "talkface/errors.hpp"
#include "talkface/transcript.hpp"

using namespace talkface;
using namespace talkface::detail;

namespace {

// A sentence of four syllables (frames 10-90) and a pause after it (90-200) holding 50 frames as
// loud as the syllables (120-170): `pause_gain` is how much better those frames fit the best sound
// of speech than a pause; the syllables' frames gain 3 per frame, the quiet ones lose 2.
struct LoudPause {
    LoudnessProfile loudness;
    EmissionScores scores;
    std::vector<AlignedStretch> stretches;

    explicit LoudPause(float pause_gain) {
        const std::size_t frames = 200;
        loudness.activity_threshold_db = 6.0f;
        loudness.activity_db.assign(frames, 0.0f);
        scores.frame_count = frames;
        scores.values.assign(frames * kPhoneClassCount, -20.0f);
        const auto set = [&](std::size_t t, float level_db, float gain) {
            loudness.activity_db[t] = level_db;
            scores.values[t * kPhoneClassCount + kSilence] = -10.0f;
            scores.values[t * kPhoneClassCount + kVowelA] = -10.0f + gain;
        };
        for (std::size_t t = 0; t < frames; ++t) set(t, 0.0f, -2.0f);
        for (std::size_t t = 10; t < 90; ++t) set(t, 30.0f, 3.0f);
        for (std::size_t t = 120; t < 170; ++t) set(t, 28.0f, pause_gain);
        stretches.push_back({0, 10, true, 0});
        for (std::size_t k = 0; k < 4; ++k) stretches.push_back({10 + 20 * k, 30 + 20 * k, false, k});
        stretches.push_back({90, 200, true, 3});
    }
};

}  // namespace

TEST_SUITE("speech") {
    TEST_CASE("loud music after a sentence's last syllable is not speech the transcript lacks") {
        const Timeline transcript = read_transcript("今天很好。");
        REQUIRE(transcript.syllables.size() == 4);
        const LoudPause music(0.5f);
        CHECK_NOTHROW(check_path(music.stretches, music.loudness, music.scores, 0, 0, {10, 90}, transcript));
        // The same frames sounding like the syllables are: speech with no syllable, named where.
        const LoudPause speech(2.5f);
        CHECK_THROWS_WITH_AS(check_path(speech.stretches, speech.loudness, speech.scores, 0, 0, {10, 90}, transcript),
                             doctest::Contains("speech at 1.2-1.7 s, after \"好\" (hao3), has no syllable"), AlignmentError);
        // A chain's scores start at its first searched frame, not the recording's.
        LoudPause later(0.5f);
        later.scores.values.erase(later.scores.values.begin(), later.scores.values.begin() + 5 * kPhoneClassCount);
        later.scores.frame_count -= 5;
        later.stretches.front().first_frame = 5;
        CHECK_NOTHROW(check_path(later.stretches, later.loudness, later.scores, 5, 0, {10, 90}, transcript));
    }

    TEST_CASE("where the models cannot tell syllables from a pause, a loud pause is judged on loudness") {
        const Timeline transcript = read_transcript("今天很好。");
        LoudPause flat(0.0f);
        for (std::size_t t = 10; t < 90; ++t) flat.scores.values[t * kPhoneClassCount + kVowelA] = -10.0f;
        CHECK_THROWS_AS(check_path(flat.stretches, flat.loudness, flat.scores, 0, 0, {10, 90}, transcript), AlignmentError);
    }
}

// AlignOptions::lenient (issue #13): a transcript a word off is aligned, the stretch that does not
// say its text reported (time span, expected text), and the other syllables placed as well as
// with a right text; a right text is never marked. The clip: espeak-ng (cmn-latn-pinyin) says
// 小朋友们在公园里放风筝 (tests/data/speech/make_clips.sh).
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "common/speech_clips.hpp"
#include "talkface/errors.hpp"
#include "talkface/speech_aligner.hpp"
#include "talkface/transcript.hpp"

using namespace talkface;

namespace {

// Where 公园 (syllables 5 and 6 of what is said) starts and ends.
constexpr std::size_t kWordFirst = 5;
constexpr std::size_t kWordEnd = 7;

SpeechAligner lenient_aligner() {
    AlignOptions options;
    options.lenient = true;
    return SpeechAligner(options);
}

}  // namespace

TEST_SUITE("speech") {
    TEST_CASE("lenient: a word the transcript lacks is reported where it is said; the rest is in place") {
        const auto truth = test::true_starts("lenient_espeak");
        REQUIRE(truth.size() == 11);
        const Timeline transcript = read_transcript("小朋友们在里放风筝。");
        const Timeline aligned = lenient_aligner().align_file(test::clip_path("lenient_espeak.flac"), transcript);
        REQUIRE(aligned.mismatches.size() == 1);
        const TextMismatch& mismatch = aligned.mismatches.front();
        CHECK(mismatch.syllable_count == 0);
        CHECK(mismatch.first_syllable == 5);  // 里, the syllable after the word
        CHECK(mismatch.expected_text.empty());
        CHECK(std::abs(mismatch.start_s - truth[kWordFirst]) < 0.05);
        CHECK(std::abs(mismatch.end_s - truth[kWordEnd]) < 0.05);
        CHECK(std::any_of(aligned.warnings.begin(), aligned.warnings.end(), [](const std::string& warning) {
            return warning.find("speech the transcript lacks") != std::string::npos;
        }));
        for (std::size_t i = 0; i < aligned.syllables.size(); ++i) {
            CAPTURE(i);
            const double said_start = truth[i < kWordFirst ? i : i + (kWordEnd - kWordFirst)];
            CHECK(std::abs(aligned.syllables[i].start_s - said_start) < 0.05);
        }
        // Without lenient alignment nothing is reported (the checks judge the text instead).
        CHECK(SpeechAligner(AlignOptions{}).options().lenient == false);
    }

    TEST_CASE("lenient: a changed word is reported inside its stretch; the syllables around it keep their place") {
        const auto truth = test::true_starts("lenient_espeak");
        const Timeline transcript = load_transcript(test::clip_path("lenient_espeak.txt"));  // 学校 for 公园
        const Timeline aligned = lenient_aligner().align_file(test::clip_path("lenient_espeak.flac"), transcript);
        REQUIRE(aligned.mismatches.size() == 1);
        const TextMismatch& mismatch = aligned.mismatches.front();
        CHECK(mismatch.syllable_count >= 1);
        CHECK(mismatch.first_syllable >= 5);
        CHECK(mismatch.first_syllable + mismatch.syllable_count <= 7);
        CHECK(std::string("学校").find(mismatch.expected_text) != std::string::npos);
        // It lies within the changed word (100 ms either way: it is found from the part of the
        // word that fits the text worst, 学 here, not from the whole word).
        CHECK(mismatch.start_s > truth[kWordFirst] - 0.1);
        CHECK(mismatch.end_s < truth[kWordEnd] + 0.1);
        for (std::size_t i = mismatch.first_syllable; i < mismatch.first_syllable + mismatch.syllable_count; ++i) {
            CAPTURE(i);
            CHECK(aligned.syllables[i].confidence == 0.0);
            CHECK(aligned.syllables[i].start_s >= mismatch.start_s - 1e-9);
            CHECK(aligned.syllables[i].end_s <= mismatch.end_s + 1e-9);
        }
        for (std::size_t i = 0; i < truth.size(); ++i) {
            if (i >= kWordFirst && i < kWordEnd) continue;
            CAPTURE(i);
            CHECK(std::abs(aligned.syllables[i].start_s - truth[i]) < 0.05);
        }
    }

    TEST_CASE("lenient: right texts are never marked, and aligned as without it") {
        const std::vector<std::pair<const char*, const char*>> clips = {
            {"one_sentence", ".wav"}, {"two_sentences", ".wav"}, {"comma_pause", ".flac"},
            {"run_together", ".flac"}, {"short_line", ".flac"}};
        for (const auto& [name, suffix] : clips) {
            CAPTURE(name);
            const std::string audio = test::clip_path(std::string(name) + suffix);
            const Timeline transcript = load_transcript(test::clip_path(std::string(name) + ".txt"));
            const Timeline strict = SpeechAligner().align_file(audio, transcript);
            const Timeline lenient = lenient_aligner().align_file(audio, transcript);
            CHECK(lenient.mismatches.empty());
            REQUIRE(lenient.syllables.size() == strict.syllables.size());
            for (std::size_t i = 0; i < strict.syllables.size(); ++i) {
                CAPTURE(i);
                CHECK(std::abs(lenient.syllables[i].start_s - strict.syllables[i].start_s) < 0.02);
            }
        }
    }
}

// AlignOptions::check (issue #13): what a transcript that does not match the audio does, and a
// correct line of a few syllables aligned, not refused.
#include <doctest/doctest.h>

#include <algorithm>
#include <string>

#include "common/test_paths.hpp"
#include "talkface/errors.hpp"
#include "talkface/speech_aligner.hpp"
#include "talkface/transcript.hpp"

using namespace talkface;

namespace {

std::string clip(const std::string& file) { return test::source_path("tests/data/speech/" + file); }

SpeechAligner aligner_with(CheckMode mode) {
    AlignOptions options;
    options.check = mode;
    return SpeechAligner(options);
}

bool has_warning_starting(const Timeline& timeline, const std::string& start) {
    return std::any_of(timeline.warnings.begin(), timeline.warnings.end(),
                       [&](const std::string& warning) { return warning.rfind(start, 0) == 0; });
}

constexpr const char* kStrongFinding = "the transcript may not match the audio";

}  // namespace

TEST_SUITE("speech") {
    TEST_CASE("check modes: a wrong text is refused, warned of with its evidence, or aligned unchecked") {
        // As in speech_aligner_test: a wrong text of the same length in a file of one sentence.
        const Timeline wrong = read_transcript("我昨天在超市买了苹果和。");
        CHECK(AlignOptions{}.check == CheckMode::refuse);
        CHECK_THROWS_WITH_AS(aligner_with(CheckMode::refuse).align_file(clip("one_sentence.wav"), wrong),
                             doctest::Contains("is it another sentence, or are two sentences swapped?"), AlignmentError);

        const Timeline warned = aligner_with(CheckMode::warn).align_file(clip("one_sentence.wav"), wrong);
        REQUIRE(warned.syllables.size() == wrong.syllables.size());
        REQUIRE(has_warning_starting(warned, kStrongFinding));
        const auto finding = std::find_if(warned.warnings.begin(), warned.warnings.end(), [](const std::string& w) {
            return w.rfind(kStrongFinding, 0) == 0;
        });
        // Which sentence, where, and how sure: the measure beside what a right text gives.
        CHECK(finding->find("sentence 1 (0.") != std::string::npos);
        CHECK(finding->find("\"我昨天在超市买了苹果和。\"") != std::string::npos);
        CHECK(finding->find("for the right text") != std::string::npos);

        const Timeline unchecked = aligner_with(CheckMode::off).align_file(clip("one_sentence.wav"), wrong);
        CHECK_FALSE(has_warning_starting(unchecked, kStrongFinding));
        REQUIRE(unchecked.syllables.size() == warned.syllables.size());
        for (std::size_t i = 0; i < unchecked.syllables.size(); ++i) {
            CAPTURE(i);
            CHECK(unchecked.syllables[i].start_s == warned.syllables[i].start_s);
        }
    }

    TEST_CASE("check modes: a right text aligns the same in every mode") {
        const Timeline transcript = load_transcript(clip("two_sentences.txt"));
        const Timeline refused = aligner_with(CheckMode::refuse).align_file(clip("two_sentences.wav"), transcript);
        for (const CheckMode mode : {CheckMode::warn, CheckMode::off}) {
            const Timeline other = aligner_with(mode).align_file(clip("two_sentences.wav"), transcript);
            CHECK(other.warnings == refused.warnings);
            for (std::size_t i = 0; i < other.syllables.size(); ++i) CHECK(other.syllables[i].start_s == refused.syllables[i].start_s);
        }
    }

    TEST_CASE("check modes: no mode aligns what cannot be aligned, and an unknown mode is named") {
        // 390 syllables in 4.5 s of audio, more than its 10 ms frames: no timeline exists to return.
        std::string text;
        for (int i = 0; i < 30; ++i) text += "今天下午有雨我们明天再去吧";
        CHECK_THROWS_AS(aligner_with(CheckMode::off).align_file(clip("two_sentences.wav"), read_transcript(text + "。")),
                        AlignmentError);
        AlignOptions options;
        options.check = static_cast<CheckMode>(7);
        CHECK_THROWS_WITH_AS(SpeechAligner{options}, doctest::Contains("check"), InvalidArgument);
    }

    TEST_CASE("a correct line of two syllables by a person is aligned by default, a weak finding only warned of") {
        const Timeline transcript = load_transcript(clip("short_line.txt"));
        const Timeline timeline = SpeechAligner().align_file(clip("short_line.flac"), transcript);
        REQUIRE(timeline.syllables.size() == 2);
        CHECK(timeline.syllables[0].start_s >= 0.2);
        CHECK(timeline.syllables[0].start_s <= 0.4);
        CHECK(timeline.syllables[1].start_s > timeline.syllables[0].start_s + 0.15);
        CHECK(timeline.syllables[1].end_s <= timeline.duration_s);
        CHECK_FALSE(has_warning_starting(timeline, kStrongFinding));
        for (const auto& warning : timeline.warnings) {
            CAPTURE(warning);
            CHECK(warning.find("too few to tell a wrong text by") != std::string::npos);
        }
    }

    TEST_CASE("a wrong line of two syllables stays refused when a stop after its nasal is let release") {
        // espeak-ng says 好啊 (tests/data/speech/make_clips.sh). The text 請進 fits it 0.28 per frame
        // worse than free sounds; aligned again with 進's closure after 請's ng free to be skipped,
        // it fits under 0 on models learned from that path alone, but models learned from the rest
        // of the recording still find it 0.72 worse, over a right text's 0.35: the first alignment
        // stands and is refused. The right text aligns.
        CHECK_THROWS_WITH_AS(SpeechAligner().align_file(clip("wrong_short_line.flac"), read_transcript("請進。")),
                             doctest::Contains("the audio does not sound like its text"), AlignmentError);
        const Timeline right = SpeechAligner().align_file(clip("wrong_short_line.flac"), load_transcript(clip("wrong_short_line.txt")));
        REQUIRE(right.syllables.size() == 2);
        CHECK(right.syllables[0].start_s >= 0.4);
        CHECK(right.syllables[0].start_s <= 0.6);
        CHECK_FALSE(has_warning_starting(right, kStrongFinding));
    }
}

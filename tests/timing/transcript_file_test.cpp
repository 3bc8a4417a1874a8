// Subtitles and TextGrids given as the transcript: their text is read, a sentence per cue or
// interval where the file cuts it, and nothing of their numbers, times or markup is said;
// warnings and errors name the file's own lines.
#include <doctest/doctest.h>

#include <string>

#include "talkface/errors.hpp"
#include "talkface/timing_formats.hpp"
#include "talkface/transcript.hpp"
#include "timing/transcript_file.hpp"

using talkface::Timeline;
using talkface::detail::read_transcript_file;

namespace {

std::string said(const Timeline& timeline) {
    std::string text;
    for (const auto& syllable : timeline.syllables) text += syllable.text;
    return text;
}

std::vector<std::string> sentences(const Timeline& timeline) {
    std::vector<std::string> texts;
    for (const auto& sentence : timeline.sentences) texts.push_back(sentence.text);
    return texts;
}

const char* const kSubRip =
    "1\r\n00:00:01,000 --> 00:00:02,500\r\n<i>大家好</i>\r\n\r\n"
    "2\r\n00:00:02,600 --> 00:00:04,000\r\n{\\an8}欢迎收看，\r\n今天的节目\r\n\r\n"
    "3\r\n00:00:04,100 --> 00:00:06,000\r\n我们今天讲，\r\n\r\n"
    "4\r\n00:00:06,100 --> 00:00:08,000\r\n天气（笑）★\r\n";

}  // namespace

TEST_SUITE("transcript files") {
    TEST_CASE(
        "SubRip: the cues' text, a sentence a cue unless it runs on, numbers, times and markup unsaid") {
        const Timeline timeline = read_transcript_file(kSubRip, {}, "subs.srt");
        CHECK(said(timeline) == "大家好欢迎收看今天的节目我们今天讲天气");
        CHECK(sentences(timeline) ==
              std::vector<std::string>{"大家好", "欢迎收看，今天的节目", "我们今天讲，天气★"});
        REQUIRE(timeline.warnings.size() == 2);
        CHECK(timeline.warnings[0].find("subs.srt:16:3: \"（笑）\" is a stage direction") == 0);
        CHECK(timeline.warnings[1].find("subs.srt:16:6: \"★\"") == 0);
    }

    TEST_CASE("WebVTT: identifiers, notes, cue settings, voices and cue timestamps unsaid") {
        const std::string vtt =
            "WEBVTT - a talk\n\nNOTE 这是注释\n\nc1\n00:00:01.000 --> 00:00:02.000 align:start\n"
            "<v 主持人>你好</v>\n\n00:00:02.000 --> 00:00:03.000\n再<00:00:02.500>见\n";
        const Timeline timeline = read_transcript_file(vtt, {}, "subs.vtt");
        CHECK(sentences(timeline) == std::vector<std::string>{"你好", "再见"});
        CHECK(timeline.warnings.empty());
    }

    TEST_CASE("a TextGrid: its sentences tier, else its words with a sentence at each long silence") {
        Timeline spoken = talkface::read_transcript("你好，世界。再见。");
        for (std::size_t k = 0; k < spoken.syllables.size(); ++k) {
            spoken.syllables[k].start_s = 0.5 * static_cast<double>(k);
            spoken.syllables[k].end_s = spoken.syllables[k].start_s + 0.4;
        }
        spoken.sentences[0] = {"你好，世界。", 0.0, 1.9};
        spoken.sentences[1] = {"再见。", 2.0, 2.9};
        spoken.duration_s = 3.0;
        talkface::ExportInput input;
        input.timeline = spoken;
        const Timeline from_sentences =
            read_transcript_file(talkface::export_to_string(input, "textgrid"), {}, "a.TextGrid");
        CHECK(sentences(from_sentences) == std::vector<std::string>{"你好，世界。", "再见。"});
        CHECK(said(from_sentences) == "你好世界再见");

        const std::string words = R"(File type = "ooTextFile"
Object class = "TextGrid"
0
3
<exists>
1
"IntervalTier"
"words"
0
3
4
0
0.5
"大家"
0.5
1
"好"
1
1.5
""
1.5
3
"欢迎★"
)";
        const Timeline from_words = read_transcript_file(words, {}, "w.TextGrid");
        CHECK(sentences(from_words) == std::vector<std::string>{"大家好", "欢迎★"});
        REQUIRE(from_words.warnings.size() == 1);
        CHECK(from_words.warnings[0].find("w.TextGrid:23:") == 0);
    }

    TEST_CASE("a malformed subtitle is refused naming its line, and a text with an arrow is no subtitle") {
        CHECK_THROWS_WITH_AS(
            read_transcript_file("1\n00:00:01,000 --> 00:00:02,000\n好\n\n2\nxx --> yy\n好\n", {}, "s.srt"),
            doctest::Contains("s.srt:6"), talkface::ParseError);
        CHECK(said(read_transcript_file("他说 --> 好。\n", {}, "t.txt")) == "他说好");
    }

    TEST_CASE("the same subtitles time the transcript read from them, their stage directions unsaid") {
        const Timeline transcript = read_transcript_file(kSubRip, {}, "subs.srt");
        const std::string without_symbol = std::string(kSubRip).substr(0, std::string(kSubRip).find("★"));
        const Timeline plain = read_transcript_file(without_symbol, {}, "subs.srt");
        const Timeline timed = talkface::read_timing_string(without_symbol, "srt", plain, 10.0, "subs.srt");
        REQUIRE(timed.syllables.size() == plain.syllables.size());
        CHECK(timed.syllables.back().text == "气");
        CHECK(timed.syllables.back().end_s == doctest::Approx(8.0));
        CHECK(transcript.syllables.size() == plain.syllables.size());
    }

    TEST_CASE("the file's encoding and options reach the reader") {
        talkface::TranscriptOptions options;
        options.keep_directions = true;
        CHECK(said(read_transcript_file(kSubRip, options, "subs.srt")) ==
              "大家好欢迎收看今天的节目我们今天讲天气笑");
        const std::string utf16 = std::string("\xFF\xFE\x60\x4F\x7D\x59", 6);  // 你好, UTF-16 LE
        CHECK(said(read_transcript_file(utf16, {}, "u.txt")) == "你好");
    }
}

// The imports: TextGrids as Praat and Montreal Forced Aligner write them, subtitles, word-time JSON;
// round trips through every format; refusals that name the file, the line and where the texts part.
#include <doctest/doctest.h>

#include <fstream>
#include <string>

#include "common/test_paths.hpp"

#include "talkface/errors.hpp"
#include "talkface/timing_formats.hpp"
#include "talkface/transcript.hpp"

using talkface::ParseError;
using talkface::Timeline;

namespace {

// 你好，世界。 spoken from 0.5 s, a syllable every 0.25 s, 2 s of audio.
Timeline transcript() { return talkface::read_transcript("你好，世界。再見。"); }

Timeline spoken() {
    Timeline timeline = transcript();
    for (std::size_t k = 0; k < timeline.syllables.size(); ++k) {
        timeline.syllables[k].start_s = 0.5 + 0.25 * static_cast<double>(k);
        timeline.syllables[k].end_s = timeline.syllables[k].start_s + 0.25;
    }
    timeline.sentences[0].start_s = 0.5;
    timeline.sentences[0].end_s = 1.5;
    timeline.sentences[1].start_s = 1.5;
    timeline.sentences[1].end_s = 2.0;
    timeline.duration_s = 2.5;
    return timeline;
}

std::string error_of(const std::string& text, const std::string& format, double duration_s = 2.5) {
    try {
        talkface::read_timing_string(text, format, transcript(), duration_s, "t");
    } catch (const ParseError& error) {
        return error.what();
    }
    return "(no error)";
}

// Montreal Forced Aligner's output: long text format, a "words" tier of characters and a "phones" tier.
const char* const kMfaTextGrid = R"(File type = "ooTextFile"
Object class = "TextGrid"

xmin = 0
xmax = 2.5
tiers? <exists>
size = 2
item []:
    item [1]:
        class = "IntervalTier"
        name = "words"
        xmin = 0
        xmax = 2.5
        intervals: size = 5
        intervals [1]:
            xmin = 0
            xmax = 0.5
            text = ""
        intervals [2]:
            xmin = 0.5
            xmax = 1.0
            text = "你好"
        intervals [3]:
            xmin = 1.0
            xmax = 1.5
            text = "世界"
        intervals [4]:
            xmin = 1.5
            xmax = 2.0
            text = "再見"
        intervals [5]:
            xmin = 2.0
            xmax = 2.5
            text = ""
    item [2]:
        class = "IntervalTier"
        name = "phones"
        xmin = 0
        xmax = 2.5
        intervals: size = 1
        intervals [1]:
            xmin = 0
            xmax = 2.5
            text = "sil"
)";

}  // namespace

TEST_SUITE("timing imports") {
    TEST_CASE("a Montreal Forced Aligner TextGrid times the words' syllables, sharing each word") {
        const Timeline timeline = talkface::read_timing_string(kMfaTextGrid, "textgrid", transcript(), 2.5, "mfa");
        REQUIRE(timeline.syllables.size() == 6);
        for (std::size_t k = 0; k < 6; ++k) {
            CAPTURE(k);
            CHECK(timeline.syllables[k].start_s == doctest::Approx(0.5 + 0.25 * static_cast<double>(k)));
            CHECK(timeline.syllables[k].end_s == doctest::Approx(0.75 + 0.25 * static_cast<double>(k)));
            CHECK_FALSE(timeline.syllables[k].final_start_s);
        }
        CHECK(timeline.sentences[1].start_s == 1.5);
        CHECK(timeline.sentences[1].end_s == 2.0);
        CHECK(timeline.duration_s == 2.5);
        CHECK(timeline.syllables[1].pause_after);  // the transcript's marks stay
    }

    TEST_CASE("the short text format and pinyin labels read the same") {
        const std::string short_grid =
            "File type = \"ooTextFile\"\nObject class = \"TextGrid\"\n\n0\n2.5\n<exists>\n1\n\"IntervalTier\"\n"
            "\"syllables\"\n0\n2.5\n6\n0.5\n0.75\n\"ni3\"\n0.75\n1\n\"hao\"\n1\n1.25\n\"SHI4\"\n1.25\n1.5\n\"jie4\"\n"
            "1.5\n1.75\n\"zai4\"\n1.75\n2\n\"jian4\"\n";
        const Timeline timeline = talkface::read_timing_string(short_grid, "textgrid", transcript(), 2.5, "g");
        CHECK(timeline.syllables[3].start_s == 1.25);
        CHECK(timeline.syllables[5].end_s == 2.0);
    }

    TEST_CASE("every format round trips the times it keeps") {
        const Timeline original = spoken();
        for (const char* format : {"textgrid", "words-json", "timeline-json", "vtt"}) {
            CAPTURE(format);
            const Timeline back = talkface::read_timing_string(talkface::write_timing_string(original, format), format,
                                                               transcript(), 2.5, "back");
            for (std::size_t k = 0; k < original.syllables.size(); ++k) {
                CAPTURE(k);
                CHECK(back.syllables[k].start_s == doctest::Approx(original.syllables[k].start_s));
                CHECK(back.syllables[k].end_s == doctest::Approx(original.syllables[k].end_s));
            }
        }
        const Timeline from_srt =
            talkface::read_timing_string(talkface::write_timing_string(original, "srt"), "srt", transcript(), 2.5, "s");
        CHECK(from_srt.sentences[0].start_s == 0.5);
        CHECK(from_srt.sentences[0].end_s == 1.5);
        CHECK(from_srt.sentences[1].start_s == 1.5);
        CHECK(from_srt.syllables[2].start_s == 1.0);  // four syllables share 0.5..1.5
    }

    TEST_CASE("a timing whose text parts from the transcript is refused, naming the first place") {
        CHECK(error_of(R"([{"text":"你好","start":0.5,"end":1},
{"text":"世間","start":1,"end":1.5}])",
                       "words-json") ==
              "t:2: \"世間\": \"間\" parts from the transcript at sentence 1 (\"你好，世界。\"), syllable 4 \"界\" "
              "(jie4): the transcript has \"界\" (jie4)");
        CHECK(error_of(R"([{"text":"你好世界","start":0.5,"end":1.5}])", "words-json") ==
              "t:1: the timing ends, but the transcript goes on at sentence 2 (\"再見。\"), syllable 1 \"再\" (zai4)");
        CHECK(error_of(R"([{"text":"你好世界再見啊","start":0.5,"end":2}])", "words-json").find(
                  "\"啊\" parts from the transcript at the end of the transcript") != std::string::npos);
        CHECK(error_of(R"([{"text":"ni3 hao3 shi4 jie4 zai4 jiang4","start":0.5,"end":2}])", "words-json")
                  .find("\"jiang4\" parts from the transcript at sentence 2") != std::string::npos);
    }

    TEST_CASE("times out of order, negative, backwards or past the audio are refused by line") {
        const std::string all = R"("text":"你好世界再見")";
        CHECK(error_of("[\n{" + all + R"(,"start":0.5,"end":3}])", "words-json") ==
              "t:2: \"你好世界再見\": ends at 3 s, past the end of the audio (2.5 s)");
        CHECK(error_of(R"([{"text":"你好","start":1,"end":1.5},
{"text":"世界再見","start":0.5,"end":1}])",
                       "words-json")
                  .find("t:2: \"世界再見\": starts at 0.5 s, before the one before it ends (1.5 s): times out of order") == 0);
        CHECK(error_of("[{" + all + R"(,"start":1,"end":0.5}])", "words-json").find("before it starts") !=
              std::string::npos);
        CHECK(error_of("[{" + all + R"(,"start":-1,"end":0.5}])", "words-json").find("expected times >= 0") !=
              std::string::npos);
    }

    TEST_CASE("a malformed file names the file, the line and what was expected") {
        std::string grid = kMfaTextGrid;
        grid.replace(grid.find("xmax = 1.0"), 10, "xmax = abc");
        CHECK(error_of(grid, "textgrid") == "t:21: expected an interval's xmax, found \"abc\"");
        CHECK(error_of("File type = \"ooTextFile\"\nObject class = \"Sound\"\n", "textgrid") ==
              "t:2: expected Object class = \"TextGrid\", found \"Sound\"");
        CHECK(error_of("1\n00:00:00,500 -> 00:00:01,500\n你好\n", "srt") ==
              "t:2: expected a cue's times, HH:MM:SS,mmm --> HH:MM:SS,mmm, found \"00:00:00,500 -> 00:00:01,500\"");
        CHECK(error_of("WEBVT\n\n00:00.500 --> 00:01.500\n你好\n", "vtt") ==
              "t:1: expected \"WEBVTT\" on the first line, found \"WEBVT\"");
        CHECK(error_of("[{\"text\": 1}]", "words-json") == "t:1:11: [0].text: expected a string, found 1");
        CHECK(error_of("[{\"text\": \"你\"\n \"start\": 1}]", "words-json").find("t:2:2: expected") == 0);
        CHECK(error_of(R"({"sentences":[],"syllables":[]})", "json").find("the timing ends, but the transcript goes on") !=
              std::string::npos);
    }

    TEST_CASE("a TextGrid without a syllables or words tier names the tiers it has") {
        std::string grid = kMfaTextGrid;
        grid.replace(grid.find("\"words\""), 7, "\"lexicon\"");
        CHECK(error_of(grid, "textgrid") == "t: expected an interval tier named \"syllables\" or \"words\" (or only "
                                            "one interval tier), found tiers \"lexicon\", \"phones\"");
    }

    TEST_CASE("WebVTT cue timestamps give the syllables' starts, markup and notes are skipped") {
        const std::string vtt = "WEBVTT - talkface\n\nNOTE made by hand\n\ncue-1\n00:00.500 --> 00:01.500 align:start\n"
                                "<v Ann>你<00:00:00.600>好，<00:00:01.000>世<00:00:01.100>界。</v>\n\n"
                                "00:00:01.500 --> 00:00:02.000\n再 見\n";
        const Timeline timeline = talkface::read_timing_string(vtt, "vtt", transcript(), 2.5, "v");
        CHECK(timeline.syllables[1].start_s == 0.6);
        CHECK(timeline.syllables[0].end_s == 0.6);
        CHECK(timeline.syllables[3].start_s == 1.1);
        CHECK(timeline.syllables[3].end_s == 1.5);
        CHECK(timeline.syllables[5].start_s == 1.75);
    }

    TEST_CASE("formats by suffix, and unknown names listed") {
        CHECK(talkface::timing_format_for_path("a.TextGrid") == "textgrid");
        CHECK(talkface::timing_format_for_path("a.json") == "json");
        CHECK_THROWS_WITH_AS(talkface::timing_format_for_path("a.lab"), doctest::Contains("\".lab\""),
                             talkface::InvalidArgument);
        CHECK_THROWS_WITH_AS(talkface::read_timing_string("", "ass", transcript(), 1.0), doctest::Contains("textgrid, srt"),
                             talkface::InvalidArgument);
    }

    TEST_CASE("a UTF-16 timing file reads as its UTF-8, and one of an odd number of bytes is refused, named") {
        // "words.json" in UTF-16 little endian with its byte order mark, as Windows Notepad saves it.
        const std::string json = R"([{"text":"你好世界再見","start":0.5,"end":2.0}])";
        std::u16string units;
        for (std::size_t k = 0; k < json.size();) {
            const auto byte = static_cast<unsigned char>(json[k]);
            const std::size_t length = byte < 0x80 ? 1 : 3;  // ASCII and the BMP's 3-byte characters only
            char32_t code = length == 1 ? byte : (byte & 0x0Fu) << 12 | (static_cast<unsigned char>(json[k + 1]) & 0x3Fu) << 6 |
                                                     (static_cast<unsigned char>(json[k + 2]) & 0x3Fu);
            units += static_cast<char16_t>(code);
            k += length;
        }
        std::string bytes = "\xFF\xFE";
        for (const char16_t unit : units) {
            bytes += static_cast<char>(unit & 0xFF);
            bytes += static_cast<char>(unit >> 8);
        }
        const auto write = [](const std::string& path, const std::string& content) {
            std::ofstream(path, std::ios::binary) << content;
        };
        const std::string whole = talkface::test::output_path("utf16_words.json");
        write(whole, bytes);
        const Timeline timeline = talkface::read_timing_file(whole, transcript(), 2.5);
        CHECK(timeline.syllables.front().start_s == 0.5);
        CHECK(timeline.syllables.back().end_s == 2.0);
        // One byte more: half a unit, which was dropped without a word before.
        const std::string odd = talkface::test::output_path("utf16_words_odd.json");
        write(odd, bytes + "\n");
        CHECK_THROWS_WITH_AS(talkface::read_timing_file(odd, transcript(), 2.5),
                             doctest::Contains((odd + ": not UTF-16: an odd number of bytes (" +
                                                std::to_string(bytes.size() + 1) + ", ").c_str()),
                             ParseError);
        // The TextGrid reader, which also reads strings as they are, refuses the same.
        CHECK(error_of(std::string("\xFE\xFF\x00", 3), "textgrid").find("t: not UTF-16: an odd number of bytes (3, ") == 0);
    }
}

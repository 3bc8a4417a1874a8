// The exports: Rhubarb's three formats byte for byte as its README shows them, Moho's switch data,
// the Live2D motion's counts and curves, the TextGrid, subtitles, and the choice of format.
#include <doctest/doctest.h>

#include <fstream>
#include <iterator>
#include <sstream>
#include <string>

#include "common/test_paths.hpp"
#include "talkface/errors.hpp"
#include "talkface/timing_formats.hpp"

using talkface::ExportInput;
using talkface::MouthKeyFrame;
using talkface::MouthShape;

namespace {

std::string read_text(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// Rhubarb README's "Hi": rest, then a (D) at 0.05, e (C) at 0.27, i (B) at 0.31, rest at 0.43; 0.47 s.
ExportInput hi() {
    ExportInput input;
    input.timeline.sentences.push_back({"嗨。", 0.05, 0.43});
    talkface::Syllable syllable;
    syllable.text = "嗨";
    syllable.pinyin = "hai1";
    syllable.start_s = 0.05;
    syllable.end_s = 0.43;
    input.timeline.syllables.push_back(syllable);
    input.timeline.duration_s = 0.4712;
    input.mouth_key_frames = {MouthKeyFrame{0.0, MouthShape::m, std::nullopt}, MouthKeyFrame{0.05, MouthShape::a, 0},
                              MouthKeyFrame{0.27, MouthShape::e, 0}, MouthKeyFrame{0.31, MouthShape::i, 0},
                              MouthKeyFrame{0.43, MouthShape::m, std::nullopt}};
    input.audio_path = "/home/daniel/av/hi/hi.wav";
    input.fps = 24.0;
    for (int frame = 0; frame <= 12; ++frame) {
        talkface::FaceState state;
        state.expression.blink_left = state.expression.blink_right = frame == 6 ? 1.0 : 0.0;
        state.pose.beta_deg = 0.5 * frame;
        input.frames.push_back(state);
    }
    return input;
}

}  // namespace

TEST_SUITE("timing exports") {
    TEST_CASE("the Rhubarb formats are the bytes of Rhubarb's own documented examples") {
        const ExportInput input = hi();
        CHECK(talkface::export_to_string(input, "rhubarb-tsv") ==
              read_text(talkface::test::source_path("tests/data/rhubarb/hi.tsv")));
        CHECK(talkface::export_to_string(input, "rhubarb-xml") ==
              read_text(talkface::test::source_path("tests/data/rhubarb/hi.xml")));
        CHECK(talkface::export_to_string(input, "rhubarb-json") ==
              read_text(talkface::test::source_path("tests/data/rhubarb/hi.json")));
    }

    TEST_CASE("every mouth shape has its documented Rhubarb letter, and a syllable's m is A, a rest X") {
        const std::pair<MouthShape, char> table[] = {
            {MouthShape::m, 'A'}, {MouthShape::f, 'G'}, {MouthShape::h_prime, 'B'}, {MouthShape::h, 'C'},
            {MouthShape::r, 'B'}, {MouthShape::z, 'B'}, {MouthShape::a, 'D'},       {MouthShape::i, 'B'},
            {MouthShape::u, 'F'}, {MouthShape::e, 'C'}, {MouthShape::o, 'E'},       {MouthShape::n, 'H'}};
        for (const auto& [shape, letter] : table) {
            CAPTURE(talkface::mouth_shape_name(shape));
            ExportInput input = hi();
            input.mouth_key_frames = {MouthKeyFrame{0.0, MouthShape::m, std::nullopt}, MouthKeyFrame{0.1, shape, 0}};
            CHECK(talkface::export_to_string(input, "rhubarb-tsv") == "0.00\tX\n0.10\t" + std::string(1, letter) +
                                                                          "\n0.47\tX\n");
        }
    }

    TEST_CASE("今 jin1 says i then n: no open C between them (ㄧㄣ has no vowel of its own)") {
        ExportInput input = hi();
        input.timeline.sentences = {{"今。", 0.1, 0.4}};
        input.timeline.syllables[0].text = "今";
        input.timeline.syllables[0].pinyin = "jin1";
        input.timeline.syllables[0].start_s = 0.1;
        input.timeline.syllables[0].end_s = 0.4;
        input.mouth_key_frames = talkface::mouth_key_frames(input.timeline);
        const std::string tsv = talkface::export_to_string(input, "rhubarb-tsv");
        CHECK(tsv.find("\tB\n") != std::string::npos);
        CHECK(tsv.find("\tH\n") != std::string::npos);
        CHECK(tsv.find("\tC\n") == std::string::npos);
    }

    TEST_CASE("Moho switch data numbers frames from 1 with Preston Blair names, and ends at rest") {
        ExportInput input = hi();
        CHECK(talkface::export_to_string(input, "moho") == "MohoSwitch1\n1 rest\n2 AI\n7 E\n8 etc\n11 rest\n12 rest\n");
        input.fps = 25.0;
        CHECK(talkface::export_to_string(input, "moho").rfind("12 rest\n") != std::string::npos);
    }

    TEST_CASE("a non-ASCII sound file is escaped as Rhubarb escapes it, by UTF-16 unit") {
        ExportInput input = hi();
        input.audio_path = "/錄音/\"說\"😀.wav";
        const std::string json = talkface::export_to_string(input, "rhubarb-json");
        CHECK(json.find("\"soundFile\": \"/\\u9304\\u97f3/\\\"\\u8aaa\\\"\\ud83d\\ude00.wav\"") != std::string::npos);
        const std::string xml = talkface::export_to_string(input, "rhubarb-xml");
        CHECK(xml.find("<soundFile>/錄音/&quot;說&quot;😀.wav</soundFile>") != std::string::npos);
    }

    TEST_CASE("the Live2D motion spans the audio and counts its curves, segments and points") {
        const std::string motion = talkface::export_to_string(hi(), "live2d");
        CHECK(motion.find("\"Version\": 3") != std::string::npos);
        CHECK(motion.find("\"Duration\": 0.4712") != std::string::npos);
        CHECK(motion.find("\"CurveCount\": 9") != std::string::npos);
        // Mouth: 5 key frames + the end = 6 points each; eyes: 0, 5/24, 6/24, 7/24, end = 5 each;
        // brows flat: 2 each; AngleX a straight line to frame 11 (frame 12 lies past the end), then
        // held to the end: 3; Y, Z flat: 2 each. 33 points, 33 - 9 curves = 24 segments.
        CHECK(motion.find("\"TotalPointCount\": 33") != std::string::npos);
        CHECK(motion.find("\"TotalSegmentCount\": 24") != std::string::npos);
        CHECK(motion.find("\"Segments\": [0, 0, 0, 0.4583, -5.5, 0, 0.4712, -5.5]") != std::string::npos);
        CHECK(motion.find("\"Id\": \"ParamMouthOpenY\",\n      \"Segments\": [0, 0, 0, 0.05, 1, 0, 0.27, 0.45, 0, 0.31, "
                          "0.15, 0, 0.43, 0, 0, 0.4712, 0]") != std::string::npos);
        CHECK(motion.find("\"Id\": \"ParamEyeLOpen\",\n      \"Segments\": [0, 1, 0, 0.2083, 1, 0, 0.25, 0, 0, 0.2917, "
                          "1, 0, 0.4712, 1]") != std::string::npos);
        ExportInput without_frames = hi();
        without_frames.frames.clear();
        CHECK_THROWS_WITH_AS(talkface::export_to_string(without_frames, "live2d"), doctest::Contains("frames"),
                             talkface::InvalidArgument);
    }

    TEST_CASE("the TextGrid tiles 0 to the end with sentence and pinyin intervals") {
        const std::string grid = talkface::export_to_string(hi(), "textgrid");
        CHECK(grid.rfind("File type = \"ooTextFile\"\nObject class = \"TextGrid\"\n\nxmin = 0 \nxmax = 0.4712 \n", 0) == 0);
        CHECK(grid.find("name = \"sentences\" \n        xmin = 0 \n        xmax = 0.4712 \n        intervals: size = 3 \n") !=
              std::string::npos);
        CHECK(grid.find("            xmin = 0.05 \n            xmax = 0.43 \n            text = \"hai1\" \n") !=
              std::string::npos);
    }

    TEST_CASE("subtitles: a cue per sentence, WebVTT with a timestamp before each later syllable") {
        ExportInput input = hi();
        input.timeline.sentences = {{"你好，世界。", 0.5, 1.5}};
        input.timeline.syllables.clear();
        const char* texts[] = {"你", "好", "世", "界"};
        for (int k = 0; k < 4; ++k) {
            talkface::Syllable syllable;
            syllable.text = texts[k];
            syllable.pinyin = "a1";
            syllable.start_s = 0.5 + 0.25 * k;
            syllable.end_s = syllable.start_s + 0.25;
            input.timeline.syllables.push_back(syllable);
        }
        input.timeline.duration_s = 2.0;
        CHECK(talkface::export_to_string(input, "srt") == "1\n00:00:00,500 --> 00:00:01,500\n你好，世界。\n");
        CHECK(talkface::export_to_string(input, "vtt") ==
              "WEBVTT\n\n1\n00:00:00.500 --> 00:00:01.500\n你<00:00:00.750>好，<00:00:01.000>世<00:00:01.250>界。\n");
    }

    TEST_CASE("the format comes from the suffix where it is plain, a plain .json or an unknown one is named") {
        CHECK(talkface::export_format_for_path("a/b.tsv") == "rhubarb-tsv");
        CHECK(talkface::export_format_for_path("b.xml") == "rhubarb-xml");
        CHECK(talkface::export_format_for_path("b.dat") == "moho");
        CHECK(talkface::export_format_for_path("b.motion3.json") == "live2d");
        CHECK(talkface::export_format_for_path("b.TextGrid") == "textgrid");
        CHECK(talkface::export_format_for_path("b.srt") == "srt");
        CHECK(talkface::export_format_for_path("b.vtt") == "vtt");
        CHECK_THROWS_WITH_AS(talkface::export_format_for_path("cues.json"), doctest::Contains("\"cues.json\""),
                             talkface::InvalidArgument);
        CHECK_THROWS_WITH_AS(talkface::export_format_for_path("a.xyz"),
                             doctest::Contains("no export format for suffix \".xyz\" on file \"a.xyz\"; the formats "
                                               "are rhubarb-tsv, rhubarb-json"),
                             talkface::InvalidArgument);
        CHECK_THROWS_WITH_AS(talkface::export_to_string(hi(), "lottie"), doctest::Contains("\"lottie\" is not"),
                             talkface::InvalidArgument);
    }

    TEST_CASE("an export with no audio length is refused, and nothing is written") {
        ExportInput input = hi();
        input.timeline.duration_s = 0.0;
        const std::string path = talkface::test::output_path("no_length.tsv");
        { std::ofstream(path) << "keep me"; }
        CHECK_THROWS_WITH_AS(talkface::export_to_file(path, input), doctest::Contains("duration_s"),
                             talkface::InvalidArgument);
        CHECK(read_text(path) == "keep me");
    }
}

// The timeline JSON: every field round trips bit for bit, the untimed form, the contract's keys,
// old documents without "version", and errors that name the line and the item.
#include <doctest/doctest.h>

#include <cmath>
#include <string>

#include "talkface/errors.hpp"
#include "talkface/timeline_json.hpp"

using talkface::ParseError;
using talkface::Timeline;

namespace {

// 你好，世界。 with awkward times (thirds, a denormal-free tiny value), every optional field set.
Timeline spoken_timeline() {
    Timeline timeline;
    timeline.sentences.push_back({"你好，世界。", 0.5, 1.0 + 1.0 / 3.0});
    const char* texts[] = {"你", "好", "世", "界"};
    const char* pinyin[] = {"ni3", "hao3", "shi4", "jie4"};
    for (int k = 0; k < 4; ++k) {
        talkface::Syllable syllable;
        syllable.text = texts[k];
        syllable.pinyin = pinyin[k];
        syllable.start_s = 0.5 + k / 3.0 * 0.25;
        syllable.end_s = syllable.start_s + 0.1 + 1e-9;
        timeline.syllables.push_back(syllable);
    }
    timeline.syllables[0].final_start_s = 0.58;
    timeline.syllables[1].confidence = 0.7500000000000001;
    timeline.syllables[1].pause_after = true;
    timeline.warnings = {"story.txt:1:7: \"A\": no reading, skipped", "a \"quoted\"\\ tab\t"};
    timeline.duration_s = 2.0 / 3.0 + 1.0;
    return timeline;
}

void check_equal(const Timeline& a, const Timeline& b) {
    REQUIRE(a.sentences.size() == b.sentences.size());
    for (std::size_t k = 0; k < a.sentences.size(); ++k) {
        CAPTURE(k);
        CHECK(a.sentences[k].text == b.sentences[k].text);
        CHECK(a.sentences[k].start_s == b.sentences[k].start_s);
        CHECK(a.sentences[k].end_s == b.sentences[k].end_s);
    }
    REQUIRE(a.syllables.size() == b.syllables.size());
    for (std::size_t k = 0; k < a.syllables.size(); ++k) {
        CAPTURE(k);
        const auto& x = a.syllables[k];
        const auto& y = b.syllables[k];
        CHECK(x.text == y.text);
        CHECK(x.pinyin == y.pinyin);
        CHECK(x.sentence == y.sentence);
        CHECK(x.start_s == y.start_s);
        CHECK(x.end_s == y.end_s);
        CHECK(x.final_start_s == y.final_start_s);
        CHECK(x.confidence == y.confidence);
        CHECK(x.pause_after == y.pause_after);
    }
    CHECK(a.warnings == b.warnings);
    CHECK(a.duration_s == b.duration_s);
    REQUIRE(a.written_forms.size() == b.written_forms.size());
    for (std::size_t k = 0; k < a.written_forms.size(); ++k) {
        CAPTURE(k);
        CHECK(a.written_forms[k].text == b.written_forms[k].text);
        CHECK(a.written_forms[k].first_syllable == b.written_forms[k].first_syllable);
        CHECK(a.written_forms[k].syllable_count == b.written_forms[k].syllable_count);
    }
}

std::string error_of(const std::string& text) {
    try {
        talkface::timeline_from_json(text, "t.json");
    } catch (const ParseError& error) {
        return error.what();
    }
    return "(no error)";
}

}  // namespace

TEST_SUITE("timeline JSON") {
    TEST_CASE("every field round trips bit for bit, and writing again gives the same bytes") {
        const Timeline timeline = spoken_timeline();
        const std::string json = talkface::timeline_to_json(timeline);
        const Timeline back = talkface::timeline_from_json(json);
        check_equal(timeline, back);
        CHECK(talkface::timeline_to_json(back) == json);
    }

    TEST_CASE("the document has the contract's keys in order, one item per line") {
        const std::string json = talkface::timeline_to_json(spoken_timeline());
        CHECK(json.rfind("{\"version\":1,\n\"sentences\":[\n{\"text\":\"你好，世界。\",\"start\":0.5,\"end\":", 0) == 0);
        CHECK(json.find("\n{\"text\":\"你\",\"pinyin\":\"ni3\",\"start\":0.5,\"end\":0.600000001,\"sentence\":0,"
                        "\"final_start\":0.58,\"confidence\":1,\"pause_after\":false},\n") != std::string::npos);
        CHECK(json.find("\"confidence\":0.7500000000000001,\"pause_after\":true}") != std::string::npos);
        CHECK(json.find("\"a \\\"quoted\\\"\\\\ tab\\u0009\"") != std::string::npos);
        CHECK(json.back() == '\n');
    }

    TEST_CASE("without times, only the transcript's items and the pause marks are written") {
        talkface::TimelineJsonOptions options;
        options.with_times = false;
        const std::string json = talkface::timeline_to_json(spoken_timeline(), options);
        CHECK(json.find("\"start\"") == std::string::npos);
        CHECK(json.find("\"confidence\"") == std::string::npos);
        CHECK(json.find("\"duration\"") == std::string::npos);
        CHECK(json.find("{\"text\":\"好\",\"pinyin\":\"hao3\",\"sentence\":0,\"pause_after\":true}") != std::string::npos);
        const Timeline back = talkface::timeline_from_json(json);
        CHECK(back.syllables[1].pause_after);
        CHECK(back.syllables[1].start_s == 0.0);
        CHECK(back.syllables[1].confidence == 1.0);
    }

    TEST_CASE("a document without a version, as talkface wrote before, reads as version 1") {
        const Timeline timeline = talkface::timeline_from_json(
            R"({"sentences":[{"text":"好。","start":0.5,"end":0.75}],
                "syllables":[{"text":"好","pinyin":"hao3","start":0.5,"end":0.75,"sentence":0,"final_start":null,
                              "future_key":[1,2]}]})");
        REQUIRE(timeline.syllables.size() == 1);
        CHECK_FALSE(timeline.syllables[0].final_start_s);
        CHECK(timeline.duration_s == 0.0);
    }

    TEST_CASE("a newer version is refused by name, with the version this build reads") {
        const std::string message = error_of("{\"version\": 2, \"sentences\": [], \"syllables\": []}");
        CHECK(message == "t.json:1:13: version: timeline JSON version 2 is newer than this talkface reads (version "
                         "1); update talkface to read it");
        CHECK(error_of("{\"version\": \"1\", \"sentences\": [], \"syllables\": []}").find("expected a whole number") !=
              std::string::npos);
    }

    TEST_CASE("errors name the file, the line of the item and what was expected") {
        CHECK(error_of("{\"sentences\": [}") == "t.json:1:16: not JSON: expected a value (a number, string, list, "
                                                "object, true, false or null)");
        CHECK(error_of("{\"sentences\": []}") == "t.json:1:1: document: \"syllables\" is missing");
        CHECK(error_of("[]") == "t.json:1:1: document: expected a timeline object {\"sentences\": ..., ...}, found a "
                                "list of 0");
        const std::string head = "{\"sentences\":[{\"text\":\"a\"}],\n\"syllables\":[\n";
        CHECK(error_of(head + R"({"text":"a","pinyin":"a1","sentence":0,"start":"x"}]})") ==
              "t.json:3:48: syllables[0].start: expected a number of seconds, found \"x\"");
        CHECK(error_of(head + R"({"text":"a","pinyin":"a1","sentence":1}]})") ==
              "t.json:3:38: syllables[0].sentence: expected a sentence index 0..0, found 1");
        CHECK(error_of(head + R"({"text":"a","pinyin":"a1","sentence":0.5}]})") ==
              "t.json:3:38: syllables[0].sentence: expected a sentence index 0..0, found 0.5");
        CHECK(error_of(head + R"({"text":"a","sentence":0}]})") == "t.json:3:1: syllables[0]: \"pinyin\" is missing");
        CHECK(error_of(head + R"({"text":"a","pinyin":"a1","sentence":0,"start":-1}]})") ==
              "t.json:3:48: syllables[0].start: expected seconds >= 0, found -1");
        CHECK(error_of(head + R"({"text":"a","pinyin":"a1","sentence":0,"start":2,"end":1}]})") ==
              "t.json:3:1: syllables[0]: ends at 1 s, before it starts (2 s)");
        CHECK(error_of(head + R"({"text":"a","pinyin":"a1","sentence":0,"confidence":2}]})") ==
              "t.json:3:53: syllables[0].confidence: expected a number 0..1, found 2");
        CHECK(error_of(head + R"({"text":"a","pinyin":"a1","sentence":0,"pause_after":1}]})") ==
              "t.json:3:54: syllables[0].pause_after: expected true or false, found 1");
        CHECK(error_of(head + R"(], "warnings": [3]})") == "t.json:3:17: warnings[0]: expected a string, found 3");
        CHECK(error_of(head + R"(], "duration": "long"})") ==
              "t.json:3:16: document.duration: expected a number of seconds, found \"long\"");
    }

    TEST_CASE("written forms round trip beside their syllables, with times and without") {
        Timeline timeline = spoken_timeline();
        timeline.written_forms = {{"2\"6", 0, 2}, {"AI", 3, 1}};
        for (const bool with_times : {true, false}) {
            CAPTURE(with_times);
            talkface::TimelineJsonOptions options;
            options.with_times = with_times;
            const std::string json = talkface::timeline_to_json(timeline, options);
            CHECK(json.find("\"written_forms\":[\n{\"text\":\"2\\\"6\",\"first_syllable\":0,\"syllable_count\":2},\n"
                            "{\"text\":\"AI\",\"first_syllable\":3,\"syllable_count\":1}\n],\n") != std::string::npos);
            const Timeline back = talkface::timeline_from_json(json);
            REQUIRE(back.written_forms.size() == 2);
            CHECK(back.written_forms[1].text == "AI");
            CHECK(talkface::timeline_to_json(back, options) == json);
        }
        CHECK(talkface::timeline_to_json(spoken_timeline()).find("written_forms") == std::string::npos);
    }

    TEST_CASE("generic speech is written only where a syllable is, and reads back") {
        Timeline timeline = spoken_timeline();
        timeline.syllables[1].generic_speech = true;
        const std::string json = talkface::timeline_to_json(timeline);
        CHECK(json.find("\"generic_speech\":true") != std::string::npos);
        CHECK(json.find("\"generic_speech\":true") == json.rfind("\"generic_speech\""));
        const Timeline back = talkface::timeline_from_json(json);
        for (std::size_t i = 0; i < back.syllables.size(); ++i) CHECK(back.syllables[i].generic_speech == (i == 1));
        CHECK(talkface::timeline_to_json(spoken_timeline()).find("generic_speech") == std::string::npos);
    }

    TEST_CASE("a written form outside the syllables or out of order is refused by item") {
        const std::string head = "{\"sentences\":[{\"text\":\"a\"}],\n\"syllables\":[\n"
                                 R"({"text":"a","pinyin":"a1","sentence":0},{"text":"a","pinyin":"a1","sentence":0}],)"
                                 "\n\"written_forms\":[";
        CHECK(error_of(head + R"({"text":"x","first_syllable":1,"syllable_count":2}]})") ==
              "t.json:4:18: written_forms[0]: covers syllables 1..2, expected a stretch of the 2 syllables from 0 on "
              "(forms come in order, apart)");
        CHECK(error_of(head + R"({"text":"x","first_syllable":1,"syllable_count":1},)"
                              R"({"text":"y","first_syllable":0,"syllable_count":1}]})")
                  .find("written_forms[1]: covers syllables 0..0") != std::string::npos);
        CHECK(error_of(head + R"({"text":"x","first_syllable":0,"syllable_count":0}]})") ==
              "t.json:4:66: written_forms[0].syllable_count: expected a whole number >= 1, found 0");
        CHECK(error_of(head + R"({"first_syllable":0,"syllable_count":1}]})") ==
              "t.json:4:18: written_forms[0]: \"text\" is missing");
    }

    TEST_CASE("mismatches of a lenient alignment round trip, a document without times has none") {
        Timeline timeline = spoken_timeline();
        timeline.mismatches = {{0.5, 0.5 + 1.0 / 3.0, 1, 2, "好\"世", {}}, {1.25, 1.25, 4, 0, "", {}}};
        const std::string json = talkface::timeline_to_json(timeline);
        CHECK(json.find("\"mismatches\":[\n{\"start\":0.5,\"end\":0.8333333333333333,\"first_syllable\":1,"
                        "\"syllable_count\":2,\"expected\":\"好\\\"世\"},\n") != std::string::npos);
        const Timeline back = talkface::timeline_from_json(json);
        REQUIRE(back.mismatches.size() == 2);
        CHECK(back.mismatches[0].end_s == timeline.mismatches[0].end_s);
        CHECK(back.mismatches[0].expected_text == "好\"世");
        CHECK(back.mismatches[1].first_syllable == 4);
        CHECK(back.mismatches[1].syllable_count == 0);
        CHECK(talkface::timeline_to_json(back) == json);
        talkface::TimelineJsonOptions without_times;
        without_times.with_times = false;
        CHECK(talkface::timeline_to_json(timeline, without_times).find("mismatches") == std::string::npos);
        CHECK(talkface::timeline_to_json(spoken_timeline()).find("mismatches") == std::string::npos);
        const std::string head = "{\"sentences\":[{\"text\":\"a\"}],\n\"syllables\":[\n"
                                 R"({"text":"a","pinyin":"a1","sentence":0}],)"
                                 "\n\"mismatches\":[";
        CHECK(error_of(head + R"({"start":1,"end":2,"first_syllable":1,"syllable_count":1,"expected":"b"}]})")
                  .find("mismatches[0]: stands for syllables from 1 (1 of them), past the 1 syllables") != std::string::npos);
        CHECK(error_of(head + R"({"start":2,"end":1,"first_syllable":0,"syllable_count":1,"expected":"b"}]})")
                  .find("mismatches[0]: ends at 1 s, before it starts (2 s)") != std::string::npos);
    }

    TEST_CASE("a mismatch's loudness round trips exactly and is refused outside 0..1") {
        Timeline timeline = spoken_timeline();
        // Values as the aligner rounds them, and one it could not give: every double comes back.
        timeline.mismatches = {{0.5, 0.58, 1, 1, "好", {0.0, 0.07, 0.29, 1.0}}, {0.9, 0.94, 2, 0, "", {1.0 / 3.0, 0.5}}};
        const std::string json = talkface::timeline_to_json(timeline);
        CHECK(json.find("\"expected\":\"好\",\"loudness\":[0,0.07,0.29,1]}") != std::string::npos);
        const Timeline back = talkface::timeline_from_json(json);
        REQUIRE(back.mismatches.size() == 2);
        CHECK(back.mismatches[0].loudness == timeline.mismatches[0].loudness);
        CHECK(back.mismatches[1].loudness == timeline.mismatches[1].loudness);
        CHECK(talkface::timeline_to_json(back) == json);
        const std::string head = "{\"sentences\":[{\"text\":\"a\"}],\n\"syllables\":[\n"
                                 R"({"text":"a","pinyin":"a1","sentence":0}],)"
                                 "\n\"mismatches\":[";
        CHECK(error_of(head + R"({"start":1,"end":2,"first_syllable":0,"syllable_count":1,"expected":"a","loudness":[0.5,1.5]}]})")
                  .find("mismatches[0].loudness: expected a number 0..1, found 1.5") != std::string::npos);
        CHECK(error_of(head + R"({"start":1,"end":2,"first_syllable":0,"syllable_count":1,"expected":"a","loudness":0.5}]})")
                  .find("mismatches[0].loudness: expected a list of numbers 0..1, found 0.5") != std::string::npos);
    }

    TEST_CASE("a file is read and written whole, and a missing one is named") {
        CHECK_THROWS_WITH_AS(talkface::load_timeline_json("/no/such/dir/t.json"),
                             doctest::Contains("/no/such/dir/t.json"), talkface::FileError);
        const std::string path = std::string(TALKFACE_TEST_OUTPUT_DIR) + "/timeline_json_test.json";
        talkface::save_timeline_json(path, spoken_timeline());
        check_equal(talkface::load_timeline_json(path), spoken_timeline());
    }
}

// ExpressionStyle: validation naming the field, the style JSON (docs/style-format.md). What a style does to
// the simulation is in expression_simulator_test.cpp.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>

#include "talkface/errors.hpp"
#include "talkface/expression_simulator.hpp"

using namespace talkface;

TEST_SUITE("ExpressionStyle") {
    TEST_CASE("validate() names the first field out of range and what it expected") {
        CHECK_NOTHROW(ExpressionStyle::normal().validate());
        CHECK_NOTHROW(ExpressionStyle::announcer().validate());
        ExpressionStyle style;
        style.tilt_angle_deg = {2.0, 20.0};
        CHECK_THROWS_WITH_AS(
            style.validate(),
            doctest::Contains("ExpressionStyle::tilt_angle_deg: expected a range with 0 <= min "
                              "<= max <= 15, got [2, 20]"),
            InvalidArgument);
        style = ExpressionStyle{};
        style.nod_down_s = {0.0, 0.5};
        CHECK_THROWS_WITH_AS(style.validate(),
                             doctest::Contains("ExpressionStyle::nod_down_s: expected a range with 0 < min"),
                             InvalidArgument);
        style = ExpressionStyle{};
        style.brows_interval_s = {3.0, 1.0};
        CHECK_THROWS_WITH_AS(style.validate(), doctest::Contains("ExpressionStyle::brows_interval_s"),
                             InvalidArgument);
        style = ExpressionStyle{};
        style.blink_interval_shape = 17;
        CHECK_THROWS_WITH_AS(
            style.validate(),
            doctest::Contains(
                "ExpressionStyle::blink_interval_shape: expected an integer from 1 to 16, got 17"),
            InvalidArgument);
        style = ExpressionStyle{};
        style.blink_interval_scale_s = 0.0;
        CHECK_THROWS_WITH_AS(style.validate(), doctest::Contains("ExpressionStyle::blink_interval_scale_s"),
                             InvalidArgument);
        style = ExpressionStyle{};
        style.nod_min_pause_s = std::nan("");
        CHECK_THROWS_WITH_AS(style.validate(), doctest::Contains("ExpressionStyle::nod_min_pause_s"),
                             InvalidArgument);
        // The first field in declaration order is named when several are out of range.
        style.blink_duration_s = {-1.0, 0.0};
        CHECK_THROWS_WITH_AS(style.validate(), doctest::Contains("ExpressionStyle::blink_duration_s"),
                             InvalidArgument);
        CHECK_THROWS_AS(style.set_simulated(static_cast<ExpressionEventKind>(9), false), InvalidArgument);
    }

    TEST_CASE("JSON: to_json reads back as the same style, for the named ones and a changed one") {
        ExpressionStyle changed = ExpressionStyle::announcer();
        changed.name = "calm \"quoted\"";
        changed.blink_interval_shape = 3;
        changed.blink_interval_scale_s = 2.0 / 3.0;
        changed.turn_angle_deg = {0.1, 14.9};
        changed.is_brows_simulated = false;
        for (const ExpressionStyle& style :
             {ExpressionStyle::normal(), ExpressionStyle::announcer(), changed}) {
            CAPTURE(style.name);
            const std::string json = style.to_json();
            CHECK(ExpressionStyle::from_json(json) == style);
            CHECK(style.to_json() == json);
        }
        CHECK(ExpressionStyle::normal() != changed);
        CHECK(ExpressionStyle::normal().to_json().find("\"blink_duration_s\": [0.15, 0.3],\n") !=
              std::string::npos);
    }

    TEST_CASE("JSON: every key is optional, starting from normal or from the base") {
        const ExpressionStyle empty = ExpressionStyle::from_json("{}");
        ExpressionStyle expected = ExpressionStyle::normal();
        expected.name = "custom";
        CHECK(empty == expected);

        const ExpressionStyle based = ExpressionStyle::from_json(
            "{\"is_nod_simulated\": false, \"tilt_angle_deg\": [1, 2], \"base\": \"announcer\", \"name\": "
            "\"mine\"}");
        expected = ExpressionStyle::announcer();
        expected.name = "mine";
        expected.is_nod_simulated = false;
        expected.tilt_angle_deg = {1.0, 2.0};
        CHECK(based == expected);
    }

    TEST_CASE("JSON: errors name the source, line, column and key") {
        CHECK_THROWS_WITH_AS(
            ExpressionStyle::from_json("{\n  \"blink_scale\": 2\n}", "style.json"),
            doctest::Contains("style.json:2:3: key \"blink_scale\": unknown key; the keys are base, name, "
                              "blink_interval_shape,"),
            ParseError);
        CHECK_THROWS_WITH_AS(
            ExpressionStyle::from_json("{\"tilt_angle_deg\": 3}", "style.json"),
            doctest::Contains(
                "style.json:1:20: key \"tilt_angle_deg\": expected [min, max], a list of two numbers, "
                "found 3"),
            ParseError);
        CHECK_THROWS_WITH_AS(ExpressionStyle::from_json("{\"tilt_angle_deg\": [1, 2, 3]}", "style.json"),
                             doctest::Contains("key \"tilt_angle_deg\": expected [min"), ParseError);
        CHECK_THROWS_WITH_AS(
            ExpressionStyle::from_json("{\"blink_interval_shape\": 2.5}", "style.json"),
            doctest::Contains("key \"blink_interval_shape\": expected a whole number, found 2.5"),
            ParseError);
        CHECK_THROWS_WITH_AS(
            ExpressionStyle::from_json("{\"is_blink_simulated\": 0}", "style.json"),
            doctest::Contains("key \"is_blink_simulated\": expected true or false, found 0"),
            ParseError);
        CHECK_THROWS_WITH_AS(ExpressionStyle::from_json("{\"nod_min_pause_s\": \"0.2\"}", "style.json"),
                             doctest::Contains("key \"nod_min_pause_s\": expected a number, found \"0.2\""),
                             ParseError);
        CHECK_THROWS_WITH_AS(
            ExpressionStyle::from_json("{\"turn_angle_deg\": [2, 20]}", "style.json"),
            doctest::Contains(
                "style.json:1:20: key \"turn_angle_deg\": expected a range with 0 <= min <= max <= 15, "
                "got [2, 20]"),
            ParseError);
        CHECK_THROWS_WITH_AS(
            ExpressionStyle::from_json("{\"base\": \"shouty\"}", "style.json"),
            doctest::Contains(
                "key \"base\": expression style \"shouty\": expected \"normal\" or \"announcer\""),
            ParseError);
        CHECK_THROWS_WITH_AS(ExpressionStyle::from_json("{\"name\": \"a\", \"name\": \"b\"}", "style.json"),
                             doctest::Contains("style.json:1:15: key \"name\": given twice"), ParseError);
        CHECK_THROWS_WITH_AS(ExpressionStyle::from_json("[1, 2]", "style.json"),
                             doctest::Contains("style.json:1:1: expected a style object"), ParseError);
        CHECK_THROWS_WITH_AS(ExpressionStyle::from_json("{\"nod_up_s\": [0.3, 0.5],}", "style.json"),
                             doctest::Contains("style.json:1:25: expected a key in quotes"), ParseError);
        CHECK_THROWS_WITH_AS(ExpressionStyle::from_json("{\"nod_up_s\": [0.3 0.5]}", "style.json"),
                             doctest::Contains("style.json:1:19: expected ','"), ParseError);
        CHECK_THROWS_WITH_AS(ExpressionStyle::from_json("{\"name\": \"x\"} x", "style.json"),
                             doctest::Contains("style.json:1:15: unexpected text"), ParseError);
        CHECK_THROWS_WITH_AS(ExpressionStyle::from_json("", "style.json"),
                             doctest::Contains("style.json:1:1: not JSON"), ParseError);
        CHECK_THROWS_WITH_AS(ExpressionStyle::from_json(std::string(100, '['), "style.json"),
                             doctest::Contains("nested too deeply"), ParseError);
    }

    TEST_CASE("JSON: strings are unescaped, numbers read in any JSON form") {
        const ExpressionStyle style = ExpressionStyle::from_json(
            "{\"name\": \"\\u5e73\\u975c \\\"calm\\\"\\n\\ud83d\\ude00\", \"blink_interval_scale_s\": 2.5e0, "
            "\"nod_min_pause_s\": -0e0, \"blink_duration_s\": [1E-1, 0.25]}");
        CHECK(style.name == "\xe5\xb9\xb3\xe9\x9d\x9c \"calm\"\n\xf0\x9f\x98\x80");
        CHECK(style.blink_interval_scale_s == 2.5);
        CHECK(style.nod_min_pause_s == 0.0);
        CHECK(style.blink_duration_s == UniformRange{0.1, 0.25});
        CHECK(ExpressionStyle::from_json(style.to_json()) == style);
    }

    TEST_CASE("load reads a file and names it, and a missing file is a FileError") {
        const std::string path = "expression_style_test_style.json";
        {
            std::ofstream out(path);
            out << "{\"base\": \"announcer\",\n \"brows_amount\": [0.2, 1.5]}\n";
        }
        CHECK_THROWS_WITH_AS(
            ExpressionStyle::load(path),
            doctest::Contains((path + ":2:18: key \"brows_amount\": expected a range with 0 <= min "
                                      "<= max <= 1")
                                  .c_str()),
            ParseError);
        std::remove(path.c_str());
        CHECK_THROWS_WITH_AS(ExpressionStyle::load(path), doctest::Contains(path.c_str()), FileError);
    }
}

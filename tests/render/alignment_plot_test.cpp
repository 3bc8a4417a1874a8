// The alignment picture (thesis Figures 3.5 and 3.8): read back as XML, checked for what a reader
// of the figure relies on.
#include <doctest/doctest.h>
#include <pugixml.hpp>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include "talkface/alignment_plot.hpp"
#include "talkface/errors.hpp"
#include "common/test_paths.hpp"

using namespace talkface;

namespace {

// Two sentences of a tone each, the second louder, with silence around them.
constexpr int kRateHz = 8000;

std::vector<float> two_tones() {
    std::vector<float> samples(4 * kRateHz, 0.0f);
    for (int i = 0; i < kRateHz; ++i) {
        samples[static_cast<std::size_t>(kRateHz / 2 + i)] = 0.25f * static_cast<float>(std::sin(0.3 * i));
        samples[static_cast<std::size_t>(2 * kRateHz + i)] = 0.5f * static_cast<float>(std::sin(0.3 * i));
    }
    return samples;
}

Timeline two_sentence_timeline() {
    Timeline timeline;
    timeline.sentences = {{"<b>甲</b>", 0.5, 1.5}, {"乙&丙", 2.0, 3.0}};
    Syllable first;
    first.text = "甲";
    first.pinyin = "jia3";
    first.start_s = 0.5;
    first.end_s = 1.5;
    first.final_start_s = 0.6;
    Syllable second = first;
    second.text = "乙";
    second.pinyin = "yi3";
    second.sentence = 1;
    second.start_s = 2.0;
    second.end_s = 3.0;
    second.final_start_s.reset();
    timeline.syllables = {first, second};
    timeline.duration_s = 4.0;
    return timeline;
}

pugi::xml_document parse(const std::string& svg) {
    pugi::xml_document document;
    REQUIRE(document.load_string(svg.c_str()));
    return document;
}

}  // namespace

TEST_CASE("the alignment plot draws each sentence, syllable and second, with escaped text") {
    const std::vector<float> samples = two_tones();
    const std::string svg = alignment_plot_svg(AudioView{samples.data(), samples.size(), 1, kRateHz},
                                               two_sentence_timeline());
    const pugi::xml_document document = parse(svg);
    const pugi::xml_node root = document.child("svg");
    CHECK(root.attribute("width").as_double() == doctest::Approx(800.0));  // 200 px a second

    std::vector<std::string> titles;
    for (const auto& rect : root.children("rect"))
        if (rect.child("title")) titles.emplace_back(rect.child_value("title"));
    CHECK(titles == std::vector<std::string>{"1: <b>甲</b>", "2: 乙&丙"});
    CHECK(svg.find("<b>") == std::string::npos);

    int solid = 0, dotted = 0, seconds = 0;
    for (const auto& text : root.children("text"))
        if (std::string(text.child_value()).find(" s") != std::string::npos) ++seconds;
    for (const auto& line : root.children("line")) {
        if (std::string(line.attribute("stroke").value()) != "#333333") continue;
        (line.attribute("stroke-dasharray") ? dotted : solid)++;
    }
    CHECK(solid == 2);
    CHECK(dotted == 1);  // only the syllable with a measured final
    CHECK(seconds == 5);
}

TEST_CASE("a syllable of low confidence is marked red, the others are not") {
    const std::vector<float> samples = two_tones();
    Timeline timeline = two_sentence_timeline();
    timeline.syllables[1].confidence = kLowAlignmentConfidence - 0.01;
    const std::string svg = alignment_plot_svg(AudioView{samples.data(), samples.size(), 1, kRateHz}, timeline);
    const pugi::xml_document document = parse(svg);
    std::vector<std::string> marked;
    for (const auto& rect : document.child("svg").children("rect"))
        if (std::string(rect.attribute("fill").value()) == "#d62728") marked.emplace_back(rect.child_value("title"));
    REQUIRE(marked.size() == 1);
    CHECK(marked[0] == "乙 yi3: confidence 0.49, below 0.5: check its place");
    int red_lines = 0, red_labels = 0;
    for (const auto& line : document.child("svg").children("line"))
        red_lines += std::string(line.attribute("stroke").value()) == "#d62728";
    for (const auto& text : document.child("svg").children("text"))
        if (std::string(text.attribute("fill").value()) == "#d62728") {
            ++red_labels;
            CHECK(std::string(text.child_value()) == "乙 yi3");
        }
    CHECK(red_lines == 1);
    CHECK(red_labels == 1);
    // At the threshold a syllable is not doubtful.
    timeline.syllables[1].confidence = kLowAlignmentConfidence;
    CHECK(alignment_plot_svg(AudioView{samples.data(), samples.size(), 1, kRateHz}, timeline).find("#d62728") ==
          std::string::npos);
}

TEST_CASE("the waveform follows the audio and takes its sentence's colour") {
    const std::vector<float> samples = two_tones();
    const std::string svg = alignment_plot_svg(AudioView{samples.data(), samples.size(), 1, kRateHz},
                                               two_sentence_timeline());
    const pugi::xml_document document = parse(svg);
    // Column x covers the audio around x / 200 seconds; its height is the envelope's.
    auto column = [&](double time_s) {
        const double x = std::floor(time_s * 200.0) + 0.5;
        for (const auto& line : document.child("svg").children("line"))
            if (line.attribute("x1").as_double() == x && std::string(line.attribute("stroke").value()) != "#333333" &&
                line.attribute("y2").as_double() <= 220.0)
                return line;
        return pugi::xml_node();
    };
    auto height = [](const pugi::xml_node& line) {
        return line.attribute("y2").as_double() - line.attribute("y1").as_double();
    };
    const pugi::xml_node silent = column(0.2), quiet = column(1.0), loud = column(2.5);
    REQUIRE(silent);
    REQUIRE(quiet);
    REQUIRE(loud);
    CHECK(height(silent) < 1.0);
    CHECK(height(loud) == doctest::Approx(160.0).epsilon(0.02));  // the peak fills the band
    CHECK(height(quiet) == doctest::Approx(80.0).epsilon(0.05));
    CHECK(std::string(silent.attribute("stroke").value()) == "#9a9a9a");
    CHECK(std::string(quiet.attribute("stroke").value()) == "#2a6fdb");
    CHECK(std::string(loud.attribute("stroke").value()) == "#2e9e4f");
}

TEST_CASE("a plot of unreadable audio names the file and writes nothing") {
    const std::string out = test::output_path("alignment_plot_unreadable.svg");
    std::remove(out.c_str());
    const std::string not_audio = test::output_path("alignment_plot_not_audio.wav");
    std::ofstream(not_audio) << "not audio at all";
    CHECK_THROWS_WITH_AS(write_alignment_plot_svg(out, not_audio, two_sentence_timeline()),
                         doctest::Contains("alignment_plot_not_audio.wav"), Error);
    CHECK_FALSE(std::ifstream(out).good());
    CHECK_THROWS_AS(alignment_plot_svg(AudioView{nullptr, 10, 1, kRateHz}, two_sentence_timeline()), InvalidArgument);
}

TEST_CASE("the plot of a committed clip is written whole") {
    const std::string out = test::output_path("alignment_plot_clip.svg");
    Timeline timeline = two_sentence_timeline();
    timeline.duration_s = 4.45;
    write_alignment_plot_svg(out, test::source_path("tests/data/speech/two_sentences.wav"), timeline);
    pugi::xml_document document;
    REQUIRE(document.load_file(out.c_str()));
    CHECK(document.child("svg").attribute("width").as_double() == doctest::Approx(890.0));
}

// The temporal half of SvgAnimator (thesis 6.3.2) and the web page (chapter 7): both encodings read
// back as XML, the key frames checked against every frame, and pages whose caller texts stay text.
#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <pugixml.hpp>

#include "common/test_paths.hpp"
#include "talkface/animation.hpp"
#include "talkface/errors.hpp"
#include "talkface/expression_simulator.hpp"
#include "talkface/face_model.hpp"
#include "talkface/svg_animator.hpp"
#include "talkface/transcript.hpp"
#include "talkface/web_page.hpp"

using namespace talkface;

namespace {

const std::string kHostile = "</script><img src=x onerror=alert(1)>\"'&";

// "媽媽好，你好。" spoken from 0.5 s at 4 syllables a second, 3 s of audio.
Timeline spoken_timeline() {
    Timeline timeline = read_transcript("媽媽好，你好。");
    for (std::size_t k = 0; k < timeline.syllables.size(); ++k) {
        timeline.syllables[k].start_s = 0.5 + 0.25 * static_cast<double>(k) + (k >= 3 ? 0.5 : 0.0);
        timeline.syllables[k].end_s = timeline.syllables[k].start_s + 0.25;
    }
    timeline.sentences[0].start_s = 0.5;
    timeline.sentences[0].end_s = timeline.syllables.back().end_s;
    timeline.duration_s = 3.0;
    return timeline;
}

Animation spoken_animation(const FaceModel& face, const Timeline& timeline) {
    const ExpressionSimulator simulator(timeline, 11);
    return animate(face, timeline, simulator);
}

pugi::xml_document parse(const std::string& text) {
    pugi::xml_document document;
    const pugi::xml_parse_result result = document.load_string(text.c_str());
    REQUIRE_MESSAGE(result, result.description());
    return document;
}

std::vector<double> numbers_of(const std::string& text) {
    std::vector<double> numbers;
    const char* p = text.c_str();
    while (*p != '\0') {
        char* end = nullptr;
        const double value = std::strtod(p, &end);
        if (end == p) {
            ++p;
        } else {
            numbers.push_back(value);
            p = end;
        }
    }
    return numbers;
}

std::vector<std::string> split(const std::string& text, char separator) {
    std::vector<std::string> parts;
    std::stringstream in(text);
    for (std::string part; std::getline(in, part, separator);) parts.push_back(part);
    return parts;
}

// The value an <animate> gives at key time `t` (0..1), interpolated linearly, as numbers.
std::vector<double> animated_numbers(const pugi::xml_node& animate, double t) {
    const std::vector<std::string> values = split(animate.attribute("values").value(), ';');
    const std::vector<std::string> times = split(animate.attribute("keyTimes").value(), ';');
    std::size_t k = 0;
    while (k + 2 < times.size() && std::stod(times[k + 1]) <= t) ++k;
    const double t0 = std::stod(times[k]);
    const double t1 = std::stod(times[k + 1]);
    const double u = t1 > t0 ? std::min(1.0, std::max(0.0, (t - t0) / (t1 - t0))) : 0.0;
    const std::vector<double> a = numbers_of(values[k]);
    const std::vector<double> b = numbers_of(values[k + 1]);
    std::vector<double> result(a.size());
    for (std::size_t i = 0; i < a.size(); ++i) result[i] = a[i] + u * (b[i] - a[i]);
    return result;
}

// A 2D affine map [a c e; b d f] as (a, b, c, d, e, f), the order of SVG's matrix().
using Affine = std::array<double, 6>;

Affine multiply(const Affine& m, const Affine& n) {
    return {m[0] * n[0] + m[2] * n[1], m[1] * n[0] + m[3] * n[1], m[0] * n[2] + m[2] * n[3],
            m[1] * n[2] + m[3] * n[3], m[0] * n[4] + m[2] * n[5] + m[4], m[1] * n[4] + m[3] * n[5] + m[5]};
}

Affine transform_of(const std::string& type, const std::vector<double>& v) {
    const double radians = 3.14159265358979323846 / 180.0;
    if (type == "translate") return {1, 0, 0, 1, v[0], v.size() > 1 ? v[1] : 0.0};
    if (type == "rotate") return {std::cos(v[0] * radians), std::sin(v[0] * radians), -std::sin(v[0] * radians),
                                  std::cos(v[0] * radians), 0, 0};
    if (type == "skewX") return {1, 0, std::tan(v[0] * radians), 1, 0, 0};
    if (type == "scale") return {v[0], 0, 0, v.size() > 1 ? v[1] : v[0], 0, 0};
    FAIL("unexpected transform " << type);
    return {};
}

// The points a polygon shows at key time `t`: its points (or their <animate> interpolated) under its
// transform and every <animateTransform> (additive="sum": each multiplies on the right).
std::vector<double> polygon_points_at(const pugi::xml_node& polygon, double t) {
    const pugi::xml_node animate = polygon.child("animate");
    std::vector<double> points =
        animate ? animated_numbers(animate, t) : numbers_of(polygon.attribute("points").value());
    Affine map{1, 0, 0, 1, 0, 0};
    const std::string base = polygon.attribute("transform").value();
    if (!base.empty()) {
        REQUIRE(base.rfind("translate(", 0) == 0);
        map = transform_of("translate", numbers_of(base));
    }
    for (const pugi::xml_node animation : polygon.children("animateTransform")) {
        CHECK(std::string(animation.attribute("additive").value()) == "sum");
        map = multiply(map, transform_of(animation.attribute("type").value(), animated_numbers(animation, t)));
    }
    for (std::size_t k = 0; k + 1 < points.size(); k += 2) {
        const double x = points[k];
        const double y = points[k + 1];
        points[k] = map[0] * x + map[2] * y + map[4];
        points[k + 1] = map[1] * x + map[3] * y + map[5];
    }
    return points;
}

}  // namespace

TEST_SUITE("SvgAnimator animation") {
    TEST_CASE("every animate element has one key time per value, rising from 0 to 1") {
        const FaceModel face = FaceModel::default_face();
        const Timeline timeline = spoken_timeline();
        const std::string svg = SvgAnimator(face).render_animation_svg(spoken_animation(face, timeline));
        const pugi::xml_document document = parse(svg);
        CHECK(std::string(document.child("svg").attribute("class").value()) == "tf-animation");
        int animated = 0;
        for (const pugi::xpath_node& node : document.select_nodes("//animate")) {
            const pugi::xml_node animate = node.node();
            const std::vector<std::string> values = split(animate.attribute("values").value(), ';');
            const std::vector<std::string> times = split(animate.attribute("keyTimes").value(), ';');
            CAPTURE(animate.parent().attribute("class").value());
            REQUIRE(values.size() == times.size());
            CHECK(std::stod(times.front()) == 0.0);
            CHECK(std::stod(times.back()) == 1.0);
            for (std::size_t k = 1; k < times.size(); ++k) CHECK(std::stod(times[k]) > std::stod(times[k - 1]));
            ++animated;
        }
        CHECK(animated > 5);
        CHECK(document.select_node("//path[@class='lips']/animate[@attributeName='d']"));
    }

    TEST_CASE("the interpolated hair and eyebrows stay within the tolerance of every frame") {
        const FaceModel face = FaceModel::default_face();
        const Timeline timeline = spoken_timeline();
        const Animation animation = spoken_animation(face, timeline);
        const SvgAnimator animator(face);
        const pugi::xml_document document = parse(animator.render_animation_svg(animation));
        // The head turns in this animation, and the hair follows as one affine map, not point by point.
        CHECK(document.select_node("//polygon[@class='hair']/animateTransform[@type='rotate']"));
        const double last_frame = static_cast<double>(animation.frames.size() - 1);
        // 0.3 px tolerance plus the 0.05 px of writing values in tenths and 0.005 of the frames' decimals.
        const double allowed = SvgAnimationOptions{}.tolerance_px + 0.06;
        for (std::size_t frame = 0; frame < animation.frames.size(); frame += 3) {
            CAPTURE(frame);
            const pugi::xml_document expected = parse(animator.render_svg(animation.frames[frame]));
            const double t = static_cast<double>(frame) / last_frame;
            for (const std::string name : {"hair", "eyebrow-left", "eyebrow-right"}) {
                CAPTURE(name);
                const std::string path = "//polygon[@class='" + name + "']";
                const std::vector<double> shown = polygon_points_at(document.select_node(path.c_str()).node(), t);
                const std::vector<double> want =
                    numbers_of(expected.select_node(path.c_str()).node().attribute("points").value());
                REQUIRE(shown.size() == want.size());
                double worst = 0.0;
                for (std::size_t k = 0; k < want.size(); ++k) worst = std::max(worst, std::abs(shown[k] - want[k]));
                CHECK(worst <= allowed);
            }
        }
    }

    TEST_CASE("the frames encoding shows one group per run of equal frames, ids unique") {
        const FaceModel face = FaceModel::default_face();
        const Timeline timeline = spoken_timeline();
        SvgAnimationOptions options;
        options.encoding = AnimationEncoding::frames;
        const pugi::xml_document document =
            parse(SvgAnimator(face).render_animation_svg(spoken_animation(face, timeline), options));
        const pugi::xpath_node_set sets = document.select_nodes("//set[@attributeName='visibility']");
        CHECK(sets.size() > 20);
        CHECK(std::string(sets[sets.size() - 1].node().attribute("fill").value()) == "freeze");
        std::vector<std::string> ids;
        for (const pugi::xpath_node& node : document.select_nodes("//*[@id]")) ids.push_back(node.node().attribute("id").value());
        std::sort(ids.begin(), ids.end());
        CHECK(std::adjacent_find(ids.begin(), ids.end()) == ids.end());
    }

    TEST_CASE("an animation without frames is refused") {
        CHECK_THROWS_WITH_AS(SvgAnimator(FaceModel::default_face()).render_animation_svg(Animation{}),
                             doctest::Contains("animation"), InvalidArgument);
    }

    TEST_CASE("a cancelled rendering throws Cancelled") {
        const FaceModel face = FaceModel::default_face();
        const Timeline timeline = spoken_timeline();
        CHECK_THROWS_AS(SvgAnimator(face).render_animation_svg(spoken_animation(face, timeline), {},
                                                               [](double, const std::string&) { return false; }),
                        Cancelled);
    }

    TEST_CASE("encoding names read back") {
        for (AnimationEncoding encoding : {AnimationEncoding::keyframes, AnimationEncoding::frames}) {
            CHECK(animation_encoding_from_name(animation_encoding_name(encoding)) == encoding);
        }
        CHECK_THROWS_WITH_AS(animation_encoding_from_name("gif"), doctest::Contains("keyframes or frames"),
                             InvalidArgument);
    }
}

TEST_SUITE("web page") {
    TEST_CASE("escape_html replaces the five characters markup is made of") {
        CHECK(escape_html(kHostile) == "&lt;/script&gt;&lt;img src=x onerror=alert(1)&gt;&quot;&#39;&amp;");
        CHECK(escape_html("會說話") == "會說話");
    }

    TEST_CASE("no caller text can add markup or script to an audio book page") {
        const FaceModel face = FaceModel::default_face();
        Timeline timeline = spoken_timeline();
        timeline.sentences[0].text = kHostile;
        WebPageOptions options;
        options.app = WebPageApp::audiobook;
        options.title = kHostile;
        options.links.push_back({kHostile, "https://example.org/?q=\"><script>"});
        const std::string html = build_web_page(SvgAnimator(face), spoken_animation(face, timeline), timeline,
                                                test::source_path("samples/speech/demo.ogg"), options);
        CHECK(html.find("<img") == std::string::npos);
        CHECK(html.find("<script>") == html.rfind("<script>"));
        CHECK(html.find("</script>") == html.rfind("</script>"));
        CHECK(html.find(escape_html(kHostile)) != std::string::npos);
        CHECK(html.find("data-start=\"0.5\"") != std::string::npos);
    }

    TEST_CASE("links with a script scheme are refused, whatever their case and spacing") {
        const FaceModel face = FaceModel::default_face();
        const Timeline timeline = spoken_timeline();
        for (const char* url : {"javascript:alert(1)", "JavaScript:alert(1)", " javascript:x", "java\tscript:x",
                                "data:text/html,<script>", "vbscript:x"}) {
            CAPTURE(url);
            WebPageOptions options;
            options.links.push_back({"x", url});
            CHECK_THROWS_WITH_AS(build_web_page(SvgAnimator(face), spoken_animation(face, timeline), timeline,
                                                test::source_path("samples/speech/demo.ogg"), options),
                                 doctest::Contains("links[0].url"), InvalidArgument);
        }
    }

    TEST_CASE("a failed page leaves the file that was there") {
        const FaceModel face = FaceModel::default_face();
        const Timeline timeline = spoken_timeline();
        const std::string path = test::output_path("web_page_kept.html");
        { std::ofstream(path) << "old"; }
        CHECK_THROWS_AS(write_web_page(path, SvgAnimator(face), spoken_animation(face, timeline), timeline,
                                       test::output_path("no_such_speech.ogg")),
                        FileError);
        std::ifstream in(path);
        std::string content;
        in >> content;
        CHECK(content == "old");
    }

    TEST_CASE("an announcer page places the face's origin and d on its stage") {
        const FaceModel face = FaceModel::default_face();
        const Timeline timeline = spoken_timeline();
        WebPageOptions options;
        options.app = WebPageApp::announcer;
        options.face_origin_px = Point2{600.0, 330.0};
        options.face_d_px = 2.0 * face.fapu("d");
        const std::string html = build_web_page(SvgAnimator(face), spoken_animation(face, timeline), timeline,
                                                test::source_path("samples/speech/demo.ogg"), options);
        const std::size_t stage = html.find("<svg class=\"tf-stage\"");
        REQUIRE(stage != std::string::npos);
        const std::size_t inner = html.find("class=\"tf-animation\"", stage);
        REQUIRE(inner != std::string::npos);
        const std::string tag = html.substr(html.rfind("<svg", inner), html.find('>', inner) - html.rfind("<svg", inner));
        const pugi::xml_document document = parse(tag + "/>");
        const pugi::xml_node root = document.first_child();
        const std::vector<double> box = numbers_of(root.attribute("viewBox").value());
        const ProjectedFace neutral = project_face(face, FaceState{});
        // O maps to the asked origin with the scale of d: x + (O.x - box.x) * scale = 600.
        const double scale = root.attribute("width").as_double() / box[2];
        CHECK(scale == doctest::Approx(2.0).epsilon(0.01));
        CHECK(root.attribute("x").as_double() + (neutral.origin.x - box[0]) * scale == doctest::Approx(600.0).epsilon(0.001));
        CHECK(root.attribute("y").as_double() + (neutral.origin.y - box[1]) * scale == doctest::Approx(330.0).epsilon(0.001));
    }
}

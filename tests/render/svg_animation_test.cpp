// The temporal half of SvgAnimator (thesis 6.3.2) and the web page (chapter 7): both encodings read
// back as XML, the key frames checked against every frame, and pages whose caller texts stay text.
#include <doctest/doctest.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <pugixml.hpp>

#include "common/number_format.hpp"
#include "common/test_paths.hpp"
#include "render/animation_frame.hpp"
#include "render/html_text.hpp"
#include "render/svg_text.hpp"
#include "talkface/animation.hpp"
#include "talkface/errors.hpp"
#include "talkface/expression_simulator.hpp"
#include "talkface/face_model.hpp"
#include "talkface/mouth_shape.hpp"
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

// The simulated face, with a tilt, a turn and a nod of its own, so that every head movement is
// seen in 3 s.
Animation spoken_animation(const FaceModel& face, const Timeline& timeline) {
    ExpressionSimulator simulator(timeline, 11);
    simulator.set_user_events({{ExpressionEventKind::tilt, 0.4, 1.2, 5.0},
                               {ExpressionEventKind::turn, 1.0, 1.7, -7.0},
                               {ExpressionEventKind::nod, 1.9, 2.4, 4.0}});
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

// Path data as commands, each with its numbers ("M1,2 c3-4 5 6 7 8" -> M{1,2} c{3,-4,5,6,7,8}).
struct PathCommand {
    char letter;
    std::vector<double> numbers;
};

std::vector<PathCommand> path_commands(const std::string& data) {
    std::vector<PathCommand> commands;
    std::size_t i = 0;
    while (i < data.size()) {
        if (std::isalpha(static_cast<unsigned char>(data[i]))) {
            commands.push_back({data[i], {}});
            ++i;
            continue;
        }
        std::size_t end = data.find_first_of("MmLlCcSsQqTtZz", i);
        if (end == std::string::npos) end = data.size();
        REQUIRE(!commands.empty());
        const std::vector<double> numbers = numbers_of(data.substr(i, end - i));
        commands.back().numbers.insert(commands.back().numbers.end(), numbers.begin(), numbers.end());
        i = end;
    }
    return commands;
}

// The control points a path draws, absolute, as x y x y ...: every point of M, L, C and Q, and
// for an S or a T the reflected first control point it leaves implicit, so that an S segment lists
// what a C would, and a T what a Q would.
std::vector<double> control_points(const std::vector<PathCommand>& commands) {
    std::vector<double> points;
    double x = 0.0, y = 0.0, start_x = 0.0, start_y = 0.0, control_x = 0.0, control_y = 0.0;
    char previous = 'M';
    for (const PathCommand& command : commands) {
        const char upper = static_cast<char>(std::toupper(static_cast<unsigned char>(command.letter)));
        const bool is_relative = command.letter != upper;
        if (upper == 'Z') {
            x = start_x;
            y = start_y;
            previous = upper;
            continue;
        }
        const std::size_t pairs = upper == 'C' ? 3 : upper == 'S' || upper == 'Q' ? 2 : 1;
        const std::vector<double>& n = command.numbers;
        REQUIRE(n.size() % (2 * pairs) == 0);
        for (std::size_t k = 0; k < n.size(); k += 2 * pairs) {
            const double base_x = is_relative ? x : 0.0;
            const double base_y = is_relative ? y : 0.0;
            if (upper == 'S' || upper == 'T') {
                // SVG: the reflection of the last control point if the previous segment is of the
                // same kind, else the pen.
                const bool reflects =
                    upper == 'S' ? previous == 'C' || previous == 'S' : previous == 'Q' || previous == 'T';
                points.push_back(reflects ? 2.0 * x - control_x : x);
                points.push_back(reflects ? 2.0 * y - control_y : y);
            }
            for (std::size_t p = 0; p < pairs; ++p) {
                points.push_back(base_x + n[k + 2 * p]);
                points.push_back(base_y + n[k + 2 * p + 1]);
            }
            const bool is_curve = upper != 'M' && upper != 'L';
            control_x = points[points.size() - (is_curve ? 4 : 2)];
            control_y = points[points.size() - (is_curve ? 3 : 1)];
            x = points[points.size() - 2];
            y = points.back();
            if (upper == 'M' && k == 0) {
                start_x = x;
                start_y = y;
            }
            previous = upper;
        }
    }
    return points;
}

// The value an <animate> of path data gives at key time `t`: its numbers interpolated, in the
// commands of its first value.
std::vector<PathCommand> animated_path(const pugi::xml_node& animate, double t) {
    std::vector<PathCommand> commands =
        path_commands(split(animate.attribute("values").value(), ';').front());
    const std::vector<double> numbers = animated_numbers(animate, t);
    std::size_t next = 0;
    for (PathCommand& command : commands) {
        for (double& number : command.numbers) number = numbers.at(next++);
    }
    REQUIRE(next == numbers.size());
    return commands;
}

// A point moved by one transform: translate(x [y]), scale(s [sy]) or rotate(degrees [cx cy]).
void apply_transform(const std::string& type, const std::vector<double>& n, double& x, double& y) {
    if (type == "translate") {
        x += n.at(0);
        y += n.size() > 1 ? n[1] : 0.0;
    } else if (type == "scale") {
        x *= n.at(0);
        y *= n.size() > 1 ? n[1] : n[0];
    } else {
        REQUIRE(type == "rotate");
        const double angle_rad = n.at(0) * 3.14159265358979323846 / 180.0;
        const double cx = n.size() > 2 ? n[1] : 0.0, cy = n.size() > 2 ? n[2] : 0.0;
        const double dx = x - cx, dy = y - cy;
        x = cx + std::cos(angle_rad) * dx - std::sin(angle_rad) * dy;
        y = cy + std::sin(angle_rad) * dx + std::cos(angle_rad) * dy;
    }
}

// Points (x y x y ...) moved by what `node` and its ancestors show at key time `t`: each one's
// transform attribute, followed by its <animateTransform additive="sum"> children, which SVG
// multiplies onto it in document order (so the last one moves a point first).
void apply_transforms(const pugi::xml_node& node, double t, std::vector<double>& points) {
    for (pugi::xml_node n = node; n && n.type() == pugi::node_element; n = n.parent()) {
        std::vector<std::pair<std::string, std::vector<double>>> transforms;
        const std::string list = n.attribute("transform").value();
        for (std::size_t open = list.find('('); open != std::string::npos; open = list.find('(', open + 1)) {
            std::size_t name_start = list.rfind(' ', open);
            name_start = name_start == std::string::npos ? 0 : name_start + 1;
            transforms.emplace_back(list.substr(name_start, open - name_start),
                                    numbers_of(list.substr(open + 1, list.find(')', open) - open - 1)));
        }
        for (const pugi::xml_node animation : n.children("animateTransform")) {
            REQUIRE(std::string(animation.attribute("additive").value()) == "sum");
            transforms.emplace_back(animation.attribute("type").value(), animated_numbers(animation, t));
        }
        for (auto transform = transforms.rbegin(); transform != transforms.rend(); ++transform) {
            for (std::size_t k = 0; k + 1 < points.size(); k += 2) {
                apply_transform(transform->first, transform->second, points[k], points[k + 1]);
            }
        }
    }
}

// The control points an element shows at key time `t` (x y x y ...), in the document's user space:
// its outline (animated or not) moved by its own transforms and its groups'.
std::vector<double> shown_points(const pugi::xml_node& element, double t) {
    std::vector<double> points;
    if (element.attribute("d")) {
        const pugi::xml_node animate = element.find_child_by_attribute("animate", "attributeName", "d");
        points = control_points(animate ? animated_path(animate, t)
                                        : path_commands(element.attribute("d").value()));
    } else {
        for (const char* coordinate : {"cx", "cy"}) {
            const pugi::xml_node animate =
                element.find_child_by_attribute("animate", "attributeName", coordinate);
            points.push_back(animate ? animated_numbers(animate, t).at(0)
                                     : element.attribute(coordinate).as_double());
        }
    }
    apply_transforms(element, t, points);
    return points;
}

// Where each drawn element of a frame is found by the same XPath in both documents.
std::vector<std::string> drawn_elements() {
    std::vector<std::string> paths;
    for (const char* name : {"hair", "ear-left", "ear-right", "face-contour", "jaw", "nose", "eyebrow-left",
                             "eyebrow-right", "lips"}) {
        paths.push_back(std::string("//path[@class='") + name + "']");
    }
    for (const char* id : {"tf-eye-left", "tf-eye-right", "tf-mouth"})
        paths.push_back(std::string("//path[@id='") + id + "']");
    for (const char* side : {"left", "right"}) {
        for (int circle = 1; circle <= 3; ++circle) {
            paths.push_back(std::string("//g[@class='eyeball-") + side + "']/circle[" +
                            std::to_string(circle) + "]");
        }
    }
    return paths;
}

// Checks every other frame of `animation` against `document`, its keyframes encoding: every
// drawn point shown where the frame drawn alone has it, within the tolerance and the rounding.
void check_every_other_frame(const SvgAnimator& animator, const Animation& animation,
                             const pugi::xml_document& document, double tolerance_px) {
    // The tolerance, plus the rounding of values written in tenths (0.05 px), of the
    // translates (0.01 px) and of the frames' own two decimals (0.005 px); a c1 that an S
    // leaves implicit is made of three rounded points and the frame's own rounding (0.17 px).
    // (A T's control and the end before it are rounded as a chain: the key frames leave
    // the extra rounding over from the tolerance, so they keep to the same bounds.)
    const double allowed = tolerance_px + 0.07;
    const double allowed_implicit = tolerance_px + 0.19;
    const double last_frame = static_cast<double>(animation.frames.size() - 1);
    for (std::size_t frame = 0; frame < animation.frames.size(); frame += 2) {
        CAPTURE(frame);
        const pugi::xml_document expected = parse(animator.render_svg(animation.frames[frame]));
        const double t = last_frame > 0.0 ? static_cast<double>(frame) / last_frame : 0.0;
        for (const std::string& path : drawn_elements()) {
            CAPTURE(path);
            const pugi::xml_node shown_node = document.select_node(path.c_str()).node();
            const pugi::xml_node want_node = expected.select_node(path.c_str()).node();
            REQUIRE(shown_node);
            REQUIRE(want_node);
            const std::vector<double> shown = shown_points(shown_node, t);
            const std::vector<double> want = shown_points(want_node, 0.0);
            REQUIRE(shown.size() == want.size());
            // Implicit control points: where the animated path writes S or T, and the frame C or Q.
            std::vector<bool> is_implicit(want.size() / 2, false);
            if (const pugi::xml_node animate =
                    shown_node.find_child_by_attribute("animate", "attributeName", "d")) {
                std::size_t point = 0;
                for (const PathCommand& command : animated_path(animate, t)) {
                    const char upper =
                        static_cast<char>(std::toupper(static_cast<unsigned char>(command.letter)));
                    if (upper == 'Z') continue;
                    const std::size_t pairs = upper == 'C' ? 3 : upper == 'S' || upper == 'Q' ? 2 : 1;
                    for (std::size_t k = 0; k < command.numbers.size(); k += 2 * pairs) {
                        if (upper == 'S' || upper == 'T') is_implicit.at(point++) = true;
                        point += pairs;
                    }
                }
            }
            double worst = 0.0, worst_implicit = 0.0;
            for (std::size_t k = 0; k < want.size(); ++k) {
                const double gap = std::abs(shown[k] - want[k]);
                (is_implicit[k / 2] ? worst_implicit : worst) =
                    std::max(is_implicit[k / 2] ? worst_implicit : worst, gap);
            }
            CHECK(worst <= allowed);
            CHECK(worst_implicit <= allowed_implicit);
        }
    }
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

    TEST_CASE("every drawn point stays within the tolerance of every frame") {
        const FaceModel face = FaceModel::default_face();
        const Timeline timeline = spoken_timeline();
        const Animation animation = spoken_animation(face, timeline);
        const SvgAnimator animator(face);
        for (const double tolerance_px : {0.3, 1.0}) {
            CAPTURE(tolerance_px);
            SvgAnimationOptions options;
            options.tolerance_px = tolerance_px;
            const pugi::xml_document document = parse(animator.render_animation_svg(animation, options));
            // The head tilts as a whole, and outlines move under a translate of their own as it turns.
            CHECK(document.select_node("//g[@id='face']/animateTransform[@type='rotate']"));
            CHECK(document.select_node("//g[@id='hair']/animateTransform[@type='rotate']"));
            CHECK(document.select_node("//path[@class='nose']/animateTransform[@type='translate']"));
            check_every_other_frame(animator, animation, document, tolerance_px);
        }
    }

    TEST_CASE("a tilt that never changes is a fixed rotate of the head, and its frames are kept") {
        const FaceModel face = FaceModel::default_face();
        const SvgAnimator animator(face);
        for (const std::size_t frame_count : {std::size_t{1}, std::size_t{3}}) {
            CAPTURE(frame_count);
            Animation animation;
            animation.duration_s = static_cast<double>(frame_count - 1) / animation.fps;
            for (std::size_t frame = 0; frame < frame_count; ++frame) {
                FaceState state;
                state.pose.gamma_deg = -6.0;
                state.pose.beta_deg = 2.0 * static_cast<double>(frame);
                state.mouth = mouth_controls(face, frame == 1 ? MouthShape::a : MouthShape::o);
                animation.frames.push_back(state);
            }
            const pugi::xml_document document = parse(animator.render_animation_svg(animation));
            CHECK_FALSE(document.select_node("//animateTransform[@type='rotate']"));
            CHECK(std::string(document.select_node("//g[@id='face']").node().attribute("transform").value())
                      .find("rotate(-6)") != std::string::npos);
            check_every_other_frame(animator, animation, document, SvgAnimationOptions{}.tolerance_px);
        }
    }

    TEST_CASE("the same animation gives the same bytes") {
        const FaceModel face = FaceModel::default_face();
        const Timeline timeline = spoken_timeline();
        const Animation animation = spoken_animation(face, timeline);
        for (AnimationEncoding encoding : {AnimationEncoding::keyframes, AnimationEncoding::frames}) {
            SvgAnimationOptions options;
            options.encoding = encoding;
            CHECK(SvgAnimator(face).render_animation_svg(animation, options) ==
                  SvgAnimator(face).render_animation_svg(animation, options));
        }
    }

    TEST_CASE("a minute of speech takes less than the stated bytes in the keyframes encoding") {
        // Issue #6 asks for less than 300 KB a minute of real speech, met there (bench/README.md:
        // 280 KB on 3 minutes). This timeline's pauses are shorter, so its mouth moves more: 305 KB
        // were reached on it, and this bound keeps that from growing back.
        constexpr double kMaxKibPerMinute = 315.0;
        const FaceModel face = FaceModel::default_face();
        Timeline timeline;
        std::string text;
        for (int sentence = 0; sentence < 20; ++sentence) text += "我們下個星期要去北京開會。";
        timeline = read_transcript(text);
        // Four syllables a second, a pause of 0.6 s after each sentence, as a speaker reads.
        double time_s = 0.5;
        for (std::size_t k = 0; k < timeline.syllables.size(); ++k) {
            Syllable& syllable = timeline.syllables[k];
            syllable.start_s = time_s;
            syllable.end_s = time_s + 0.25;
            time_s = syllable.end_s;
            const bool ends_sentence =
                k + 1 == timeline.syllables.size() || timeline.syllables[k + 1].sentence != syllable.sentence;
            if (ends_sentence) time_s += 0.6;
        }
        for (std::size_t s = 0; s < timeline.sentences.size(); ++s) {
            double start = 1e9, end = 0.0;
            for (const Syllable& syllable : timeline.syllables) {
                if (syllable.sentence != s) continue;
                start = std::min(start, syllable.start_s);
                end = std::max(end, syllable.end_s);
            }
            timeline.sentences[s].start_s = start;
            timeline.sentences[s].end_s = end;
        }
        timeline.duration_s = time_s + 0.5;
        const Animation animation = spoken_animation(face, timeline);
        const std::string svg = SvgAnimator(face).render_animation_svg(animation);
        const double kib_per_minute =
            static_cast<double>(svg.size()) / 1024.0 / (animation.duration_s / 60.0);
        CAPTURE(animation.duration_s);
        CHECK(animation.duration_s > 60.0);
        CHECK(kib_per_minute < kMaxKibPerMinute);
        MESSAGE("keyframes: " << kib_per_minute << " KiB per minute");
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

    TEST_CASE("coordinates are written as format_fixed writes them") {
        std::uint64_t state = 12345;
        auto next_unit = [&] {
            state = state * 6364136223846793005ULL + 1442695040888963407ULL;
            return static_cast<double>(state >> 11) / 9007199254740992.0;
        };
        std::vector<double> values{0.0, -0.0, 0.125, -0.125, 2.5, 0.005, -0.004, 1e16, -3e20};
        for (int i = 0; i < 20000; ++i)
            values.push_back((next_unit() - 0.5) * std::pow(10.0, 6.0 * next_unit()));
        for (const double value : values) {
            for (int decimals = 0; decimals <= 6; ++decimals) {
                CAPTURE(value);
                CAPTURE(decimals);
                std::string text = "x";
                detail::append_fixed(text, value, decimals);
                CHECK(text == "x" + detail::format_fixed(value, decimals));
            }
        }
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
        // The page's script and the packed animation's data block, nothing else.
        CHECK(html.find("<script>") == html.rfind("<script>"));
        const std::size_t data = html.find("<script type=\"application/gzip\" id=\"tf-animation-data\">");
        CHECK(html.find("<script") == data);
        CHECK(html.find("</script>", html.find("</script>") + 1) == html.rfind("</script>"));
        CHECK(html.find("</script>", html.find("</script>") + 1) != std::string::npos);
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
        const std::size_t stage = html.find("<svg class=\"tf-stage-art\"");
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

TEST_CASE("a held frame is one that repeats pose, expression, mouth and tilt exactly") {
    using talkface::detail::is_held_frame;
    FaceState state;
    state.mouth = MouthControls{};
    CHECK_FALSE(is_held_frame(state, 0.0, nullptr, 0.0));  // the first frame is drawn
    const FaceState same = state;
    CHECK(is_held_frame(same, 1.5, &state, 1.5));
    CHECK_FALSE(is_held_frame(same, 1.5, &state, 1.25));  // the head tilts on
    FaceState moved = state;
    moved.pose.gamma_deg = 0.5;
    CHECK_FALSE(is_held_frame(moved, 0.0, &state, 0.0));
    moved = state;
    moved.expression.blink_left = 0.1;
    CHECK_FALSE(is_held_frame(moved, 0.0, &state, 0.0));
    moved = state;
    moved.mouth->up.y += 0.01;
    CHECK_FALSE(is_held_frame(moved, 0.0, &state, 0.0));
    moved.mouth.reset();  // the neutral mouth is another mouth
    CHECK_FALSE(is_held_frame(moved, 0.0, &state, 0.0));
}

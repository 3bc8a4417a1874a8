// SvgAnimator: the documents it writes, read back as XML (thesis 6.3.1; SPEC "Rendering").
#include <doctest/doctest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <pugixml.hpp>

#include "talkface/errors.hpp"
#include "talkface/face_model.hpp"
#include "talkface/mouth_shape.hpp"
#include "talkface/svg_animator.hpp"
#include "common/test_paths.hpp"
#include "render/face_grid.hpp"

using namespace talkface;

namespace {

struct ViewBox {
    double x = 0.0, y = 0.0, width = 0.0, height = 0.0;
};

pugi::xml_document parse_svg(const std::string& svg) {
    pugi::xml_document document;
    const pugi::xml_parse_result result = document.load_string(svg.c_str());
    REQUIRE_MESSAGE(result, result.description());
    return document;
}

ViewBox view_box_of(const pugi::xml_document& document) {
    std::istringstream in(document.child("svg").attribute("viewBox").value());
    ViewBox box;
    in >> box.x >> box.y >> box.width >> box.height;
    return box;
}

std::vector<double> numbers_in(const std::string& text) {
    static const std::regex number(R"(-?\d+(\.\d+)?)");
    std::vector<double> numbers;
    for (auto it = std::sregex_iterator(text.begin(), text.end(), number); it != std::sregex_iterator(); ++it) {
        numbers.push_back(std::stod(it->str()));
    }
    return numbers;
}

// The closed outline of path data made of M, C and Z (what SvgAnimator writes), sampled finely.
std::vector<std::pair<double, double>> sample_path(const std::string& data) {
    std::vector<std::pair<double, double>> outline;
    std::istringstream in(data);
    std::string token;
    std::pair<double, double> pen;
    auto point_of = [](const std::string& text) {
        const std::vector<double> xy = numbers_in(text);
        REQUIRE(xy.size() == 2);
        return std::make_pair(xy[0], xy[1]);
    };
    while (in >> token) {
        if (token[0] == 'M') {
            pen = point_of(token.substr(1));
            outline.push_back(pen);
        } else if (token[0] == 'C') {
            std::string second, third;
            in >> second >> third;
            const auto c1 = point_of(token.substr(1));
            const auto c2 = point_of(second);
            const auto end = point_of(third);
            for (int step = 1; step <= 32; ++step) {
                const double t = step / 32.0, u = 1.0 - t;
                outline.emplace_back(
                    u * u * u * pen.first + 3 * u * u * t * c1.first + 3 * u * t * t * c2.first + t * t * t * end.first,
                    u * u * u * pen.second + 3 * u * u * t * c1.second + 3 * u * t * t * c2.second +
                        t * t * t * end.second);
            }
            pen = end;
        }
    }
    return outline;
}

double enclosed_area(const std::vector<std::pair<double, double>>& outline) {
    double twice_area = 0.0;
    for (std::size_t i = 0; i < outline.size(); ++i) {
        const auto& a = outline[i];
        const auto& b = outline[(i + 1) % outline.size()];
        twice_area += a.first * b.second - b.first * a.second;
    }
    return std::abs(twice_area) / 2.0;
}

pugi::xml_node node_with_id(const pugi::xml_document& document, const std::string& id) {
    return document.find_node([&](pugi::xml_node node) { return id == node.attribute("id").value(); });
}

}  // namespace

TEST_SUITE("SvgAnimator") {

TEST_CASE("the document is XML with the four layers in thesis order") {
    const SvgAnimator animator(FaceModel::default_face());
    const std::string svg = animator.render_svg({});
    CHECK(svg.rfind("<?xml version=\"1.0\"", 0) == 0);
    const pugi::xml_document document = parse_svg(svg);
    const pugi::xml_node root = document.child("svg");
    CHECK(std::string(root.attribute("xmlns").value()) == "http://www.w3.org/2000/svg");
    CHECK(std::string(root.attribute("xmlns:xlink").value()) == "http://www.w3.org/1999/xlink");
    CHECK(std::string(root.attribute("version").value()) == "1.1");
    std::vector<std::string> layers;
    for (pugi::xml_node group : root.children("g")) layers.push_back(group.attribute("id").value());
    CHECK(layers == std::vector<std::string>{"background", "hair", "clothes", "face"});
    CHECK(root.find_child_by_attribute("g", "id", "hair").find_child_by_attribute("path", "class", "hair"));
    CHECK(node_with_id(document, "face").select_nodes(".//path | .//use").size() >= 10);
}

TEST_CASE("every url(#id) reference names an id that exists, and ids are unique") {
    const SvgAnimator animator(FaceModel::default_face());
    FaceState state;
    state.mouth = mouth_controls(animator.face(), MouthShape::a);
    const pugi::xml_document document = parse_svg(animator.render_svg(state));
    std::multiset<std::string> ids;
    std::vector<std::string> references;
    static const std::regex url(R"(url\(#([^)]+)\))");
    for (pugi::xpath_node found : document.select_nodes("//*")) {
        for (pugi::xml_attribute attribute : found.node().attributes()) {
            const std::string value = attribute.value();
            if (std::string(attribute.name()) == "id") ids.insert(value);
            // The eye outline is drawn once and <use>d for its white and its stroke.
            if (std::string(attribute.name()) == "xlink:href" && value.rfind('#', 0) == 0) references.push_back(value.substr(1));
            for (auto it = std::sregex_iterator(value.begin(), value.end(), url); it != std::sregex_iterator(); ++it) {
                references.push_back((*it)[1]);
            }
        }
    }
    for (const std::string& id : ids) {
        CAPTURE(id);
        CHECK(ids.count(id) == 1);
    }
    CHECK(references.size() >= 8);  // two clip paths, two gradients, each eye outline used twice
    for (const std::string& reference : references) {
        CAPTURE(reference);
        CHECK(ids.count(reference) == 1);
    }
    CHECK(std::string(node_with_id(document, "tf-eye-left-clip").name()) == "clipPath");
    CHECK(std::string(node_with_id(document, "tf-iris-left-gradient").name()) == "radialGradient");
}

TEST_CASE("the same state gives the same bytes") {
    FaceState state;
    state.pose = {5.0, -12.5, 3.0};
    state.expression.smile = 0.4;
    state.mouth = mouth_controls(FaceModel::default_face(), MouthShape::o);
    const SvgAnimator first(FaceModel::default_face());
    const SvgAnimator second(FaceModel::default_face());
    CHECK(first.render_svg(state) == first.render_svg(state));
    CHECK(first.render_svg(state) == second.render_svg(state));
}

TEST_CASE("a full blink closes the eye outline, hiding the clipped eyeball") {
    const SvgAnimator animator(FaceModel::default_face());
    for (const Pose& pose : {Pose{}, Pose{10.0, -15.0, 5.0}}) {
        CAPTURE(pose.beta_deg);
        FaceState state;
        state.pose = pose;
        const pugi::xml_document open = parse_svg(animator.render_svg(state));
        state.expression.blink_left = 1.0;
        state.expression.blink_right = 1.0;
        const pugi::xml_document closed = parse_svg(animator.render_svg(state));
        for (const char* clip : {"tf-eye-left-clip", "tf-eye-right-clip"}) {
            CAPTURE(clip);
            const double open_area =
                enclosed_area(sample_path(node_with_id(open, clip).child("path").attribute("d").value()));
            const double closed_area =
                enclosed_area(sample_path(node_with_id(closed, clip).child("path").attribute("d").value()));
            CHECK(open_area > 20.0);
            CHECK(closed_area < 0.02 * open_area);
        }
    }
}

TEST_CASE("the canvas is the same at every pose and expression of one face") {
    const SvgAnimator animator(FaceModel::default_face());
    const pugi::xml_document frontal = parse_svg(animator.render_svg({}));
    const std::string view_box = frontal.child("svg").attribute("viewBox").value();
    const std::string width = frontal.child("svg").attribute("width").value();
    for (const Pose& pose : test::pose_grid()) {
        FaceState state;
        state.pose = pose;
        state.expression.brows = 1.0;
        state.mouth = mouth_controls(animator.face(), MouthShape::a);
        const pugi::xml_document document = parse_svg(animator.render_svg(state));
        CAPTURE(pose.alpha_deg);
        CAPTURE(pose.beta_deg);
        CAPTURE(pose.gamma_deg);
        CHECK(view_box == document.child("svg").attribute("viewBox").value());
        CHECK(width == document.child("svg").attribute("width").value());
    }
}

TEST_CASE("every coordinate lies inside the canvas at every pose within 15 degrees") {
    for (const auto& [face_name, face] : test::bundled_faces()) {
        CAPTURE(face_name);
        const SvgAnimator animator(face);
        const std::vector<FaceState> expressions = [&] {
            std::vector<FaceState> states(3);
            states[1].mouth = mouth_controls(face, MouthShape::a);
            states[1].expression.brows = 1.0;
            states[2].expression.smile = 1.0;
            states[2].mouth = mouth_controls(face, MouthShape::u);
            return states;
        }();
        for (const Pose& pose : test::pose_grid()) {
            for (FaceState state : expressions) {
                state.pose = pose;
                const pugi::xml_document document = parse_svg(animator.render_svg(state));
                const ViewBox box = view_box_of(document);
                CAPTURE(pose.alpha_deg);
                CAPTURE(pose.beta_deg);
                CAPTURE(pose.gamma_deg);
                int outside = 0;
                for (pugi::xpath_node found : document.select_nodes("//*[@d or @points] | //circle")) {
                    const pugi::xml_node node = found.node();
                    std::vector<double> xy = numbers_in(node.attribute("d").value());
                    const std::vector<double> points = numbers_in(node.attribute("points").value());
                    xy.insert(xy.end(), points.begin(), points.end());
                    if (node.attribute("cx")) {
                        xy.push_back(node.attribute("cx").as_double());
                        xy.push_back(node.attribute("cy").as_double());
                    }
                    for (std::size_t i = 0; i + 1 < xy.size(); i += 2) {
                        if (xy[i] < box.x || xy[i] > box.x + box.width || xy[i + 1] < box.y ||
                            xy[i + 1] > box.y + box.height) {
                            ++outside;
                        }
                    }
                }
                CHECK(outside == 0);
            }
        }
    }
}

TEST_CASE("coordinates carry at most the requested decimals") {
    for (int decimals : {0, 1, 3}) {
        CAPTURE(decimals);
        SvgOptions options;
        options.decimals = decimals;
        const SvgAnimator animator(FaceModel::default_face(), options);
        FaceState state;
        state.pose = {3.3, 7.7, -1.1};
        const pugi::xml_document document = parse_svg(animator.render_svg(state));
        const std::string data = node_with_id(document, "face").find_child_by_attribute("path", "class", "lips")
                                     .attribute("d").value();
        static const std::regex fraction(R"(\.(\d+))");
        std::size_t longest = 0;
        for (auto it = std::sregex_iterator(data.begin(), data.end(), fraction); it != std::sregex_iterator(); ++it) {
            longest = std::max(longest, (*it)[1].str().size());
        }
        CHECK(longest <= static_cast<std::size_t>(decimals));
    }
}

TEST_CASE("background and clothes layers follow the options, and stay in place when empty") {
    SvgOptions options;
    options.background = std::nullopt;
    options.draw_clothes = false;
    const SvgAnimator animator(FaceModel::default_face(), options);
    const pugi::xml_document document = parse_svg(animator.render_svg({}));
    CHECK(node_with_id(document, "background"));
    CHECK_FALSE(node_with_id(document, "background").first_child());
    CHECK_FALSE(node_with_id(document, "clothes").first_child());

    const SvgAnimator with_layers(FaceModel::default_face());
    const pugi::xml_document full = parse_svg(with_layers.render_svg({}));
    CHECK(std::string(node_with_id(full, "background").child("rect").attribute("fill").value()) == "#dde8f0");
    CHECK(node_with_id(full, "clothes").child("path"));
}

TEST_CASE("width_px and height_px set the size, the viewBox stays the face's") {
    SvgOptions options;
    options.width_px = 300;
    const SvgAnimator sized(FaceModel::default_face(), options);
    const SvgAnimator fitted(FaceModel::default_face());
    const pugi::xml_document a = parse_svg(sized.render_svg({}));
    const pugi::xml_document b = parse_svg(fitted.render_svg({}));
    CHECK(a.child("svg").attribute("width").as_int() == 300);
    CHECK(a.child("svg").attribute("height").as_int() > 0);
    CHECK(std::string(a.child("svg").attribute("viewBox").value()) == b.child("svg").attribute("viewBox").value());
}

TEST_CASE("out-of-range options are rejected naming the option") {
    auto make = [](SvgOptions options) { SvgAnimator animator(FaceModel::default_face(), options); };
    SvgOptions options;
    options.decimals = kMaxSvgDecimals;
    CHECK_NOTHROW(make(options));
    options.decimals = kMaxSvgDecimals + 1;
    CHECK_THROWS_WITH_AS(make(options), doctest::Contains("decimals"), InvalidArgument);
    options.decimals = -1;
    CHECK_THROWS_WITH_AS(make(options), doctest::Contains("decimals"), InvalidArgument);
    options = {};
    options.stroke_width_in_d = 0.0;
    CHECK_THROWS_WITH_AS(make(options), doctest::Contains("stroke_width_in_d"), InvalidArgument);
    options.stroke_width_in_d = std::nan("");
    CHECK_THROWS_WITH_AS(make(options), doctest::Contains("stroke_width_in_d"), InvalidArgument);
    options = {};
    options.width_px = -1;
    CHECK_THROWS_WITH_AS(make(options), doctest::Contains("width_px"), InvalidArgument);
    options = {};
    options.height_px = -5;
    CHECK_THROWS_WITH_AS(make(options), doctest::Contains("height_px"), InvalidArgument);
}

TEST_CASE("write_svg writes render_svg's bytes, and a bad pose leaves no file") {
    const SvgAnimator animator(FaceModel::default_face());
    const std::string path = test::output_path("svg_animator_write.svg");
    std::remove(path.c_str());
    FaceState state;
    state.pose.beta_deg = 10.0;
    animator.write_svg(path, state);
    std::ifstream in(path, std::ios::binary);
    std::stringstream written;
    written << in.rdbuf();
    CHECK(written.str() == animator.render_svg(state));

    const std::string refused = test::output_path("svg_animator_refused.svg");
    std::remove(refused.c_str());
    state.pose.beta_deg = 20.0;
    CHECK_THROWS_WITH_AS(animator.write_svg(refused, state), doctest::Contains("beta"), InvalidArgument);
    CHECK_FALSE(std::filesystem::exists(refused));
}

}  // TEST_SUITE

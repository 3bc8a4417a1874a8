// The Lottie encoding: every shape kind of the drawing model in Lottie's form, clipped groups as
// masked layers, and key frames that a linear player turns back into every frame within the
// tolerance; then a whole animation as one document.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "common/json.hpp"
#include "render/lottie_layer_encoder.hpp"
#include "talkface/animation.hpp"
#include "talkface/errors.hpp"
#include "talkface/expression_simulator.hpp"
#include "talkface/svg_animator.hpp"
#include "talkface/transcript.hpp"

using namespace talkface;
using namespace talkface::detail;

namespace {

constexpr double kTolerance = 0.3;
constexpr int kDecimals = 2;
constexpr std::size_t kFrames = 60;

JsonValue parse(const std::string& text) {
    JsonReader reader(text, "<lottie>");
    return reader.read_document();
}

// A property's numbers at `frame` as a linear player computes them (lottie-web with linear
// easing): a static value, or the keys around the frame interpolated. A Bezier path gives its
// vertices, then its absolute in and out controls.
std::vector<double> flatten(const JsonValue& value) {
    std::vector<double> numbers;
    if (value.type == JsonValue::Type::number) return {value.number};
    if (value.type == JsonValue::Type::object) {
        const JsonValue& v = *value.find("v");
        for (const char* key : {"v", "i", "o"}) {
            const JsonValue& list = *value.find(key);
            for (std::size_t k = 0; k < list.items.size(); ++k) {
                const double base_x = key[0] == 'v' ? 0.0 : v.items[k].items[0].number;
                const double base_y = key[0] == 'v' ? 0.0 : v.items[k].items[1].number;
                numbers.push_back(base_x + list.items[k].items[0].number);
                numbers.push_back(base_y + list.items[k].items[1].number);
            }
        }
        return numbers;
    }
    for (const JsonValue& item : value.items) {
        const std::vector<double> inner = flatten(item);
        numbers.insert(numbers.end(), inner.begin(), inner.end());
    }
    return numbers;
}

std::vector<double> property_at(const JsonValue& property, double frame) {
    if (property.find("a")->number == 0.0) return flatten(*property.find("k"));
    const std::vector<JsonValue>& keys = property.find("k")->items;
    if (frame <= keys.front().find("t")->number) return flatten(*keys.front().find("s"));
    for (std::size_t k = 0; k + 1 < keys.size(); ++k) {
        const double t0 = keys[k].find("t")->number, t1 = keys[k + 1].find("t")->number;
        if (frame > t1) continue;
        const std::vector<double> a = flatten(*keys[k].find("s")), b = flatten(*keys[k + 1].find("s"));
        std::vector<double> result(a.size());
        for (std::size_t n = 0; n < a.size(); ++n) result[n] = a[n] + (b[n] - a[n]) * (frame - t0) / (t1 - t0);
        return result;
    }
    return flatten(*keys.back().find("s"));
}

std::size_t key_count(const JsonValue& property) {
    return property.find("a")->number == 0.0 ? 0 : property.find("k")->items.size();
}

// A layer of every shape kind, moving with t in 0..1: a closed path of a line, a cubic and a
// quadratic, a polyline, a rectangle, and a circle clipped by an outline that moves too.
Layer moving_layer(double t) {
    Layer layer;
    Definition clip;
    clip.kind = DefinitionKind::clip_path;
    clip.id = "tf-clip";
    clip.outline_id = "tf-clip-outline";
    clip.outline.move_to({40.0, 40.0}).line_to({80.0 + 10.0 * t, 40.0}).line_to({80.0, 80.0}).close();
    layer.definitions.push_back(clip);
    Definition gradient;
    gradient.kind = DefinitionKind::radial_gradient;
    gradient.id = "tf-gradient";
    gradient.gradient.stops = {{0.0, Rgb{255, 255, 255}}, {1.0, Rgb{0, 0, 80}}};
    layer.definitions.push_back(gradient);

    Shape path;
    path.name = "blob";
    path.paint.fill = Paint::of(Rgb{200, 150, 100});
    path.paint.stroke = Paint::of(Rgb{0, 0, 0});
    path.paint.stroke_width = 1.5;
    path.path.move_to({10.0, 10.0}).line_to({30.0, 10.0 + 20.0 * t * t});
    path.path.curves({CubicSegment{{35.0, 20.0}, {30.0, 30.0 + 5.0 * std::sin(6.0 * t)}, {20.0, 35.0}}});
    path.path.verbs.push_back(PathVerb::quadratic);
    path.path.points.insert(path.path.points.end(), {Point2{5.0, 30.0}, Point2{10.0, 10.0}});
    path.path.close();
    layer.elements.push_back(path);

    Shape eyeball;
    eyeball.kind = ShapeKind::circle;
    eyeball.centre = {60.0 + 15.0 * t, 60.0};
    eyeball.radius = 10.0;
    eyeball.paint.fill = Paint::of_gradient(1);
    Shape group;
    group.kind = ShapeKind::group;
    group.name = "eyeball";
    group.is_clipped = true;
    group.definition = 0;
    group.children.push_back(eyeball);
    layer.elements.push_back(group);

    Shape line;
    line.kind = ShapeKind::polyline;
    line.points = {{0.0, 90.0}, {50.0, 90.0 - 30.0 * t}, {100.0, 90.0}};
    line.paint.stroke = Paint::of(Rgb{10, 20, 30});
    line.paint.stroke_width = 2.0;
    layer.elements.push_back(line);

    Shape box;
    box.kind = ShapeKind::rect;
    box.corner = {0.0, 0.0};
    box.width = 100.0;
    box.height = 100.0;
    box.paint.fill = Paint::of(Rgb{221, 232, 240});
    layer.elements.insert(layer.elements.begin(), box);
    return layer;
}

std::vector<LottieLayerContent> encode_moving(std::size_t frames) {
    LottieLayerEncoder encoder("test", kTolerance, kDecimals, frames);
    for (std::size_t frame = 0; frame < frames; ++frame) {
        encoder.add(moving_layer(static_cast<double>(frame) / static_cast<double>(frames - 1)));
    }
    return encoder.finish();
}

}  // namespace

TEST_SUITE("lottie") {
    TEST_CASE("a clipped group becomes a layer masked by its clip, between the shapes drawn before and after it") {
        const std::vector<LottieLayerContent> layers = encode_moving(kFrames);
        REQUIRE(layers.size() == 3);
        CHECK(layers[0].masks.empty());
        CHECK(layers[1].name == "test eyeball");
        CHECK(layers[2].masks.empty());
        const JsonValue masks = parse(layers[1].masks);
        REQUIRE(masks.items.size() == 1);
        CHECK(masks.items[0].find("mode")->text == "a");
        // The clip's outline: 3 vertices, closed, moving with its corner.
        const JsonValue& outline = *masks.items[0].find("pt");
        CHECK(key_count(outline) >= 2);
        CHECK(outline.find("k")->items[0].find("s")->items[0].find("c")->boolean);
        // Paint order in Lottie: the top shape first. The rectangle (drawn first) is last.
        const JsonValue bottom = parse(layers[0].shapes);
        REQUIRE(bottom.items.size() == 2);
        CHECK(bottom.items[0].find("nm")->text == "blob");
        CHECK(bottom.items[1].find("it")->items[0].find("ty")->text == "rc");
        // The blob's group: its path, its stroke over its fill, then the transform.
        const JsonValue& blob = *bottom.items[0].find("it");
        REQUIRE(blob.items.size() == 4);
        CHECK(blob.items[0].find("ty")->text == "sh");
        CHECK(blob.items[1].find("ty")->text == "st");
        CHECK(blob.items[2].find("ty")->text == "fl");
        CHECK(blob.items[3].find("ty")->text == "tr");
        // The eyeball: an ellipse under a radial gradient fill.
        const JsonValue eyeball = parse(layers[1].shapes);
        CHECK(eyeball.items[0].find("it")->items[0].find("ty")->text == "el");
        const JsonValue& fill = eyeball.items[0].find("it")->items[1];
        CHECK(fill.find("ty")->text == "gf");
        CHECK(fill.find("t")->number == 2.0);
        CHECK(fill.find("g")->find("p")->number == 2.0);
    }

    TEST_CASE("every frame is what a linear player interpolates from the key frames, within the tolerance") {
        const std::vector<LottieLayerContent> layers = encode_moving(kFrames);
        const JsonValue bottom = parse(layers[0].shapes);
        const JsonValue eyeball = parse(layers[1].shapes);
        const JsonValue top = parse(layers[2].shapes);
        const JsonValue masks = parse(layers[1].masks);
        const JsonValue& blob_path = *bottom.items[0].find("it")->items[0].find("ks");
        const JsonValue& circle = eyeball.items[0].find("it")->items[0];
        const JsonValue& gradient_start = *eyeball.items[0].find("it")->items[1].find("s");
        const JsonValue& polyline = *top.items[0].find("it")->items[0].find("ks");
        const JsonValue& clip = *masks.items[0].find("pt");
        // Rounding to 2 decimals adds up to 0.005 on each side.
        const double allowed = kTolerance + 0.011;
        double worst = 0.0;
        for (std::size_t frame = 0; frame < kFrames; ++frame) {
            const double t = static_cast<double>(frame) / static_cast<double>(kFrames - 1);
            const Layer drawn = moving_layer(t);
            const std::vector<double> blob = property_at(blob_path, static_cast<double>(frame));
            // Vertices: the move, the line's end, the cubic's end; the quadratic, back at the start,
            // is Lottie's closing segment, not a vertex of its own.
            REQUIRE(blob.size() == 18);
            worst = std::max(worst, std::abs(blob[3] - (10.0 + 20.0 * t * t)));
            // The cubic's second control is the third vertex's in control.
            worst = std::max(worst, std::abs(blob[6 + 5] - (30.0 + 5.0 * std::sin(6.0 * t))));
            // The quadratic's, raised to a cubic, the first vertex's in control.
            worst = std::max(worst, std::abs(blob[6] - (10.0 - 10.0 / 3.0)));
            worst = std::max(worst, std::abs(blob[7] - (10.0 + 40.0 / 3.0)));
            const std::vector<double> centre = property_at(*circle.find("p"), static_cast<double>(frame));
            worst = std::max(worst, std::abs(centre[0] - drawn.elements[2].children[0].centre.x));
            // The gradient's centre follows the circle's box.
            const std::vector<double> focus = property_at(gradient_start, static_cast<double>(frame));
            worst = std::max(worst, std::abs(focus[0] - drawn.elements[2].children[0].centre.x));
            const std::vector<double> line = property_at(polyline, static_cast<double>(frame));
            worst = std::max(worst, std::abs(line[3] - (90.0 - 30.0 * t)));
            const std::vector<double> outline = property_at(clip, static_cast<double>(frame));
            worst = std::max(worst, std::abs(outline[2] - (80.0 + 10.0 * t)));
        }
        CHECK(worst <= allowed);
        // What moves in a straight line needs no key between its ends.
        CHECK(key_count(*circle.find("p")) == 2);
        CHECK(key_count(polyline) == 2);
        // What bends needs more, and still far fewer than the frames.
        CHECK(key_count(blob_path) > 2);
        CHECK(key_count(blob_path) < kFrames / 3);
        // What holds still is static: the circle's size, the fills' colours.
        CHECK(key_count(*circle.find("s")) == 0);
        CHECK(key_count(*bottom.items[0].find("it")->items[2].find("c")) == 0);
    }

    TEST_CASE("a layer added once, or repeated, holds still, a frame with other shapes is a bug") {
        LottieLayerEncoder still("still", kTolerance, kDecimals, 1);
        still.add(moving_layer(0.5));
        for (const LottieLayerContent& layer : still.finish()) {
            CHECK(layer.shapes.find("\"a\":1") == std::string::npos);
        }
        LottieLayerEncoder repeated("repeated", kTolerance, kDecimals, 5);
        repeated.add(moving_layer(0.5));
        for (int k = 0; k < 4; ++k) repeated.add_repeat();
        CHECK(repeated.animated_property_count() == 0);
        CHECK(repeated.property_count() > 10);

        LottieLayerEncoder broken("broken", kTolerance, kDecimals, 2);
        broken.add(moving_layer(0.0));
        Layer other = moving_layer(0.5);
        other.elements.pop_back();
        CHECK_THROWS_AS(broken.add(other), Error);

        // A gradient fill of a path inside a clipped group would need a union (its box's mask) inside
        // an intersection.
        Layer boxed = moving_layer(0.0);
        Shape blob = boxed.elements[1];
        blob.paint.fill = Paint::of_gradient(1);
        boxed.elements[2].children.push_back(blob);
        LottieLayerEncoder boxing("boxing", kTolerance, kDecimals, 1);
        CHECK_THROWS_WITH_AS(boxing.add(boxed), doctest::Contains("no Lottie form"), Error);
    }

    TEST_CASE("a clipped group inside another is masked by both clips, intersected, a moved clip by its source moved") {
        // Inside the eyeball's group: the clip's outline moved 5 right (a moved clip), holding a
        // reference to the clip's outline moved 3 down.
        const auto nested_layer = [](double t) {
            Layer layer = moving_layer(t);
            Definition moved_clip;
            moved_clip.kind = DefinitionKind::clip_path;
            moved_clip.id = "tf-moved";
            moved_clip.is_moved = true;
            moved_clip.source = 0;
            moved_clip.offset = {5.0, 0.0};
            layer.definitions.push_back(moved_clip);
            Shape reference;
            reference.kind = ShapeKind::reference;
            reference.name = "inner";
            reference.definition = 0;
            reference.offset = {0.0, 3.0};
            reference.paint.fill = Paint::of(Rgb{250, 250, 240});
            Shape inner;
            inner.kind = ShapeKind::group;
            inner.name = "inner-group";
            inner.is_clipped = true;
            inner.definition = 2;
            inner.children.push_back(reference);
            layer.elements[2].children.push_back(inner);
            return layer;
        };
        LottieLayerEncoder encoder("test", kTolerance, kDecimals, kFrames);
        for (std::size_t frame = 0; frame < kFrames; ++frame) {
            encoder.add(nested_layer(static_cast<double>(frame) / static_cast<double>(kFrames - 1)));
        }
        const std::vector<LottieLayerContent> layers = encoder.finish();
        REQUIRE(layers.size() == 4);
        CHECK(layers[1].name == "test eyeball");
        CHECK(layers[2].name == "test inner-group");
        const JsonValue outer = parse(layers[1].masks);
        const JsonValue inner = parse(layers[2].masks);
        REQUIRE(outer.items.size() == 1);
        REQUIRE(inner.items.size() == 2);
        CHECK(inner.items[0].find("mode")->text == "a");
        CHECK(inner.items[1].find("mode")->text == "i");
        // Frame 0: the clip's first vertex (40, 40); the moved clip's 5 right of it, the reference's 3 below.
        const auto first_vertex = [](const JsonValue& path) {
            const JsonValue& value = *path.find("k");
            const JsonValue& shape = path.find("a")->number == 0.0 ? value : *value.items[0].find("s")->items.data();
            return std::make_pair(shape.find("v")->items[0].items[0].number, shape.find("v")->items[0].items[1].number);
        };
        CHECK(first_vertex(*inner.items[0].find("pt")) == std::make_pair(40.0, 40.0));
        CHECK(first_vertex(*inner.items[1].find("pt")) == std::make_pair(45.0, 40.0));
        const JsonValue inner_shapes = parse(layers[2].shapes);
        CHECK(first_vertex(*inner_shapes.items[0].find("it")->items[0].find("ks")) == std::make_pair(40.0, 43.0));
    }

    TEST_CASE("an animation is one Lottie document: the composition, the face's layers, the mouth moving") {
        Timeline timeline = read_transcript("八。");
        timeline.syllables[0].start_s = 0.4;
        timeline.syllables[0].end_s = 0.8;
        timeline.sentences[0].start_s = 0.4;
        timeline.sentences[0].end_s = 0.8;
        timeline.duration_s = 1.2;
        const FaceModel face = FaceModel::default_face();
        const Animation animation = animate(face, timeline, ExpressionSimulator(timeline, 1));
        const SvgAnimator animator(face);
        const JsonValue lottie = parse(animator.render_animation_lottie(animation));
        CHECK(lottie.find("fr")->number == animation.fps);
        CHECK(lottie.find("ip")->number == 0.0);
        CHECK(lottie.find("op")->number == static_cast<double>(animation.frames.size()));
        CHECK(lottie.find("w")->number > 0.0);
        const std::vector<JsonValue>& layers = lottie.find("layers")->items;
        // Face (with the two eyeballs as masked layers between its parts), clothes, hair, background.
        REQUIRE(layers.size() >= 6);
        CHECK(layers.back().find("nm")->text == "background");
        std::size_t masked = 0;
        const JsonValue* lips = nullptr;
        for (const JsonValue& layer : layers) {
            CHECK(layer.find("ty")->number == 4.0);
            CHECK(layer.find("op")->number == static_cast<double>(animation.frames.size()));
            if (layer.find("hasMask") != nullptr) ++masked;
            for (const JsonValue& group : layer.find("shapes")->items) {
                if (group.find("nm")->text == "lips") lips = &group;
            }
        }
        // The eyeballs, clipped by their eye outlines, and the inside of the mouth: the upper teeth
        // clipped by the opening moved to either side (short of the corners), the lower teeth,
        // tongue and back also by the opening moved down (under the upper teeth).
        CHECK(masked == 4);
        const auto below_upper_teeth = std::find_if(layers.begin(), layers.end(), [](const JsonValue& layer) {
            return layer.find("nm")->text == "face mouth-below-upper-teeth";
        });
        REQUIRE(below_upper_teeth != layers.end());
        const std::vector<JsonValue>& masks = below_upper_teeth->find("masksProperties")->items;
        REQUIRE(masks.size() == 3);
        CHECK(masks[0].find("mode")->text == "a");
        for (std::size_t k = 1; k < masks.size(); ++k) CHECK(masks[k].find("mode")->text == "i");
        // The opening and its moved copies move with the mouth.
        for (const JsonValue& mask : masks) CHECK(key_count(*mask.find("pt")) >= 3);
        REQUIRE(lips != nullptr);
        const JsonValue& lips_path = *lips->find("it")->items[0].find("ks");
        CHECK(key_count(lips_path) >= 3);
        CHECK(key_count(lips_path) < animation.frames.size());
        CHECK_THROWS_AS(animator.render_animation_lottie(Animation{}), InvalidArgument);
        LottieOptions bad;
        bad.tolerance_px = 0.0;
        CHECK_THROWS_WITH_AS(animator.render_animation_lottie(animation, bad), doctest::Contains("tolerance_px"),
                             InvalidArgument);
    }
}

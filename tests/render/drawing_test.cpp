// The drawing model (src/render/drawing.hpp) and its SVG writer: what the encodings and the raster
// renderer rely on.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <random>
#include <string>
#include <vector>

#include "render/drawing.hpp"
#include "render/keyframes_encoder.hpp"
#include "render/layers.hpp"
#include "render/svg_text.hpp"
#include "render/svg_writer.hpp"
#include "talkface/errors.hpp"
#include "talkface/face_model.hpp"
#include "talkface/face_look.hpp"
#include "talkface/face_pose.hpp"
#include "talkface/mouth_shape.hpp"

using namespace talkface;
using namespace talkface::detail;

namespace {

// The number an SVG reader gets from `text`, read digit by digit as our encoder once read it.
double read_decimal(const std::string& text) {
    std::size_t i = 0;
    const bool is_negative = text[0] == '-';
    if (is_negative) ++i;
    long long whole = 0;
    for (; i < text.size() && text[i] != '.'; ++i) whole = whole * 10 + (text[i] - '0');
    long long fraction = 0, power = 1;
    for (++i; i < text.size(); ++i) {
        fraction = fraction * 10 + (text[i] - '0');
        power *= 10;
    }
    const double value = static_cast<double>(whole) + static_cast<double>(fraction) / static_cast<double>(power);
    return is_negative ? -value : value;
}

Layer face_layer_at(const FaceState& state) {
    const FaceModel face = FaceModel::default_face();
    const ProjectedFace projected = project_face(face, state);
    const FacePaints paints = make_face_paints(projected, LayerStyle{2, 1.5});
    return draw_face_layer(projected, paints);
}

}  // namespace

TEST_SUITE("drawing model") {
    TEST_CASE("round_as_written gives back what the written text reads as") {
        std::mt19937 random(7);
        std::uniform_real_distribution<double> value(-5000.0, 5000.0);
        for (int decimals = 0; decimals <= 3; ++decimals) {
            for (int i = 0; i < 20000; ++i) {
                // Ties (x.5 at the last digit) go to the general conversion: make some.
                const double x = i % 10 == 0 ? std::round(value(random) * 20.0) / 20.0 : value(random);
                std::string text;
                append_fixed(text, x, decimals);
                CAPTURE(x);
                CAPTURE(text);
                CHECK(round_as_written(x, decimals) == read_decimal(text));
            }
        }
    }

    TEST_CASE("path data is written verb by verb") {
        Path path;
        path.move_to({1, 2}).line_to({3.26, 4}).curves({{{5, 6}, {7, 8}, {9, 10}}}).close();
        path.verbs.push_back(PathVerb::quadratic);
        path.points.insert(path.points.end(), {{1, 1}, {2, 2.5}});
        std::string text;
        append_path_data(text, path, 1);
        CHECK(text == "M1,2 L3.3,4 C5,6 7,8 9,10 Z Q1,1 2,2.5");
    }

    TEST_CASE("numeric attributes are listed in the order the writer writes them") {
        const Layer layer = face_layer_at(FaceState{});
        std::vector<NumericAttribute> attributes;
        list_numeric_attributes(layer, attributes);
        REQUIRE(attributes.size() > 10);
        std::vector<AttributeOverride> overrides(attributes.size());
        for (std::size_t i = 0; i < overrides.size(); ++i) {
            overrides[i].is_set = true;
            overrides[i].value = "#" + std::to_string(i) + "#";
        }
        std::string svg;
        write_layer_svg(layer, SvgLayerOptions{2, {}, &overrides}, svg);
        std::size_t position = 0;
        for (std::size_t i = 0; i < attributes.size(); ++i) {
            CAPTURE(i);
            const std::size_t found = svg.find(std::string(attributes[i].name) + "=\"#" + std::to_string(i) + "#\"");
            REQUIRE(found != std::string::npos);
            CHECK(found > position);
            position = found;
        }
        overrides.pop_back();
        svg.clear();
        CHECK_THROWS_AS(write_layer_svg(layer, SvgLayerOptions{2, {}, &overrides}, svg), Error);
    }

    TEST_CASE("ids and references get the frame's prefix") {
        std::string svg;
        write_layer_svg(face_layer_at(FaceState{}), SvgLayerOptions{2, "f3-", nullptr}, svg);
        CHECK(svg.find("id=\"f3-tf-eye-left-clip\"") != std::string::npos);
        CHECK(svg.find("url(#f3-tf-eye-left-clip)") != std::string::npos);
        CHECK(svg.find("url(#f3-tf-iris-right-gradient)") != std::string::npos);
        CHECK(svg.find("xlink:href=\"#f3-tf-eye-right\"") != std::string::npos);
        CHECK(svg.find("\"tf-") == std::string::npos);
        CHECK(svg.find("#tf-") == std::string::npos);
    }

    TEST_CASE("a moved clip path and a moved reference draw their source's outline under a translate") {
        Layer layer;
        Definition clip;
        clip.kind = DefinitionKind::clip_path;
        clip.id = "tf-clip";
        clip.outline_id = "tf-outline";
        clip.outline.move_to({1, 2}).line_to({5, 2}).line_to({3, 6}).close();
        layer.definitions.push_back(clip);
        Definition moved_clip;
        moved_clip.kind = DefinitionKind::clip_path;
        moved_clip.id = "tf-moved";
        moved_clip.is_moved = true;
        moved_clip.source = 0;
        moved_clip.offset = {0.0, 1.25};
        layer.definitions.push_back(moved_clip);
        Shape reference;
        reference.kind = ShapeKind::reference;
        reference.name = "copy";
        reference.definition = 1;
        reference.offset = {-2.0, 0.0};
        reference.paint.fill = Paint::of(Rgb{1, 2, 3});
        Shape group;
        group.kind = ShapeKind::group;
        group.is_clipped = true;
        group.definition = 1;
        group.children.push_back(reference);
        layer.elements.push_back(group);
        // The outlines as drawn: the source's moved, and a reference's moved further.
        CHECK(clip_outline(layer, layer.definitions[1]).points.front() == Point2{1.0, 3.25});
        CHECK(reference_outline(layer, reference).points.back() == Point2{1.0, 7.25});
        // Only the source's outline is a number an animation moves.
        std::vector<NumericAttribute> attributes;
        list_numeric_attributes(layer, attributes);
        CHECK(attributes.size() == 1);
        std::string svg;
        write_layer_svg(layer, SvgLayerOptions{2, "f1-", nullptr}, svg);
        CHECK(svg.find("<clipPath id=\"f1-tf-moved\">\n<use xlink:href=\"#f1-tf-outline\" transform=\"translate(0 1.25)\"/>") !=
              std::string::npos);
        CHECK(svg.find("<use class=\"copy\" xlink:href=\"#f1-tf-outline\" transform=\"translate(-2 1.25)\" fill=\"#010203\"") !=
              std::string::npos);
        CHECK(svg.find("clip-path=\"url(#f1-tf-moved)\"") != std::string::npos);
    }

    TEST_CASE("the keyframes encoder refuses a frame drawn with other path verbs") {
        const Layer first = face_layer_at(FaceState{});
        Layer other = first;
        other.elements.front().path.line_to({1, 1});
        KeyframesEncoder encoder(25.0, 3.0, 1, 2);
        encoder.add(first);
        CHECK_THROWS_WITH_AS(encoder.add(other), doctest::Contains("frame 1 draws attribute d"), Error);
        Layer fewer = first;
        fewer.elements.erase(fewer.elements.begin());
        CHECK_THROWS_WITH_AS(encoder.add(fewer), doctest::Contains("numeric attributes"), Error);
    }

    TEST_CASE("a layer that holds still is written as the first frame, without animations") {
        const Layer layer = face_layer_at(FaceState{});
        KeyframesEncoder encoder(25.0, 3.0, 1, 3);
        encoder.add(layer);
        encoder.add(layer);
        encoder.add_repeat();
        std::string still;
        write_layer_svg(layer, SvgLayerOptions{1, {}, nullptr}, still);
        CHECK(encoder.finish({}, 0.0, 1.0) == still);
    }

    TEST_CASE("the flat look draws no outline but the upper lids, and tells the ears and the nose apart by colour") {
        const FaceModel face = FaceModel::default_face();
        FaceState state;
        state.mouth = mouth_controls(face, MouthShape::a);
        const ProjectedFace projected = project_face(face, state);
        const FacePaints flat = make_face_paints(projected, LayerStyle{2, 1.5, FaceLook::flat});
        const FacePaints outlined = make_face_paints(projected, LayerStyle{2, 1.5, FaceLook::outlined});
        // The lids' band is a stroke of the eye's outline, moved up (layer_order_test checks where
        // it shows).
        std::size_t strokes = 0;
        std::function<void(const Shape&)> count = [&](const Shape& shape) {
            const bool is_lid = shape.name == "eye-left-lid" || shape.name == "eye-right-lid";
            strokes += shape.paint.stroke.kind != PaintKind::none && !is_lid;
            for (const Shape& child : shape.children) count(child);
        };
        for (const Layer& layer : {draw_hair_layer(projected, flat), draw_face_layer(projected, flat),
                                   draw_clothes_layer(projected, CanvasBox{0, 0, 400, 400}, Rgb{}, flat.style)}) {
            for (const Shape& shape : layer.elements) count(shape);
        }
        CHECK(strokes == 0);
        CHECK_FALSE(flat.ears.fill.colour == flat.skin.fill.colour);
        CHECK(outlined.ears.fill.colour == outlined.skin.fill.colour);
        CHECK(outlined.ears.stroke.kind == PaintKind::colour);
        // The nose is its shade and nostrils when nothing outlines it.
        const Layer layer = draw_face_layer(projected, flat);
        CHECK(std::any_of(layer.elements.begin(), layer.elements.end(),
                          [](const Shape& shape) { return shape.name == "nose-shade"; }));
        CHECK(face_look_from_name(face_look_name(FaceLook::flat)) == FaceLook::flat);
        CHECK(face_look_from_name("outlined") == FaceLook::outlined);
        CHECK_THROWS_AS(face_look_from_name("sketch"), InvalidArgument);
    }
}

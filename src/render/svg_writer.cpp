#include "render/svg_writer.hpp"

#include <algorithm>
#include <cstddef>

#include "common/internal_error.hpp"
#include "common/number_format.hpp"
#include "render/svg_text.hpp"
#include "talkface/errors.hpp"

namespace talkface::detail {

namespace {

void append_point(std::string& svg, Point2 point, int decimals) {
    append_fixed(svg, point.x, decimals);
    svg += ',';
    append_fixed(svg, point.y, decimals);
}

class LayerWriter {
public:
    LayerWriter(const Layer& layer, const SvgLayerOptions& options, std::string& svg)
        : layer_(layer), options_(options), svg_(svg) {}

    void write() {
        if (!layer_.definitions.empty()) {
            svg_ += "<defs>\n";
            for (const Definition& definition : layer_.definitions) write_definition(definition);
            svg_ += "</defs>\n";
        }
        for (const Shape& shape : layer_.elements) write_shape(shape);
        if (options_.overrides != nullptr && slot_ != options_.overrides->size()) {
            throw internal_error("a layer of " +
                                                 std::to_string(slot_) + " numeric attributes written with " +
                                                 std::to_string(options_.overrides->size()) + " overrides");
        }
    }

private:
    void id_attribute(const char* name, std::string_view id) {
        svg_ += ' ';
        svg_ += name;
        svg_ += "=\"";
        svg_ += options_.id_prefix;
        svg_ += id;
        svg_ += '"';
    }

    void text_attribute(const char* name, std::string_view value) {
        if (value.empty()) return;
        svg_ += ' ';
        svg_ += name;
        svg_ += "=\"";
        svg_ += value;
        svg_ += '"';
    }

    void paint_value(const Paint& paint) {
        switch (paint.kind) {
            case PaintKind::none: svg_ += "none"; return;
            case PaintKind::colour: svg_ += to_hex(paint.colour); return;
            case PaintKind::gradient:
                svg_ += "url(#";
                svg_ += options_.id_prefix;
                svg_ += layer_.definitions.at(paint.gradient).id;
                svg_ += ')';
                return;
        }
    }

    void paint_attribute(const char* name, const Paint& paint) {
        svg_ += ' ';
        svg_ += name;
        svg_ += "=\"";
        paint_value(paint);
        svg_ += '"';
    }

    // `is_stroke_written`: shapes whose SVG default is no stroke (circles, rectangles) write none.
    void paint_attributes(const ShapePaint& paint, bool is_stroke_written) {
        paint_attribute("fill", paint.fill);
        if (paint.stroke.kind == PaintKind::none && !is_stroke_written) return;
        paint_attribute("stroke", paint.stroke);
        if (paint.stroke.kind == PaintKind::none) return;
        // A thin outline must not round to 0 when coordinates are written with few decimals.
        svg_ += " stroke-width=\"";
        append_fixed(svg_, paint.stroke_width, std::max(options_.decimals, 2));
        svg_ += '"';
        svg_ += " stroke-linejoin=\"round\" stroke-linecap=\"round\"";
    }

    // Writes the numeric attribute of the next slot; returns the children its animation puts inside
    // the element.
    std::string numeric_attribute(const char* name, const NumericAttribute& attribute) {
        const AttributeOverride* override =
            options_.overrides != nullptr && slot_ < options_.overrides->size() ? &(*options_.overrides)[slot_]
                                                                              : nullptr;
        ++slot_;
        svg_ += ' ';
        svg_ += name;
        svg_ += "=\"";
        if (override != nullptr && override->is_set) {
            svg_ += override->value;
            svg_ += '"';
            svg_ += override->attributes;
            return override->children;
        }
        append_attribute_value(svg_, attribute, options_.decimals);
        svg_ += '"';
        return {};
    }

    std::string number_attribute(const char* name, double value) {
        return numeric_attribute(name, {AttributeKind::number, name, nullptr, nullptr, value});
    }

    void end_element(const char* tag, const std::string& children) {
        if (children.empty()) {
            svg_ += "/>\n";
            return;
        }
        svg_ += '>';
        svg_ += children;
        svg_ += "</";
        svg_ += tag;
        svg_ += ">\n";
    }

    // ` xlink:href="#ID"` of a clip path's outline path.
    void outline_reference(const Definition& clip) {
        svg_ += " xlink:href=\"#";
        svg_ += options_.id_prefix;
        svg_ += clip.outline_id;
        svg_ += '"';
    }

    // A static move, written as drawn: ` transform="translate(X Y)"`, nothing for none.
    void translate_attribute(Point2 offset) {
        if (offset.x == 0.0 && offset.y == 0.0) return;
        svg_ += " transform=\"translate(";
        append_fixed(svg_, offset.x, options_.decimals);
        svg_ += ' ';
        append_fixed(svg_, offset.y, options_.decimals);
        svg_ += ")\"";
    }

    void write_definition(const Definition& definition) {
        if (definition.kind == DefinitionKind::clip_path && definition.is_moved) {
            svg_ += "<clipPath";
            id_attribute("id", definition.id);
            svg_ += ">\n<use";
            outline_reference(layer_.definitions.at(definition.source));
            translate_attribute(definition.offset);
            svg_ += "/>\n</clipPath>\n";
            return;
        }
        if (definition.kind == DefinitionKind::clip_path) {
            svg_ += "<clipPath";
            id_attribute("id", definition.id);
            svg_ += ">\n<path";
            id_attribute("id", definition.outline_id);
            const std::string children =
                numeric_attribute("d", {AttributeKind::path_data, "d", &definition.outline, nullptr, 0.0});
            end_element("path", children);
            svg_ += "</clipPath>\n";
            return;
        }
        const RadialGradient& gradient = definition.gradient;
        svg_ += "<radialGradient";
        id_attribute("id", definition.id);
        text_attribute("cx", format_shortest(gradient.cx));
        text_attribute("cy", format_shortest(gradient.cy));
        text_attribute("r", format_shortest(gradient.r));
        svg_ += ">\n";
        for (const GradientStop& stop : gradient.stops) {
            svg_ += "<stop";
            text_attribute("offset", format_shortest(stop.offset));
            text_attribute("stop-color", to_hex(stop.colour));
            svg_ += "/>\n";
        }
        svg_ += "</radialGradient>\n";
    }

    void write_shape(const Shape& shape) {
        switch (shape.kind) {
            case ShapeKind::path: {
                svg_ += "<path";
                text_attribute("class", shape.name);
                const std::string children =
                    numeric_attribute("d", {AttributeKind::path_data, "d", &shape.path, nullptr, 0.0});
                paint_attributes(shape.paint, true);
                end_element("path", children);
                return;
            }
            case ShapeKind::polyline: {
                svg_ += "<polyline";
                text_attribute("class", shape.name);
                const std::string children = numeric_attribute(
                    "points", {AttributeKind::polyline_points, "points", nullptr, &shape.points, 0.0});
                paint_attributes(shape.paint, true);
                end_element("polyline", children);
                return;
            }
            case ShapeKind::circle: {
                svg_ += "<circle";
                text_attribute("class", shape.name);
                std::string children = number_attribute("cx", shape.centre.x);
                children += number_attribute("cy", shape.centre.y);
                children += number_attribute("r", shape.radius);
                paint_attributes(shape.paint, false);
                end_element("circle", children);
                return;
            }
            case ShapeKind::rect: {
                svg_ += "<rect";
                text_attribute("class", shape.name);
                std::string children = number_attribute("x", shape.corner.x);
                children += number_attribute("y", shape.corner.y);
                children += number_attribute("width", shape.width);
                children += number_attribute("height", shape.height);
                paint_attributes(shape.paint, false);
                end_element("rect", children);
                return;
            }
            case ShapeKind::reference: {
                svg_ += "<use";
                text_attribute("class", shape.name);
                // A moved clip path has no outline path of its own: its source's, moved further.
                const Definition& clip = layer_.definitions.at(shape.definition);
                const Point2 offset = clip.is_moved ? Point2{shape.offset.x + clip.offset.x, shape.offset.y + clip.offset.y}
                                                    : shape.offset;
                outline_reference(clip.is_moved ? layer_.definitions.at(clip.source) : clip);
                translate_attribute(offset);
                paint_attributes(shape.paint, true);
                svg_ += "/>\n";
                return;
            }
            case ShapeKind::group: {
                svg_ += "<g";
                text_attribute("class", shape.name);
                if (shape.is_clipped) {
                    svg_ += " clip-path=\"url(#";
                    svg_ += options_.id_prefix;
                    svg_ += layer_.definitions.at(shape.definition).id;
                    svg_ += ")\"";
                }
                svg_ += ">\n";
                for (const Shape& child : shape.children) write_shape(child);
                svg_ += "</g>\n";
                return;
            }
        }
    }

    const Layer& layer_;
    const SvgLayerOptions& options_;
    std::string& svg_;
    std::size_t slot_ = 0;
};

}  // namespace

void append_path_data(std::string& svg, const Path& path, int decimals) {
    std::size_t next = 0;
    const std::size_t start = svg.size();
    for (const PathVerb verb : path.verbs) {
        switch (verb) {
            case PathVerb::move:
                if (svg.size() != start) svg += ' ';
                svg += 'M';
                append_point(svg, path.points[next++], decimals);
                break;
            case PathVerb::line:
                svg += " L";
                append_point(svg, path.points[next++], decimals);
                break;
            case PathVerb::cubic:
                svg += " C";
                append_point(svg, path.points[next++], decimals);
                svg += ' ';
                append_point(svg, path.points[next++], decimals);
                svg += ' ';
                append_point(svg, path.points[next++], decimals);
                break;
            case PathVerb::quadratic:
                svg += " Q";
                append_point(svg, path.points[next++], decimals);
                svg += ' ';
                append_point(svg, path.points[next++], decimals);
                break;
            case PathVerb::close: svg += " Z"; break;
        }
    }
}

void append_polyline_points(std::string& svg, const std::vector<Point2>& points, int decimals) {
    for (std::size_t i = 0; i < points.size(); ++i) {
        if (i > 0) svg += ' ';
        append_point(svg, points[i], decimals);
    }
}

void append_attribute_value(std::string& svg, const NumericAttribute& attribute, int decimals) {
    switch (attribute.kind) {
        case AttributeKind::path_data: append_path_data(svg, *attribute.path, decimals); return;
        case AttributeKind::polyline_points: append_polyline_points(svg, *attribute.points, decimals); return;
        case AttributeKind::number: append_fixed(svg, attribute.value, decimals); return;
    }
}

void append_numbers_as_written(const NumericAttribute& attribute, int decimals, std::vector<double>& numbers) {
    const std::vector<Point2>* points = attribute.kind == AttributeKind::path_data ? &attribute.path->points
                                        : attribute.kind == AttributeKind::polyline_points ? attribute.points
                                                                                             : nullptr;
    if (points == nullptr) {
        numbers.push_back(round_as_written(attribute.value, decimals));
        return;
    }
    for (const Point2& point : *points) {
        numbers.push_back(round_as_written(point.x, decimals));
        numbers.push_back(round_as_written(point.y, decimals));
    }
}

void write_layer_svg(const Layer& layer, const SvgLayerOptions& options, std::string& svg) {
    LayerWriter(layer, options, svg).write();
}

}  // namespace talkface::detail

// The drawing model (drawing.hpp) written as SVG 1.1 elements: what every SVG document of talkface
// is made of. One layer's content at a time; the document around it is svg_document.hpp's.
#ifndef TALKFACE_RENDER_SVG_WRITER_HPP
#define TALKFACE_RENDER_SVG_WRITER_HPP

#include <string>
#include <string_view>
#include <vector>

#include "render/drawing.hpp"

namespace talkface::detail {

// Path data: "M1,2 C3,4 5,6 7,8 Q9,1 2,3 L4,5 Z", coordinates with `decimals` digits after the point.
void append_path_data(std::string& svg, const Path& path, int decimals);

// A polyline's points: "1,2 3,4 5,6".
void append_polyline_points(std::string& svg, const std::vector<Point2>& points, int decimals);

// The value of a numeric attribute as the layer writes it (path data, points or one number).
void append_attribute_value(std::string& svg, const NumericAttribute& attribute, int decimals);

// The numbers of `attribute` as the document shows them (x, y of every point, or the one number),
// appended: round_as_written() of each (svg_text.hpp).
void append_numbers_as_written(const NumericAttribute& attribute, int decimals, std::vector<double>& numbers);

// What an animation writes in place of one numeric attribute (drawing.hpp: list_numeric_attributes).
struct AttributeOverride {
    bool is_set = false;
    std::string value;       // between the quotes, instead of the model's numbers
    std::string attributes;  // right after the attribute (` transform="translate(1 2)"`)
    std::string children;    // inside the element (its <animate> elements)
};

struct SvgLayerOptions {
    int decimals = 2;            // digits after the point in coordinates
    std::string_view id_prefix;  // put before every id and every reference to one
    // One per numeric attribute of the layer, in list_numeric_attributes() order; null for none.
    const std::vector<AttributeOverride>* overrides = nullptr;
};

// Appends the layer's content: a <defs> of its definitions (if any), then its elements.
// \throws talkface::Error (internal) if `overrides` has another count than the layer's numeric
// attributes.
void write_layer_svg(const Layer& layer, const SvgLayerOptions& options, std::string& svg);

}  // namespace talkface::detail

#endif

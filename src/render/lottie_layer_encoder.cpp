#include "render/lottie_layer_encoder.hpp"

#include <cmath>
#include <utility>

#include "common/internal_error.hpp"
#include "common/json.hpp"
#include "common/number_format.hpp"
#include "talkface/errors.hpp"

namespace talkface::detail {

namespace {

// Colours and gradient stops are written 0..1 to three digits: a step of 1/255 is 0.004.
constexpr int kColourDecimals = 3;
constexpr double kColourTolerance = 0.5 / 255.0;
// A key time to a thousandth of a frame.
constexpr int kTimeDecimals = 3;
// Gradient geometry in a bounding box's units (0..1).
constexpr int kUnitDecimals = 4;

// One subpath as Lottie draws it: vertices with absolute in and out controls (a line's controls
// are its ends). A closed subpath's last segment runs back to its first vertex; the drawing
// model's closes come after a segment that already ends there, so that segment is of length 0.
struct Subpath {
    std::vector<Point2> vertices, in, out;
    bool closed = false;
};

std::vector<Subpath> subpaths_of(const Path& path) {
    std::vector<Subpath> subpaths;
    Point2 start{0.0, 0.0};
    const auto begin = [&](Point2 point) {
        subpaths.push_back({{point}, {point}, {point}, false});
        start = point;
    };
    std::size_t next = 0;
    const std::vector<Point2>& p = path.points;
    for (const PathVerb verb : path.verbs) {
        if (verb == PathVerb::move) {
            begin(p[next]);
        } else if (verb == PathVerb::close) {
            if (!subpaths.empty()) subpaths.back().closed = true;
        } else {
            // After a close, SVG goes on from the closed subpath's start.
            if (subpaths.empty() || subpaths.back().closed) begin(start);
            Subpath& subpath = subpaths.back();
            const Point2 from = subpath.vertices.back();
            Point2 c1 = from, c2 = p[next], end = p[next];
            if (verb == PathVerb::cubic) {
                c1 = p[next];
                c2 = p[next + 1];
                end = p[next + 2];
            } else if (verb == PathVerb::quadratic) {
                // Raised to a cubic, exactly.
                end = p[next + 1];
                c1 = {from.x + 2.0 / 3.0 * (p[next].x - from.x), from.y + 2.0 / 3.0 * (p[next].y - from.y)};
                c2 = {end.x + 2.0 / 3.0 * (p[next].x - end.x), end.y + 2.0 / 3.0 * (p[next].y - end.y)};
            }
            subpath.out.back() = c1;
            subpath.vertices.push_back(end);
            subpath.in.push_back(c2);
            subpath.out.push_back(end);
        }
        next += static_cast<std::size_t>(points_of(verb));
    }
    return subpaths;
}

// The box of a shape's geometry, for gradients in its bounding box units (SVG objectBoundingBox).
// Of a path, the box of its points and controls: the curve's own box where the extremes are
// points, as on the shapes a gradient paints today (circles).
struct Box {
    double min_x = HUGE_VAL, min_y = HUGE_VAL, max_x = -HUGE_VAL, max_y = -HUGE_VAL;
    void add(Point2 point) {
        min_x = std::min(min_x, point.x);
        min_y = std::min(min_y, point.y);
        max_x = std::max(max_x, point.x);
        max_y = std::max(max_y, point.y);
    }
};

void append_points(const std::vector<Point2>& points, int decimals, std::vector<double>& numbers) {
    for (const Point2& point : points) {
        numbers.push_back(rounded(point.x, decimals));
        numbers.push_back(rounded(point.y, decimals));
    }
}

void append_number_list(std::string& text, const double* numbers, std::size_t count, int decimals) {
    text += '[';
    for (std::size_t k = 0; k < count; ++k) {
        if (k > 0) text += ',';
        text += format_fixed(numbers[k], decimals);
    }
    text += ']';
}

// Lottie's animated value {"a":1,"k":[...]}: a key at each of `keys`' frames, linear between keys
// (a Bezier easing from (0, 0) to (1, 1) with its handles on the line), a key that the next repeats
// as written holding ("h":1). `append_key_value` writes one key's `width` numbers.
template <class AppendKeyValue>
std::string keyed_value_text(const KeyFrames& keys, std::size_t width, int decimals, bool is_bezier_path,
                             const AppendKeyValue& append_key_value) {
    std::string ease_in = "{\"x\":1,\"y\":1}", ease_out = "{\"x\":0,\"y\":0}";
    // Bodymovin's habit: one easing number a dimension, except for Bezier paths.
    if (!is_bezier_path) {
        std::string ones = "[", zeros = "[";
        for (std::size_t k = 0; k < width; ++k) {
            ones += k > 0 ? ",1" : "1";
            zeros += k > 0 ? ",0" : "0";
        }
        ease_in = "{\"x\":" + ones + "],\"y\":" + ones + "]}";
        ease_out = "{\"x\":" + zeros + "],\"y\":" + zeros + "]}";
    }
    std::string text = "{\"a\":1,\"k\":[";
    std::vector<double> numbers(width);
    for (std::size_t key = 0; key < keys.positions.size(); ++key) {
        if (key > 0) text += ',';
        for (std::size_t k = 0; k < width; ++k) numbers[k] = keys.values.numbers[key * width + k];
        text += "{\"t\":" + format_fixed(keys.positions[key], kTimeDecimals) + ",\"s\":";
        append_key_value(text, numbers.data());
        if (key + 1 < keys.positions.size()) {
            // A key the next one repeats as written holds (a pause): the same as linear between
            // them, without the easing.
            bool holds = true;
            for (std::size_t k = 0; k < width && holds; ++k) {
                holds = rounded(numbers[k], decimals) == rounded(keys.values.numbers[(key + 1) * width + k], decimals);
            }
            text += holds ? ",\"h\":1" : ",\"i\":" + ease_in + ",\"o\":" + ease_out;
        }
        text += '}';
    }
    return text + "]}";
}

// A Bezier path value from its numbers: n vertices, then n in controls, then n out controls,
// absolute; Lottie's controls are relative to their vertex. `folded`: the path is closed and its
// last vertex is its first (the drawing model's close after a segment back to the start), so the
// last vertex is left out and its in control becomes the first's: Lottie's own closing segment
// is then that last segment, the same curve, one vertex shorter.
void append_bezier(std::string& text, const double* numbers, std::size_t width, bool closed, bool folded,
                   int decimals) {
    const std::size_t n = width / 6;
    const std::size_t written = folded ? n - 1 : n;
    const auto list = [&](const char* key, std::size_t offset) {
        text += '"';
        text += key;
        text += "\":[";
        for (std::size_t k = 0; k < written; ++k) {
            if (k > 0) text += ',';
            const std::size_t from = folded && k == 0 && offset == 2 * n ? n - 1 : k;
            const double x = numbers[offset + 2 * from], y = numbers[offset + 2 * from + 1];
            // Relative to the vertex as written, so that a control is as near as the vertex.
            const double vx = offset == 0 ? 0.0 : rounded(numbers[2 * from], decimals);
            const double vy = offset == 0 ? 0.0 : rounded(numbers[2 * from + 1], decimals);
            text += '[' + format_fixed(x - vx, decimals) + ',' + format_fixed(y - vy, decimals) + ']';
        }
        text += ']';
    };
    text += '{';
    list("i", 2 * n);
    text += ',';
    list("o", 4 * n);
    text += ',';
    list("v", 0);
    text += closed ? ",\"c\":true}" : ",\"c\":false}";
}

// Whether a closed path of these rows (`width` numbers each, as append_bezier reads them) ends
// every one at its first vertex.
template <typename Number>
bool ends_at_start(const std::vector<Number>& rows, std::size_t width) {
    const std::size_t last = 2 * (width / 6 - 1);
    for (std::size_t row = 0; row < rows.size(); row += width) {
        if (rows[row + last] != rows[row] || rows[row + last + 1] != rows[row + 1]) return false;
    }
    return true;
}

}  // namespace

// One frame's walk over a layer: every property's numbers in walk order, and (for the first
// frame) the Lottie text with a placeholder for each property.
struct LottieLayerEncoder::Frame {
    struct Value {
        Form form = Form::vector;
        bool closed = false;
        double tolerance = 0.0;
        int decimals = 0;
        std::vector<double> numbers;
    };

    const std::string& name;
    double tolerance;
    int decimals;  // of the written coordinates; recorded a digit finer, so that keys do not chase the rounding
    bool write_text;
    std::vector<Value> values;
    std::vector<LottieLayerContent> layers;
    std::vector<std::string> items;  // the current Lottie layer's shapes, in paint order
    std::string clip_masks;          // the clips around the shapes being walked, as masks

    // A placeholder for a property of these numbers (rounded to `digits`).
    std::string property(Form form, bool closed, double property_tolerance, int digits, std::vector<double> numbers) {
        const std::size_t index = values.size();
        values.push_back({form, closed, property_tolerance, digits, std::move(numbers)});
        return write_text ? "\x01" + std::to_string(index) + "\x02" : std::string();
    }

    std::string bezier(const Subpath& subpath) {
        std::vector<double> numbers;
        numbers.reserve(6 * subpath.vertices.size());
        append_points(subpath.vertices, decimals + 1, numbers);
        append_points(subpath.in, decimals + 1, numbers);
        append_points(subpath.out, decimals + 1, numbers);
        return property(Form::bezier, subpath.closed, tolerance, decimals, std::move(numbers));
    }

    std::string point(double x, double y) {
        return property(Form::vector, false, tolerance, decimals, {rounded(x, decimals + 1), rounded(y, decimals + 1)});
    }

    std::string colour(Rgb rgb) {
        return property(Form::vector, false, kColourTolerance, kColourDecimals,
                        {rounded(rgb.r / 255.0, kColourDecimals), rounded(rgb.g / 255.0, kColourDecimals),
                         rounded(rgb.b / 255.0, kColourDecimals), 1.0});
    }

    // A gradient's "g": its stops' count and their offsets and colours (a property: stops may change).
    std::string stops(const RadialGradient& radial) {
        std::vector<double> numbers;
        for (const GradientStop& stop : radial.stops) {
            numbers.insert(numbers.end(), {rounded(stop.offset, kColourDecimals),
                                           rounded(stop.colour.r / 255.0, kColourDecimals),
                                           rounded(stop.colour.g / 255.0, kColourDecimals),
                                           rounded(stop.colour.b / 255.0, kColourDecimals)});
        }
        return "{\"p\":" + std::to_string(radial.stops.size()) + ",\"k\":" +
               property(Form::vector, false, kColourTolerance, kColourDecimals, std::move(numbers)) + "}";
    }

    // "s", "e" and "g" of a radial gradient over `box`: centred at (cx, cy) in the box's units,
    // its last stop at r times the box's width. Exact on a square box (a circle's); fills of other
    // shapes take add_fill_in_box(), and a gradient stroke (none is drawn) keeps the width's circle.
    std::string gradient(const RadialGradient& radial, const Box& box) {
        const double width = box.max_x - box.min_x, height = box.max_y - box.min_y;
        const double cx = box.min_x + radial.cx * width, cy = box.min_y + radial.cy * height;
        std::string text = "\"g\":" + stops(radial) + ",\"s\":" + point(cx, cy) + ",\"e\":" + point(cx + radial.r * width, cy);
        return text + ",\"t\":2,\"h\":{\"a\":0,\"k\":0},\"a\":{\"a\":0,\"k\":0}";
    }

    // The stroke or fill item of `paint`; empty for none.
    std::string paint_item(const Layer& layer, const Paint& paint, const Box& box, bool is_stroke, double width) {
        const std::string line = is_stroke ? ",\"w\":" + property(Form::scalar, false, tolerance, decimals,
                                                                   {rounded(width, decimals + 1)}) +
                                                 ",\"lc\":2,\"lj\":2,\"ml\":4"
                                           : ",\"r\":1";
        switch (paint.kind) {
            case PaintKind::none: return {};
            case PaintKind::colour:
                return std::string("{\"ty\":\"") + (is_stroke ? "st" : "fl") + "\",\"c\":" + colour(paint.colour) +
                       ",\"o\":{\"a\":0,\"k\":100}" + line + ",\"bm\":0}";
            case PaintKind::gradient:
                return std::string("{\"ty\":\"") + (is_stroke ? "gs" : "gf") + "\",\"o\":{\"a\":0,\"k\":100}," +
                       gradient(layer.definitions.at(paint.gradient).gradient, box) + line + ",\"bm\":0}";
        }
        return {};
    }

    // The "sh" items of a path's subpaths; `outlines` gets their Bezier properties (for masks).
    std::vector<std::string> path_items(const Path& path, Box& box, std::vector<std::string>& outlines) {
        std::vector<std::string> shapes;
        for (const Subpath& subpath : subpaths_of(path)) {
            for (const Point2& p : subpath.vertices) box.add(p);
            for (const Point2& p : subpath.in) box.add(p);
            for (const Point2& p : subpath.out) box.add(p);
            outlines.push_back(bezier(subpath));
            shapes.push_back("{\"ty\":\"sh\",\"ks\":" + outlines.back() + "}");
        }
        return shapes;
    }

    // The masks of `outlines` (no brackets): their union ("a", added), or, `intersected` with the
    // masks before them ("i"), the one outline's.
    static std::string mask_items(const std::vector<std::string>& outlines, const char* name, bool intersected) {
        std::string masks;
        for (const std::string& outline : outlines) {
            if (!masks.empty()) masks += ',';
            masks += std::string("{\"inv\":false,\"mode\":\"") + (intersected ? "i" : "a") + "\",\"pt\":" + outline +
                     ",\"o\":{\"a\":0,\"k\":100},\"x\":{\"a\":0,\"k\":0},\"nm\":\"" + name + "\"}";
        }
        return masks;
    }

    static std::string masks_of(const std::vector<std::string>& outlines, const char* name) {
        return "[" + mask_items(outlines, name, false) + "]";
    }

    // A gradient fill in the bounding box's units as SVG draws it on a box that is not square (an
    // ellipse, which Lottie's radial gradients are not): a unit square filled with the gradient as a
    // circle, stretched onto the box by its group's transform, in a layer masked by the shape's
    // outline. A box of no height or width paints nothing, as in SVG.
    void add_fill_in_box(const RadialGradient& radial, const Box& box, const std::vector<std::string>& outlines,
                         const std::string& layer_name) {
        close_layer(name, {});
        const std::string gradient_stops = stops(radial);
        const std::string corner = point(box.min_x, box.min_y);
        const std::string size = property(Form::vector, false, 100.0 * tolerance, decimals,
                                          {rounded(100.0 * (box.max_x - box.min_x), decimals + 1),
                                           rounded(100.0 * (box.max_y - box.min_y), decimals + 1)});
        if (!write_text) return;
        const auto unit = [](double value) { return format_fixed(value, kUnitDecimals); };
        items.push_back(
            "{\"ty\":\"gr\",\"nm\":\"fill\",\"it\":[{\"ty\":\"rc\",\"p\":{\"a\":0,\"k\":[0.5,0.5]},"
            "\"s\":{\"a\":0,\"k\":[1,1]},\"r\":{\"a\":0,\"k\":0},\"d\":1},{\"ty\":\"gf\","
            "\"o\":{\"a\":0,\"k\":100},\"g\":" + gradient_stops + ",\"s\":{\"a\":0,\"k\":[" +
            unit(radial.cx) + "," + unit(radial.cy) + "]},\"e\":{\"a\":0,\"k\":[" + unit(radial.cx + radial.r) + "," +
            unit(radial.cy) + "]},\"t\":2,\"h\":{\"a\":0,\"k\":0},\"a\":{\"a\":0,\"k\":0},\"r\":1,\"bm\":0},"
            "{\"ty\":\"tr\",\"p\":" + corner + ",\"a\":{\"a\":0,\"k\":[0,0]},\"s\":" + size +
            ",\"r\":{\"a\":0,\"k\":0},\"o\":{\"a\":0,\"k\":100},\"sk\":{\"a\":0,\"k\":0},"
            "\"sa\":{\"a\":0,\"k\":0}}],\"bm\":0}");
        close_layer(layer_name, masks_of(outlines, "fill"));
    }

    // One shape as a group: its geometry, its stroke over its fill, and the group's transform.
    void add_shape(const Layer& layer, const Shape& shape) {
        const bool in_clip = !clip_masks.empty();
        Box box;
        std::vector<std::string> geometry;
        std::vector<std::string> outlines;
        switch (shape.kind) {
            case ShapeKind::path: geometry = path_items(shape.path, box, outlines); break;
            case ShapeKind::reference:
                geometry = path_items(reference_outline(layer, shape), box, outlines);
                break;
            case ShapeKind::polyline: {
                // Open: Lottie fills an open path as if closed, as SVG fills a polyline.
                Subpath subpath{shape.points, shape.points, shape.points, false};
                for (const Point2& p : shape.points) box.add(p);
                outlines.push_back(bezier(subpath));
                geometry.push_back("{\"ty\":\"sh\",\"ks\":" + outlines.back() + "}");
                break;
            }
            case ShapeKind::circle:
                box.add({shape.centre.x - shape.radius, shape.centre.y - shape.radius});
                box.add({shape.centre.x + shape.radius, shape.centre.y + shape.radius});
                geometry.push_back("{\"ty\":\"el\",\"p\":" + point(shape.centre.x, shape.centre.y) +
                                   ",\"s\":" + point(2.0 * shape.radius, 2.0 * shape.radius) + ",\"d\":1}");
                break;
            case ShapeKind::rect: {
                box.add(shape.corner);
                box.add({shape.corner.x + shape.width, shape.corner.y + shape.height});
                geometry.push_back("{\"ty\":\"rc\",\"p\":" +
                                   point(shape.corner.x + 0.5 * shape.width, shape.corner.y + 0.5 * shape.height) +
                                   ",\"s\":" + point(shape.width, shape.height) + ",\"r\":{\"a\":0,\"k\":0},\"d\":1}");
                const Point2 c = shape.corner;
                const std::vector<Point2> corners{
                    c, {c.x + shape.width, c.y}, {c.x + shape.width, c.y + shape.height}, {c.x, c.y + shape.height}};
                outlines.push_back(bezier(Subpath{corners, corners, corners, true}));
                break;
            }
            case ShapeKind::group: return;  // walk() takes groups apart
        }
        // A circle's box is square: its gradient is Lottie's own. Any other shape's may not be.
        const bool is_fill_in_box = shape.paint.fill.kind == PaintKind::gradient && shape.kind != ShapeKind::circle;
        if (is_fill_in_box) {
            if (in_clip) throw internal_error("a gradient fill inside a clipped group has no Lottie form (its mask would be a union inside an intersection)");
            add_fill_in_box(layer.definitions.at(shape.paint.fill.gradient).gradient, box, outlines,
                            name + " " + std::string(shape.name.empty() ? "fill" : shape.name));
        }
        const std::string stroke = paint_item(layer, shape.paint.stroke, box, true, shape.paint.stroke_width);
        const std::string fill = is_fill_in_box ? std::string() : paint_item(layer, shape.paint.fill, box, false, 0.0);
        if (!write_text || (stroke.empty() && fill.empty())) return;
        std::string group = "{\"ty\":\"gr\",\"nm\":" + json_quoted(shape.name.empty() ? "shape" : shape.name) +
                            ",\"it\":[";
        for (const std::string& item : geometry) group += item + ",";
        if (!stroke.empty()) group += stroke + ",";
        if (!fill.empty()) group += fill + ",";
        group += "{\"ty\":\"tr\",\"p\":{\"a\":0,\"k\":[0,0]},\"a\":{\"a\":0,\"k\":[0,0]},"
                 "\"s\":{\"a\":0,\"k\":[100,100]},\"r\":{\"a\":0,\"k\":0},\"o\":{\"a\":0,\"k\":100},"
                 "\"sk\":{\"a\":0,\"k\":0},\"sa\":{\"a\":0,\"k\":0}}],\"bm\":0}";
        items.push_back(std::move(group));
    }

    // Ends the current Lottie layer (if it drew anything).
    void close_layer(const std::string& layer_name, std::string masks) {
        if (items.empty()) return;
        LottieLayerContent content{layer_name, "[", std::move(masks)};
        for (std::size_t k = items.size(); k-- > 0;) {
            content.shapes += items[k];
            if (k > 0) content.shapes += ',';
        }
        content.shapes += ']';
        items.clear();
        if (write_text) layers.push_back(std::move(content));
    }

    // The masks of the clipped layer being drawn, as close_layer() takes them.
    std::string masks_now() const { return clip_masks.empty() ? std::string() : "[" + clip_masks + "]"; }

    // A clipped group is a layer of its own, masked by its clip; inside another, by both: its
    // mask intersects theirs (which a clip of several subpaths, a union, cannot do).
    void walk(const Layer& layer, const Shape& shape, const std::string& layer_name) {
        if (shape.kind != ShapeKind::group) {
            add_shape(layer, shape);
            return;
        }
        if (!shape.is_clipped) {
            for (const Shape& child : shape.children) walk(layer, child, layer_name);
            return;
        }
        close_layer(layer_name, masks_now());
        std::vector<std::string> outlines;
        for (const Subpath& subpath : subpaths_of(clip_outline(layer, layer.definitions.at(shape.definition)))) {
            outlines.push_back(bezier(subpath));
        }
        const bool intersected = !clip_masks.empty();
        if (intersected && outlines.size() != 1) {
            throw internal_error("a clip of " + std::to_string(outlines.size()) +
                                 " subpaths inside a clipped group has no Lottie form (masks intersect one by one)");
        }
        const std::string outer = clip_masks;
        clip_masks += (intersected ? "," : "") + mask_items(outlines, "clip", intersected);
        const std::string clipped_name = name + " " + std::string(shape.name.empty() ? "clipped" : shape.name);
        for (const Shape& child : shape.children) walk(layer, child, clipped_name);
        close_layer(clipped_name, masks_now());
        clip_masks = outer;
    }

    void walk(const Layer& layer) {
        for (const Shape& shape : layer.elements) walk(layer, shape, name);
        close_layer(name, {});
    }
};

LottieLayerEncoder::LottieLayerEncoder(std::string name, double tolerance, int decimals, std::size_t expected_frames)
    : name_(std::move(name)), tolerance_(tolerance), decimals_(decimals), expected_frames_(expected_frames) {}

void LottieLayerEncoder::add(const Layer& layer) {
    const std::size_t frame = frame_count_++;
    Frame walk{name_, tolerance_, decimals_, frame == 0, {}, {}, {}, {}};
    walk.walk(layer);
    if (frame == 0) {
        templates_ = std::move(walk.layers);
        properties_.resize(walk.values.size());
        for (std::size_t i = 0; i < properties_.size(); ++i) {
            Frame::Value& value = walk.values[i];
            Property& property = properties_[i];
            property.form = value.form;
            property.closed = value.closed;
            property.tolerance = value.tolerance;
            property.decimals = value.decimals;
            property.numbers.start(std::move(value.numbers));
        }
        return;
    }
    if (walk.values.size() != properties_.size()) {
        throw internal_error("frame " + std::to_string(frame) + " of layer " + name_ + " has " +
                             std::to_string(walk.values.size()) + " Lottie properties, frame 0 has " +
                             std::to_string(properties_.size()));
    }
    for (std::size_t i = 0; i < properties_.size(); ++i) {
        const Frame::Value& value = walk.values[i];
        Property& property = properties_[i];
        if (value.form != property.form || value.closed != property.closed ||
            value.numbers.size() != property.numbers.width()) {
            throw internal_error("frame " + std::to_string(frame) + " of layer " + name_ + " draws property " +
                                 std::to_string(i) + " with another form or number count than frame 0");
        }
        property.numbers.add(value.numbers, frame, expected_frames_);
    }
}

void LottieLayerEncoder::add_repeat() {
    if (frame_count_++ == 0) throw internal_error("no frame to repeat");
    for (Property& property : properties_) property.numbers.repeat();
}

std::size_t LottieLayerEncoder::animated_property_count() const {
    std::size_t count = 0;
    for (const Property& property : properties_) count += property.numbers.track().varies ? 1 : 0;
    return count;
}

std::string LottieLayerEncoder::property_text(const Property& property) const {
    bool folded = false;  // a closed path that ends where it starts: one vertex fewer (append_bezier)
    const auto append_value = [&](std::string& text, const double* numbers, std::size_t width, bool as_keyframe) {
        switch (property.form) {
            case Form::scalar:
                if (as_keyframe) {
                    append_number_list(text, numbers, 1, property.decimals);
                } else {
                    text += format_fixed(numbers[0], property.decimals);
                }
                return;
            case Form::vector: append_number_list(text, numbers, width, property.decimals); return;
            case Form::bezier:
                if (as_keyframe) text += '[';
                append_bezier(text, numbers, width, property.closed, folded, property.decimals);
                if (as_keyframe) text += ']';
                return;
        }
    };
    const Track& track = property.numbers.track();
    const std::size_t width = property.numbers.width();
    const bool is_closed_path = property.form == Form::bezier && property.closed && width >= 12;
    std::string text;
    if (!track.varies) {
        folded = is_closed_path && ends_at_start(property.numbers.first(), width);
        text = "{\"a\":0,\"k\":";
        append_value(text, property.numbers.first().data(), width, false);
        return text + "}";
    }
    const KeyFrames keys =
        choose_key_frames(track, frame_count_, std::vector<double>(width, property.tolerance));
    // Every key ending at its start, so does every shape the player interpolates between them.
    folded = is_closed_path && ends_at_start(keys.values.numbers, width);
    return keyed_value_text(keys, width, property.decimals, property.form == Form::bezier,
                            [&](std::string& out, const double* numbers) { append_value(out, numbers, width, true); });
}

std::string lottie_scalar_property(const KeyFrames& keys, double held_value, int decimals) {
    if (keys.positions.empty()) return "{\"a\":0,\"k\":" + format_fixed(held_value, decimals) + "}";
    return keyed_value_text(keys, 1, decimals, false, [decimals](std::string& out, const double* numbers) {
        append_number_list(out, numbers, 1, decimals);
    });
}

std::vector<LottieLayerContent> LottieLayerEncoder::finish() const {
    std::vector<std::string> texts(properties_.size());
    for (std::size_t i = 0; i < properties_.size(); ++i) texts[i] = property_text(properties_[i]);
    const auto fill_in = [&](const std::string& pattern) {
        std::string text;
        text.reserve(pattern.size());
        for (std::size_t at = 0; at < pattern.size();) {
            const std::size_t open = pattern.find('\x01', at);
            if (open == std::string::npos) {
                text.append(pattern, at, std::string::npos);
                break;
            }
            const std::size_t close = pattern.find('\x02', open);
            text.append(pattern, at, open - at);
            text += texts[std::stoul(pattern.substr(open + 1, close - open - 1))];
            at = close + 1;
        }
        return text;
    };
    std::vector<LottieLayerContent> layers;
    for (const LottieLayerContent& layer : templates_) {
        layers.push_back({layer.name, fill_in(layer.shapes), layer.masks.empty() ? std::string() : fill_in(layer.masks)});
    }
    return layers;
}

}  // namespace talkface::detail

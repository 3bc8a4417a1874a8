#include "raster/cairo_drawing.hpp"

#include <algorithm>
#include <cstddef>
#include <limits>

namespace talkface::detail {

namespace {

void add_path(cairo_t* cairo, const Path& path) {
    std::size_t next = 0;
    const std::vector<Point2>& p = path.points;
    for (const PathVerb verb : path.verbs) {
        switch (verb) {
            case PathVerb::move:
                cairo_move_to(cairo, p[next].x, p[next].y);
                break;
            case PathVerb::line:
                cairo_line_to(cairo, p[next].x, p[next].y);
                break;
            case PathVerb::cubic:
                cairo_curve_to(cairo, p[next].x, p[next].y, p[next + 1].x, p[next + 1].y, p[next + 2].x,
                               p[next + 2].y);
                break;
            case PathVerb::quadratic: {
                // cairo draws cubics only: the quadratic's controls raised by degree, exactly.
                double x0 = 0.0, y0 = 0.0;
                cairo_get_current_point(cairo, &x0, &y0);
                const Point2 control = p[next];
                const Point2 end = p[next + 1];
                cairo_curve_to(cairo, x0 + 2.0 / 3.0 * (control.x - x0), y0 + 2.0 / 3.0 * (control.y - y0),
                               end.x + 2.0 / 3.0 * (control.x - end.x), end.y + 2.0 / 3.0 * (control.y - end.y),
                               end.x, end.y);
                break;
            }
            case PathVerb::close: cairo_close_path(cairo); break;
        }
        next += static_cast<std::size_t>(points_of(verb));
    }
}

void add_geometry(cairo_t* cairo, const Layer& layer, const Shape& shape) {
    cairo_new_path(cairo);
    switch (shape.kind) {
        case ShapeKind::path: add_path(cairo, shape.path); return;
        case ShapeKind::polyline:
            for (std::size_t i = 0; i < shape.points.size(); ++i) {
                if (i == 0) {
                    cairo_move_to(cairo, shape.points[i].x, shape.points[i].y);
                } else {
                    cairo_line_to(cairo, shape.points[i].x, shape.points[i].y);
                }
            }
            return;
        case ShapeKind::circle:
            cairo_new_sub_path(cairo);
            cairo_arc(cairo, shape.centre.x, shape.centre.y, shape.radius, 0.0, 2.0 * 3.14159265358979323846);
            cairo_close_path(cairo);
            return;
        case ShapeKind::rect: cairo_rectangle(cairo, shape.corner.x, shape.corner.y, shape.width, shape.height); return;
        case ShapeKind::reference: add_path(cairo, reference_outline(layer, shape)); return;
        case ShapeKind::group: return;
    }
}

// The shape's bounding box as SVG's objectBoundingBox: its geometry, without the stroke.
CanvasBox geometry_box(cairo_t* cairo) {
    double x1 = 0.0, y1 = 0.0, x2 = 0.0, y2 = 0.0;
    cairo_path_extents(cairo, &x1, &y1, &x2, &y2);
    return {x1, y1, x2 - x1, y2 - y1};
}

// Sets the paint as the source; false for none.
bool set_source(cairo_t* cairo, const Layer& layer, const Paint& paint) {
    switch (paint.kind) {
        case PaintKind::none: return false;
        case PaintKind::colour:
            cairo_set_source_rgb(cairo, paint.colour.r / 255.0, paint.colour.g / 255.0, paint.colour.b / 255.0);
            return true;
        case PaintKind::gradient: {
            const RadialGradient& gradient = layer.definitions.at(paint.gradient).gradient;
            const CanvasBox box = geometry_box(cairo);
            if (box.width <= 0.0 || box.height <= 0.0) return false;  // SVG: no bounding box, no paint
            cairo_pattern_t* pattern =
                cairo_pattern_create_radial(gradient.cx, gradient.cy, 0.0, gradient.cx, gradient.cy, gradient.r);
            for (const GradientStop& stop : gradient.stops) {
                cairo_pattern_add_color_stop_rgb(pattern, stop.offset, stop.colour.r / 255.0, stop.colour.g / 255.0,
                                                 stop.colour.b / 255.0);
            }
            cairo_pattern_set_extend(pattern, CAIRO_EXTEND_PAD);
            // The pattern's space is the bounding box's units: user = box.x + u * box.width.
            cairo_matrix_t matrix;
            cairo_matrix_init(&matrix, 1.0 / box.width, 0.0, 0.0, 1.0 / box.height, -box.x / box.width,
                              -box.y / box.height);
            cairo_pattern_set_matrix(pattern, &matrix);
            cairo_set_source(cairo, pattern);
            cairo_pattern_destroy(pattern);
            return true;
        }
    }
    return false;
}

void draw_shape(cairo_t* cairo, const Layer& layer, const Shape& shape) {
    if (shape.kind == ShapeKind::group) {
        cairo_save(cairo);
        if (shape.is_clipped) {
            cairo_new_path(cairo);
            add_path(cairo, clip_outline(layer, layer.definitions.at(shape.definition)));
            cairo_set_fill_rule(cairo, CAIRO_FILL_RULE_WINDING);
            cairo_clip(cairo);
        }
        for (const Shape& child : shape.children) draw_shape(cairo, layer, child);
        cairo_restore(cairo);
        return;
    }
    add_geometry(cairo, layer, shape);
    // SVG paints the fill first, then the stroke over it.
    if (set_source(cairo, layer, shape.paint.fill)) cairo_fill_preserve(cairo);
    if (shape.paint.stroke_width > 0.0 && set_source(cairo, layer, shape.paint.stroke)) {
        cairo_set_line_width(cairo, shape.paint.stroke_width);
        cairo_stroke_preserve(cairo);
    }
    cairo_new_path(cairo);
}

struct Extent {
    double min_x = std::numeric_limits<double>::infinity();
    double min_y = std::numeric_limits<double>::infinity();
    double max_x = -std::numeric_limits<double>::infinity();
    double max_y = -std::numeric_limits<double>::infinity();
    double half_stroke = 0.0;

    void add(Point2 point, double margin) {
        min_x = std::min(min_x, point.x - margin);
        min_y = std::min(min_y, point.y - margin);
        max_x = std::max(max_x, point.x + margin);
        max_y = std::max(max_y, point.y + margin);
    }

    void add_shape(const Layer& layer, const Shape& shape) {
        half_stroke = std::max(half_stroke, 0.5 * shape.paint.stroke_width);
        switch (shape.kind) {
            case ShapeKind::path:
                for (const Point2& point : shape.path.points) add(point, 0.0);
                return;
            case ShapeKind::polyline:
                for (const Point2& point : shape.points) add(point, 0.0);
                return;
            case ShapeKind::circle: add(shape.centre, shape.radius); return;
            case ShapeKind::rect:
                add(shape.corner, 0.0);
                add({shape.corner.x + shape.width, shape.corner.y + shape.height}, 0.0);
                return;
            case ShapeKind::reference:
                for (const Point2& point : reference_outline(layer, shape).points) add(point, 0.0);
                return;
            case ShapeKind::group:
                for (const Shape& child : shape.children) add_shape(layer, child);
                return;
        }
    }
};

}  // namespace

void draw_layer(cairo_t* cairo, const Layer& layer) {
    cairo_set_fill_rule(cairo, CAIRO_FILL_RULE_WINDING);
    cairo_set_line_join(cairo, CAIRO_LINE_JOIN_ROUND);
    cairo_set_line_cap(cairo, CAIRO_LINE_CAP_ROUND);
    for (const Shape& shape : layer.elements) draw_shape(cairo, layer, shape);
}

CanvasBox layer_extent(const Layer& layer) {
    Extent extent;
    for (const Shape& shape : layer.elements) extent.add_shape(layer, shape);
    if (!(extent.min_x <= extent.max_x)) return {};
    const double margin = extent.half_stroke;
    return {extent.min_x - margin, extent.min_y - margin, extent.max_x - extent.min_x + 2.0 * margin,
            extent.max_y - extent.min_y + 2.0 * margin};
}

}  // namespace talkface::detail

#include "render/drawing.hpp"

namespace talkface::detail {

namespace {

Point2 middle_of(Point2 a, Point2 b) { return {0.5 * (a.x + b.x), 0.5 * (a.y + b.y)}; }

void list_shape(const Shape& shape, std::vector<NumericAttribute>& attributes) {
    switch (shape.kind) {
        case ShapeKind::path:
            attributes.push_back({AttributeKind::path_data, "d", &shape.path, nullptr, 0.0});
            return;
        case ShapeKind::polyline:
            attributes.push_back({AttributeKind::polyline_points, "points", nullptr, &shape.points, 0.0});
            return;
        case ShapeKind::circle:
            attributes.push_back({AttributeKind::number, "cx", nullptr, nullptr, shape.centre.x});
            attributes.push_back({AttributeKind::number, "cy", nullptr, nullptr, shape.centre.y});
            attributes.push_back({AttributeKind::number, "r", nullptr, nullptr, shape.radius});
            return;
        case ShapeKind::rect:
            attributes.push_back({AttributeKind::number, "x", nullptr, nullptr, shape.corner.x});
            attributes.push_back({AttributeKind::number, "y", nullptr, nullptr, shape.corner.y});
            attributes.push_back({AttributeKind::number, "width", nullptr, nullptr, shape.width});
            attributes.push_back({AttributeKind::number, "height", nullptr, nullptr, shape.height});
            return;
        case ShapeKind::reference: return;
        case ShapeKind::group:
            for (const Shape& child : shape.children) list_shape(child, attributes);
            return;
    }
}

}  // namespace

int points_of(PathVerb verb) {
    switch (verb) {
        case PathVerb::move:
        case PathVerb::line: return 1;
        case PathVerb::cubic: return 3;
        case PathVerb::quadratic: return 2;
        case PathVerb::close: return 0;
    }
    return 0;
}

Path& Path::move_to(Point2 point) {
    verbs.push_back(PathVerb::move);
    points.push_back(point);
    return *this;
}

Path& Path::line_to(Point2 point) {
    verbs.push_back(PathVerb::line);
    points.push_back(point);
    return *this;
}

Path& Path::curves(const std::vector<CubicSegment>& segments) {
    for (const CubicSegment& segment : segments) {
        verbs.push_back(PathVerb::cubic);
        points.insert(points.end(), {segment.c1, segment.c2, segment.end});
    }
    return *this;
}

Path& Path::arc(const std::vector<Point2>& arc_points) { return curves(arc_segments(arc_points)); }

Path& Path::corner_cut_closed(const std::vector<Point2>& corners) {
    const std::size_t n = corners.size();
    if (n < 3) return *this;
    move_to(middle_of(corners[n - 1], corners[0]));
    for (std::size_t i = 0; i < n; ++i) {
        verbs.push_back(PathVerb::quadratic);
        points.push_back(corners[i]);
        points.push_back(middle_of(corners[i], corners[(i + 1) % n]));
    }
    return close();
}

Path& Path::close() {
    verbs.push_back(PathVerb::close);
    return *this;
}

Path moved(const Path& path, Point2 offset) {
    Path result = path;
    for (Point2& point : result.points) point = {point.x + offset.x, point.y + offset.y};
    return result;
}

Path clip_outline(const Layer& layer, const Definition& clip) {
    if (!clip.is_moved) return clip.outline;
    return moved(layer.definitions.at(clip.source).outline, clip.offset);
}

Path reference_outline(const Layer& layer, const Shape& reference) {
    return moved(clip_outline(layer, layer.definitions.at(reference.definition)), reference.offset);
}

void list_numeric_attributes(const Layer& layer, std::vector<NumericAttribute>& attributes) {
    attributes.clear();
    for (const Definition& definition : layer.definitions) {
        if (definition.kind == DefinitionKind::clip_path && !definition.is_moved)
            attributes.push_back({AttributeKind::path_data, "d", &definition.outline, nullptr, 0.0});
    }
    for (const Shape& shape : layer.elements) list_shape(shape, attributes);
}

}  // namespace talkface::detail

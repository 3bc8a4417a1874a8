#include "render/curves.hpp"

#include <cstddef>


namespace talkface::detail {

namespace {

Point2 operator+(Point2 a, Point2 b) { return {a.x + b.x, a.y + b.y}; }
Point2 operator-(Point2 a, Point2 b) { return {a.x - b.x, a.y - b.y}; }
Point2 operator*(double s, Point2 a) { return {s * a.x, s * a.y}; }

// The Bezier form of the Catmull-Rom segment p1 -> p2 with outer neighbours p0 and p3.
CubicSegment catmull_rom_segment(Point2 p0, Point2 p1, Point2 p2, Point2 p3) {
    return {p1 + (1.0 / 6.0) * (p2 - p0), p2 - (1.0 / 6.0) * (p3 - p1), p2};
}

}  // namespace

std::vector<CubicSegment> arc_segments(const std::vector<Point2>& points) {
    std::vector<CubicSegment> segments;
    const std::size_t n = points.size();
    if (n < 2) return segments;
    const Point2 before_first = 2.0 * points[0] - points[1];
    const Point2 after_last = 2.0 * points[n - 1] - points[n - 2];
    for (std::size_t i = 0; i + 1 < n; ++i) {
        const Point2 p0 = i == 0 ? before_first : points[i - 1];
        const Point2 p3 = i + 2 < n ? points[i + 2] : after_last;
        segments.push_back(catmull_rom_segment(p0, points[i], points[i + 1], p3));
    }
    return segments;
}

std::vector<CubicSegment> closed_curve_segments(const std::vector<Point2>& points) {
    std::vector<CubicSegment> segments;
    const std::size_t n = points.size();
    if (n < 2) return segments;
    for (std::size_t i = 0; i < n; ++i) {
        segments.push_back(catmull_rom_segment(points[(i + n - 1) % n], points[i],
                                               points[(i + 1) % n], points[(i + 2) % n]));
    }
    return segments;
}

}  // namespace talkface::detail

// The two curve drawing methods of thesis 2.2: cubic Bezier curves through given points (the
// thesis's arc(P1, ..., Pn)) and corner-cutting subdivision of a polygon (hair and eyebrows).
#ifndef TALKFACE_RENDER_CURVES_HPP
#define TALKFACE_RENDER_CURVES_HPP

#include <vector>

#include "talkface/types.hpp"

namespace talkface::detail {

// One cubic Bezier segment: from the pen's position through control points c1, c2 to `end`.
struct CubicSegment {
    Point2 c1;
    Point2 c2;
    Point2 end;
};

// arc(P1, ..., Pn): Catmull-Rom through every point, as cubic Bezier segments starting at P1.
// An end's tangent points at its neighbour (the missing outer point is P1 reflected through P2),
// so several arcs joined at their ends meet in a corner, as the eye and lip corners should.
std::vector<CubicSegment> arc_segments(const std::vector<Point2>& points);

// A closed Catmull-Rom curve through every point, smooth everywhere (the face contour, whose
// four arcs meet without corners). Starts and ends at points.front().
std::vector<CubicSegment> closed_curve_segments(const std::vector<Point2>& points);

}  // namespace talkface::detail

#endif

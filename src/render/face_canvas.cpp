#include "render/face_canvas.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "talkface/face_pose.hpp"
#include "talkface/mouth_shape.hpp"

namespace talkface::detail {

namespace {

// Room around the outermost points for the curves' overshoot between points and the outline's
// width: a Catmull-Rom control point lies at most 1/6 of a neighbour span outside.
constexpr double kMarginInD = 0.35;
// The clothes layer reaches this far from O (see clothes_drawing.cpp), so the canvas shows them.
constexpr double kMinHalfWidthInD = 2.2;
constexpr double kMinBottomBelowOriginInD = 1.9;

}  // namespace

CanvasBox fit_face_canvas(const FaceModel& face) {
    double min_x = std::numeric_limits<double>::infinity();
    double min_y = min_x;
    double max_x = -min_x;
    double max_y = -min_x;
    std::vector<FaceState> states(3);
    states[1].mouth = mouth_controls(face, MouthShape::a);
    states[2].expression.brows = 1.0;
    Point2 origin;
    double d = 0.0;
    const double angles[] = {-kMaxPoseAngleDeg, 0.0, kMaxPoseAngleDeg};
    for (FaceState state : states) {
        for (double alpha : angles) {
            for (double beta : angles) {
                for (double gamma : angles) {
                    state.pose = {alpha, beta, gamma};
                    const ProjectedFace projected = project_face(face, state);
                    for (const ProjectedPoint& point : projected.points) {
                        const Point2& p = point.xy;
                        min_x = std::min(min_x, p.x);
                        max_x = std::max(max_x, p.x);
                        min_y = std::min(min_y, p.y);
                        max_y = std::max(max_y, p.y);
                    }
                    origin = projected.origin;
                    d = projected.d;
                }
            }
        }
    }
    const double margin = kMarginInD * d;
    const double half_width =
        std::max({origin.x - min_x + margin, max_x - origin.x + margin, kMinHalfWidthInD * d});
    const double top = std::floor(min_y - margin);
    const double bottom = std::ceil(std::max(max_y + margin, origin.y + kMinBottomBelowOriginInD * d));
    const double left = std::floor(origin.x - half_width);
    const double right = std::ceil(origin.x + half_width);
    return {left, top, right - left, bottom - top};
}

}  // namespace talkface::detail

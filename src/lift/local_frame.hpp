// The face's local frame (Point3: origin O, x towards the image left, y up, z towards the
// viewer) and image pixels: shared by the lift and the projection; a user only sees image pixels.
#ifndef TALKFACE_LIFT_LOCAL_FRAME_HPP
#define TALKFACE_LIFT_LOCAL_FRAME_HPP

#include "talkface/types.hpp"

namespace talkface::detail {

// Image to local: x' = x_o - x, y' = y_o - y, z kept (SPEC: the exact inverse of to_image()).
inline Point3 to_local(Point2 image_xy, double z, Point2 origin) {
    return {origin.x - image_xy.x, origin.y - image_xy.y, z};
}

// Local to image, orthographic: x = x_o - x', y = y_o - y', z dropped. The thesis's "x_p + x_o"
// would mirror the face.
inline Point2 to_image(Point3 local_xyz, Point2 origin) {
    return {origin.x - local_xyz.x, origin.y - local_xyz.y};
}

}  // namespace talkface::detail

#endif

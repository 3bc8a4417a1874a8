// tf_lifted_face, the local frame and tf_place_face: the C face of face_lift.hpp.
#include <string>

#include "c_api_guard.hpp"
#include "c_api_handles.hpp"

using talkface::InvalidArgument;
using talkface::Point2;
using talkface::Point3;
using talkface::capi::guard;
using talkface::capi::new_face;
using talkface::capi::require_non_null;

namespace {

void check_index(size_t index, size_t count) {
    if (index >= count) {
        throw InvalidArgument("index",
                              "expected 0.." + std::to_string(count - 1) + ", got " + std::to_string(index));
    }
}

void from_point3(Point3 point, double out_xyz[3]) {
    out_xyz[0] = point.x;
    out_xyz[1] = point.y;
    out_xyz[2] = point.z;
}

}  // namespace

extern "C" {

tf_status tf_lift_face(const tf_face_model* face, tf_lifted_face** out) {
    return guard([&] {
        require_non_null(face, "face");
        require_non_null(out, "out");
        *out = new tf_lifted_face{talkface::lift_face(face->model)};
    });
}

void tf_lifted_face_destroy(tf_lifted_face* lifted) {
    delete lifted;
}

tf_status tf_lifted_face_origin(const tf_lifted_face* lifted, double* out_x, double* out_y,
                                double* out_d_px) {
    return guard([&] {
        require_non_null(lifted, "lifted");
        require_non_null(out_x, "out_x");
        require_non_null(out_y, "out_y");
        require_non_null(out_d_px, "out_d_px");
        *out_x = lifted->lifted.origin.x;
        *out_y = lifted->lifted.origin.y;
        *out_d_px = lifted->lifted.d;
    });
}

tf_status tf_lifted_face_point_count(const tf_lifted_face* lifted, size_t* out_count) {
    return guard([&] {
        require_non_null(lifted, "lifted");
        require_non_null(out_count, "out_count");
        *out_count = lifted->lifted.points.size();
    });
}

tf_status tf_lifted_face_point_id(const tf_lifted_face* lifted, size_t index, const char** out_id) {
    return guard([&] {
        require_non_null(lifted, "lifted");
        require_non_null(out_id, "out_id");
        check_index(index, lifted->lifted.points.size());
        *out_id = lifted->lifted.points[index].id.c_str();
    });
}

tf_status tf_lifted_face_local(const tf_lifted_face* lifted, const char* id, double out_local_xyz[3]) {
    return guard([&] {
        require_non_null(lifted, "lifted");
        require_non_null(id, "id");
        require_non_null(out_local_xyz, "out_local_xyz");
        from_point3(lifted->lifted.local(id), out_local_xyz);
    });
}

tf_status tf_depth_in_d(const char* id, double* out_depth_in_d) {
    return guard([&] {
        require_non_null(id, "id");
        require_non_null(out_depth_in_d, "out_depth_in_d");
        *out_depth_in_d = talkface::depth_in_d(id);
    });
}

tf_status tf_rotation_origin(const tf_face_model* face, double* out_x, double* out_y) {
    return guard([&] {
        require_non_null(face, "face");
        require_non_null(out_x, "out_x");
        require_non_null(out_y, "out_y");
        const Point2 origin = talkface::rotation_origin(face->model);
        *out_x = origin.x;
        *out_y = origin.y;
    });
}

tf_status tf_place_face(const tf_face_model* face, double origin_x, double origin_y, double d_px,
                        tf_face_model** out) {
    return guard([&] {
        require_non_null(face, "face");
        require_non_null(out, "out");
        *out = new_face(talkface::place_face(face->model, Point2{origin_x, origin_y}, d_px));
    });
}

}  // extern "C"

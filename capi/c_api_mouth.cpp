// Mouth shapes and expressions: the C face of mouth_shape.hpp and expression.hpp.
#include "c_api_guard.hpp"
#include "c_api_handles.hpp"
#include "talkface/expression.hpp"

using talkface::MouthControls;
using talkface::capi::from_point;
using talkface::capi::guard;
using talkface::capi::new_face;
using talkface::capi::require_non_null;
using talkface::capi::to_mouth_shape;
using talkface::capi::to_point;

namespace {

void require_controls_out(double* up, double* down, double* left, double* right) {
    require_non_null(up, "out_up");
    require_non_null(down, "out_down");
    require_non_null(left, "out_left");
    require_non_null(right, "out_right");
}

void from_controls(const MouthControls& controls, double up[2], double down[2], double left[2],
                   double right[2]) {
    from_point(controls.up, up);
    from_point(controls.down, down);
    from_point(controls.left, left);
    from_point(controls.right, right);
}

}  // namespace

extern "C" {

const char* tf_mouth_shape_name(tf_mouth_shape shape) {
    const int value = talkface::capi::enum_value(shape);
    if (value < 0 || value >= TF_MOUTH_SHAPE_COUNT) return nullptr;
    return talkface::mouth_shape_name(static_cast<talkface::MouthShape>(value));
}

tf_status tf_mouth_shape_from_name(const char* name, tf_mouth_shape* out) {
    return guard([&] {
        require_non_null(name, "name");
        require_non_null(out, "out");
        *out = static_cast<tf_mouth_shape>(talkface::mouth_shape_from_name(name));
    });
}

tf_status tf_neutral_mouth_controls(const tf_face_model* neutral, double out_up[2], double out_down[2],
                                    double out_left[2], double out_right[2]) {
    return guard([&] {
        require_non_null(neutral, "neutral");
        require_controls_out(out_up, out_down, out_left, out_right);
        from_controls(talkface::neutral_mouth_controls(neutral->model), out_up, out_down, out_left,
                      out_right);
    });
}

tf_status tf_mouth_controls(const tf_face_model* neutral, tf_mouth_shape shape, double out_up[2],
                            double out_down[2], double out_left[2], double out_right[2]) {
    return guard([&] {
        require_non_null(neutral, "neutral");
        require_controls_out(out_up, out_down, out_left, out_right);
        from_controls(talkface::mouth_controls(neutral->model, to_mouth_shape(shape, "shape")), out_up,
                      out_down, out_left, out_right);
    });
}

tf_status tf_apply_mouth(const tf_face_model* neutral, const double up[2], const double down[2],
                         const double left[2], const double right[2], tf_face_model** out) {
    return guard([&] {
        require_non_null(neutral, "neutral");
        require_non_null(up, "up");
        require_non_null(down, "down");
        require_non_null(left, "left");
        require_non_null(right, "right");
        require_non_null(out, "out");
        const MouthControls controls{to_point(up), to_point(down), to_point(left), to_point(right)};
        *out = new_face(talkface::apply_mouth(neutral->model, controls));
    });
}

tf_status tf_apply_expression(const tf_face_model* face, double blink_left, double blink_right, double smile,
                              double brows, tf_face_model** out) {
    return guard([&] {
        require_non_null(face, "face");
        require_non_null(out, "out");
        talkface::Expression expression;
        expression.blink_left = blink_left;
        expression.blink_right = blink_right;
        expression.smile = smile;
        expression.brows = brows;
        *out = new_face(talkface::apply_expression(face->model, expression));
    });
}

}  // extern "C"

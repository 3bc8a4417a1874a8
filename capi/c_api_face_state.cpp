// tf_face_state and tf_projected_face: the C face of face_pose.hpp.
#include <cmath>
#include <sstream>
#include <string>

#include "c_api_guard.hpp"
#include "c_api_handles.hpp"

using talkface::InvalidArgument;
using talkface::MouthControls;
using talkface::Point2;
using talkface::capi::guard;
using talkface::capi::new_face;
using talkface::capi::require_non_null;
using talkface::capi::to_mouth_shape;
using talkface::capi::to_point;

namespace {

std::string number_text(double value) {
    std::ostringstream out;
    out << value;
    return out.str();
}

// The setters check at once, so a C caller learns which call passed the bad value (project_face would
// only report it at the first projection, far from the mistake).
void check_angle(double angle_deg, const char* name) {
    if (!std::isfinite(angle_deg) || std::fabs(angle_deg) > talkface::kMaxPoseAngleDeg) {
        throw InvalidArgument(name, "expected -" + number_text(talkface::kMaxPoseAngleDeg) + ".." +
                                        number_text(talkface::kMaxPoseAngleDeg) + " degrees, got " +
                                        number_text(angle_deg));
    }
}

void check_amount(double amount, const char* name) {
    if (!std::isfinite(amount) || amount < 0.0 || amount > 1.0) {
        throw InvalidArgument(name, "expected an amount in 0..1, got " + number_text(amount));
    }
}

Point2 checked_point(const double xy[2], const char* name) {
    require_non_null(xy, name);
    if (!std::isfinite(xy[0]) || !std::isfinite(xy[1])) {
        throw InvalidArgument(name, "coordinates must be finite");
    }
    return to_point(xy);
}

size_t index_of(const talkface::ProjectedFace& projected, size_t index) {
    if (index >= projected.points.size()) {
        throw InvalidArgument("index", "expected 0.." + std::to_string(projected.points.size() - 1) +
                                           ", got " + std::to_string(index));
    }
    return index;
}

}  // namespace

extern "C" {

tf_status tf_face_state_create(tf_face_state** out) {
    return guard([&] {
        require_non_null(out, "out");
        *out = new tf_face_state{};
    });
}

void tf_face_state_destroy(tf_face_state* state) {
    delete state;
}

tf_status tf_face_state_set_pose(tf_face_state* state, double alpha_deg, double beta_deg, double gamma_deg) {
    return guard([&] {
        require_non_null(state, "state");
        check_angle(alpha_deg, "alpha_deg");
        check_angle(beta_deg, "beta_deg");
        check_angle(gamma_deg, "gamma_deg");
        state->state.pose = talkface::Pose{alpha_deg, beta_deg, gamma_deg};
    });
}

tf_status tf_face_state_set_blink(tf_face_state* state, double left, double right) {
    return guard([&] {
        require_non_null(state, "state");
        check_amount(left, "blink_left");
        check_amount(right, "blink_right");
        state->state.expression.blink_left = left;
        state->state.expression.blink_right = right;
    });
}

tf_status tf_face_state_set_smile(tf_face_state* state, double amount) {
    return guard([&] {
        require_non_null(state, "state");
        check_amount(amount, "smile");
        state->state.expression.smile = amount;
    });
}

tf_status tf_face_state_set_brows(tf_face_state* state, double amount) {
    return guard([&] {
        require_non_null(state, "state");
        check_amount(amount, "brows");
        state->state.expression.brows = amount;
    });
}

tf_status tf_face_state_set_mouth_shape(tf_face_state* state, const tf_face_model* face,
                                        tf_mouth_shape shape) {
    return guard([&] {
        require_non_null(state, "state");
        require_non_null(face, "face");
        state->state.mouth = talkface::mouth_controls(face->model, to_mouth_shape(shape, "shape"));
    });
}

tf_status tf_face_state_set_mouth_controls(tf_face_state* state, const double up[2], const double down[2],
                                           const double left[2], const double right[2]) {
    return guard([&] {
        require_non_null(state, "state");
        const MouthControls controls{checked_point(up, "up"), checked_point(down, "down"),
                                     checked_point(left, "left"), checked_point(right, "right")};
        state->state.mouth = controls;
    });
}

tf_status tf_face_state_set_neutral_mouth(tf_face_state* state) {
    return guard([&] {
        require_non_null(state, "state");
        state->state.mouth.reset();
    });
}

tf_status tf_project_face(const tf_face_model* face, const tf_face_state* state, tf_projected_face** out) {
    return guard([&] {
        require_non_null(face, "face");
        require_non_null(state, "state");
        require_non_null(out, "out");
        *out = new tf_projected_face{talkface::project_face(face->model, state->state)};
    });
}

void tf_projected_face_destroy(tf_projected_face* projected) {
    delete projected;
}

tf_status tf_projected_face_point(const tf_projected_face* projected, const char* id, double* out_x,
                                  double* out_y) {
    return guard([&] {
        require_non_null(projected, "projected");
        require_non_null(id, "id");
        require_non_null(out_x, "out_x");
        require_non_null(out_y, "out_y");
        const Point2 point = projected->projected.point(id);
        *out_x = point.x;
        *out_y = point.y;
    });
}

tf_status tf_projected_face_point_count(const tf_projected_face* projected, size_t* out_count) {
    return guard([&] {
        require_non_null(projected, "projected");
        require_non_null(out_count, "out_count");
        *out_count = projected->projected.points.size();
    });
}

tf_status tf_projected_face_point_id(const tf_projected_face* projected, size_t index, const char** out_id) {
    return guard([&] {
        require_non_null(projected, "projected");
        require_non_null(out_id, "out_id");
        *out_id = projected->projected.points[index_of(projected->projected, index)].id.c_str();
    });
}

tf_status tf_projected_face_contour(const tf_projected_face* projected, tf_side side,
                                    const char* out_ids[3]) {
    return guard([&] {
        require_non_null(projected, "projected");
        require_non_null(out_ids, "out_ids");
        const int side_value = talkface::capi::enum_value(side);
        if (side_value != TF_SIDE_LEFT && side_value != TF_SIDE_RIGHT) {
            throw InvalidArgument(
                "side", "expected TF_SIDE_LEFT (0) or TF_SIDE_RIGHT (1), got " + std::to_string(side_value));
        }
        const std::array<std::string, 3>& contour = side_value == TF_SIDE_LEFT
                                                        ? projected->projected.left_contour
                                                        : projected->projected.right_contour;
        for (size_t i = 0; i < 3; ++i) out_ids[i] = contour[i].c_str();
    });
}

tf_status tf_projected_face_nose_bridge(const tf_projected_face* projected, tf_side* out_side) {
    return guard([&] {
        require_non_null(projected, "projected");
        require_non_null(out_side, "out_side");
        *out_side =
            projected->projected.nose_bridge == talkface::NoseBridgeSide::left ? TF_SIDE_LEFT : TF_SIDE_RIGHT;
    });
}

tf_status tf_projected_face_origin(const tf_projected_face* projected, double* out_x, double* out_y,
                                   double* out_d_px) {
    return guard([&] {
        require_non_null(projected, "projected");
        require_non_null(out_x, "out_x");
        require_non_null(out_y, "out_y");
        require_non_null(out_d_px, "out_d_px");
        *out_x = projected->projected.origin.x;
        *out_y = projected->projected.origin.y;
        *out_d_px = projected->projected.d;
    });
}

tf_status tf_projected_face_face(const tf_projected_face* projected, tf_face_model** out) {
    return guard([&] {
        require_non_null(projected, "projected");
        require_non_null(out, "out");
        *out = new_face(projected->projected.face);
    });
}

}  // extern "C"

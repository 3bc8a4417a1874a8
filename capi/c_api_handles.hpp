// The opaque handles of talkface.h: each wraps the C++ value it stands for. Shared by the capi/
// files because rendering reads faces, states and options together.
#ifndef TALKFACE_CAPI_C_API_HANDLES_HPP
#define TALKFACE_CAPI_C_API_HANDLES_HPP

#include <cmath>
#include <optional>
#include <string>

#include "c_api_guard.hpp"
#include "talkface/animation.hpp"
#include "talkface/errors.hpp"
#include "talkface/expression_simulator.hpp"
#include "talkface/face_lift.hpp"
#include "talkface/face_model.hpp"
#include "talkface/face_pose.hpp"
#include "talkface/frame_renderer.hpp"
#include "talkface/lip_sync.hpp"
#include "talkface/mouth_shape.hpp"
#include "talkface/speech_aligner.hpp"
#include "talkface/svg_animator.hpp"
#include "talkface/talkface.h"
#include "talkface/timeline.hpp"

struct tf_face_model {
    talkface::FaceModel model;
};

struct tf_lifted_face {
    talkface::LiftedFace lifted;
};

struct tf_face_state {
    talkface::FaceState state;
};

struct tf_projected_face {
    talkface::ProjectedFace projected;
};

struct tf_svg_options {
    talkface::SvgOptions options;
};

struct tf_timeline {
    talkface::Timeline timeline;
};

struct tf_expression_style {
    talkface::ExpressionStyle style;
};

struct tf_expression_simulator {
    talkface::ExpressionSimulator simulator;
};

struct tf_lip_sync_options {
    talkface::LipSyncOptions options;
};

struct tf_animation {
    talkface::Animation animation;
};

struct tf_align_options {
    talkface::AlignOptions options;
};

namespace talkface::capi {

// A new handle owning `model`, for the (tf_face_model **out) of every call that makes a face.
inline tf_face_model* new_face(FaceModel model) {
    return new tf_face_model{std::move(model)};
}

// A C colour; NULL (for an optional one) is none.
inline Rgb to_rgb(tf_rgb colour) {
    return Rgb{colour.r, colour.g, colour.b};
}
inline std::optional<Rgb> to_optional_rgb(const tf_rgb* colour) {
    return colour == nullptr ? std::nullopt : std::optional<Rgb>(to_rgb(*colour));
}

inline Point2 to_point(const double xy[2]) {
    return Point2{xy[0], xy[1]};
}

// An animator per call: it only holds a copy of the face and the options, so a C caller needs no
// animator handle to keep in step with its face. NULL options are the defaults.
inline SvgAnimator animator_for(const tf_face_model* face, const tf_svg_options* options) {
    return SvgAnimator(face->model, options != nullptr ? options->options : SvgOptions{});
}

// Where a frame puts the face, from C: a NULL origin leaves the layout's own place (both frame
// options and a video's look take it so).
inline void set_face_placement(FrameOptions& options, const double origin_px[2], double d_px) {
    options.face_origin_px = origin_px == nullptr ? std::nullopt : std::optional<Point2>(to_point(origin_px));
    options.face_d_px = d_px;
}

inline void from_point(Point2 point, double out_xy[2]) {
    out_xy[0] = point.x;
    out_xy[1] = point.y;
}

// Throws InvalidArgument naming `parameter` unless `shape` is one of the 12 tf_mouth_shape values
// (a C enum may hold any int).
inline MouthShape to_mouth_shape(const tf_mouth_shape& shape, const char* parameter) {
    const int value = enum_value(shape);
    if (value < 0 || value >= TF_MOUTH_SHAPE_COUNT) {
        throw InvalidArgument(parameter, "expected a tf_mouth_shape (0.." +
                                             std::to_string(TF_MOUTH_SHAPE_COUNT - 1) + "), got " +
                                             std::to_string(value));
    }
    return static_cast<MouthShape>(value);
}

}  // namespace talkface::capi

#endif

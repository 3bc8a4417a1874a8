// tf_expression_simulator, tf_lip_sync_options and tf_animation: the C face of
// expression_simulator.hpp and animation.hpp.
#include <algorithm>
#include <string>
#include <vector>

#include "c_api_guard.hpp"
#include "c_api_handles.hpp"

using talkface::ExpressionEvent;
using talkface::ExpressionEventKind;
using talkface::FaceState;
using talkface::InvalidArgument;
using talkface::capi::enum_value;
using talkface::capi::from_point;
using talkface::capi::guard;
using talkface::capi::require_non_null;

namespace {

constexpr int kEventKindCount = 5;

// Throws InvalidArgument naming `parameter` unless `kind` is a tf_expression_event_kind (a C enum
// may hold any int).
ExpressionEventKind to_event_kind(const tf_expression_event_kind& kind, const std::string& parameter) {
    const int value = enum_value(kind);
    if (value < 0 || value >= kEventKindCount) {
        throw InvalidArgument(parameter, "expected a tf_expression_event_kind (0.." +
                                             std::to_string(kEventKindCount - 1) + "), got " +
                                             std::to_string(value));
    }
    return static_cast<ExpressionEventKind>(value);
}

tf_expression_event to_c_event(const ExpressionEvent& event) {
    tf_expression_event result;
    result.kind = static_cast<tf_expression_event_kind>(event.kind);
    result.start_s = event.start_s;
    result.end_s = event.end_s;
    result.amount = event.amount;
    return result;
}

template <typename Items>
const auto& item_at(const Items& items, size_t index, const char* what) {
    if (index >= items.size()) {
        throw InvalidArgument("index", std::string("expected a ") + what + " index below " +
                                           std::to_string(items.size()) + ", got " + std::to_string(index));
    }
    return items[index];
}

// The row of the onset table for syllables of `shape_count` shapes, which holds shape_count - 1
// fractions.
template <typename Table>
auto* onset_row(Table& table, size_t shape_count) {
    if (shape_count < 2 || shape_count > 4) {
        throw InvalidArgument("shape_count",
                              "expected 2, 3 or 4 (a syllable of one shape has no onsets to set), got " +
                                  std::to_string(shape_count));
    }
    return shape_count == 2 ? table.two_shapes.data() : shape_count == 3 ? table.three_shapes.data()
                                                                         : table.four_shapes.data();
}

const FaceState& frame_at(const tf_animation* animation, size_t index) {
    return item_at(animation->animation.frames, index, "frame");
}

}  // namespace

extern "C" {

const char* tf_expression_event_kind_name(tf_expression_event_kind kind) {
    const int value = enum_value(kind);
    if (value < 0 || value >= kEventKindCount) return nullptr;
    return talkface::expression_event_kind_name(static_cast<ExpressionEventKind>(value));
}

tf_status tf_expression_event_kind_from_name(const char* name, tf_expression_event_kind* out) {
    return guard([&] {
        require_non_null(name, "name");
        require_non_null(out, "out");
        *out = static_cast<tf_expression_event_kind>(talkface::expression_event_kind_from_name(name));
    });
}

tf_status tf_expression_simulator_create(const tf_timeline* timeline, uint64_t seed, const char* style_name,
                                         tf_expression_simulator** out) {
    return guard([&] {
        require_non_null(timeline, "timeline");
        require_non_null(out, "out");
        const talkface::ExpressionStyle style =
            talkface::ExpressionStyle::from_name(style_name != nullptr ? style_name : "normal");
        *out = new tf_expression_simulator{talkface::ExpressionSimulator(timeline->timeline, seed, style)};
    });
}

void tf_expression_simulator_destroy(tf_expression_simulator* simulator) {
    delete simulator;
}

tf_status tf_expression_simulator_duration_s(const tf_expression_simulator* simulator, double* out_duration_s) {
    return guard([&] {
        require_non_null(simulator, "simulator");
        require_non_null(out_duration_s, "out_duration_s");
        *out_duration_s = simulator->simulator.duration_s();
    });
}

tf_status tf_expression_simulator_event_count(const tf_expression_simulator* simulator, size_t* out_count) {
    return guard([&] {
        require_non_null(simulator, "simulator");
        require_non_null(out_count, "out_count");
        *out_count = simulator->simulator.events().size();
    });
}

tf_status tf_expression_simulator_event(const tf_expression_simulator* simulator, size_t index,
                                        tf_expression_event* out) {
    return guard([&] {
        require_non_null(simulator, "simulator");
        require_non_null(out, "out");
        *out = to_c_event(item_at(simulator->simulator.events(), index, "event"));
    });
}

tf_status tf_expression_simulator_set_user_events(tf_expression_simulator* simulator,
                                                  const tf_expression_event* events, size_t count,
                                                  tf_user_event_mode mode) {
    return guard([&] {
        require_non_null(simulator, "simulator");
        if (count > 0) require_non_null(events, "events");
        const int mode_value = enum_value(mode);
        if (mode_value != TF_EVENTS_ADD && mode_value != TF_EVENTS_REPLACE) {
            throw InvalidArgument("mode", "expected TF_EVENTS_ADD (0) or TF_EVENTS_REPLACE (1), got " +
                                              std::to_string(mode_value));
        }
        std::vector<ExpressionEvent> converted;
        converted.reserve(count);
        for (size_t k = 0; k < count; ++k) {
            converted.push_back({to_event_kind(events[k].kind, "events[" + std::to_string(k) + "].kind"),
                                 events[k].start_s, events[k].end_s, events[k].amount});
        }
        simulator->simulator.set_user_events(converted, static_cast<talkface::UserEventMode>(mode_value));
    });
}

tf_status tf_expression_simulator_pose_at(const tf_expression_simulator* simulator, double time_s,
                                          double* out_alpha_deg, double* out_beta_deg, double* out_gamma_deg) {
    return guard([&] {
        require_non_null(simulator, "simulator");
        require_non_null(out_alpha_deg, "out_alpha_deg");
        require_non_null(out_beta_deg, "out_beta_deg");
        require_non_null(out_gamma_deg, "out_gamma_deg");
        const talkface::Pose pose = simulator->simulator.pose_at(time_s);
        *out_alpha_deg = pose.alpha_deg;
        *out_beta_deg = pose.beta_deg;
        *out_gamma_deg = pose.gamma_deg;
    });
}

tf_status tf_expression_simulator_expression_at(const tf_expression_simulator* simulator, double time_s,
                                                double* out_blink_left, double* out_blink_right,
                                                double* out_smile, double* out_brows) {
    return guard([&] {
        require_non_null(simulator, "simulator");
        require_non_null(out_blink_left, "out_blink_left");
        require_non_null(out_blink_right, "out_blink_right");
        require_non_null(out_smile, "out_smile");
        require_non_null(out_brows, "out_brows");
        const talkface::Expression expression = simulator->simulator.expression_at(time_s);
        *out_blink_left = expression.blink_left;
        *out_blink_right = expression.blink_right;
        *out_smile = expression.smile;
        *out_brows = expression.brows;
    });
}

tf_status tf_lip_sync_options_create(tf_lip_sync_options** out) {
    return guard([&] {
        require_non_null(out, "out");
        *out = new tf_lip_sync_options{};
    });
}

void tf_lip_sync_options_destroy(tf_lip_sync_options* options) {
    delete options;
}

tf_status tf_lip_sync_options_set_fps(tf_lip_sync_options* options, double fps) {
    return guard([&] {
        require_non_null(options, "options");
        options->options.fps = fps;
    });
}

tf_status tf_lip_sync_options_set_rest(tf_lip_sync_options* options, double rest_min_pause_s,
                                       double rest_transition_s) {
    return guard([&] {
        require_non_null(options, "options");
        options->options.rest_min_pause_s = rest_min_pause_s;
        options->options.rest_transition_s = rest_transition_s;
    });
}

tf_status tf_lip_sync_options_set_onsets(tf_lip_sync_options* options, size_t shape_count,
                                         const double* fractions) {
    return guard([&] {
        require_non_null(options, "options");
        require_non_null(fractions, "fractions");
        double* row = onset_row(options->options.onsets, shape_count);
        std::copy(fractions, fractions + (shape_count - 1), row);
    });
}

tf_status tf_lip_sync_options_get_onsets(const tf_lip_sync_options* options, size_t shape_count,
                                         double* out_fractions) {
    return guard([&] {
        require_non_null(options, "options");
        require_non_null(out_fractions, "out_fractions");
        const double* row = onset_row(options->options.onsets, shape_count);
        std::copy(row, row + (shape_count - 1), out_fractions);
    });
}

tf_status tf_lip_sync_options_set_interpolation(tf_lip_sync_options* options,
                                                tf_mouth_interpolation interpolation) {
    return guard([&] {
        require_non_null(options, "options");
        const int value = enum_value(interpolation);
        if (value != TF_INTERPOLATION_LINEAR && value != TF_INTERPOLATION_SMOOTH) {
            throw InvalidArgument("interpolation",
                                  "expected TF_INTERPOLATION_LINEAR (0) or TF_INTERPOLATION_SMOOTH (1), got " +
                                      std::to_string(value));
        }
        options->options.interpolation = static_cast<talkface::MouthInterpolation>(value);
    });
}

tf_status tf_lip_sync_options_set_max_speed_mns0_per_s(tf_lip_sync_options* options,
                                                      double max_speed_mns0_per_s) {
    return guard([&] {
        require_non_null(options, "options");
        options->options.max_speed_mns0_per_s = max_speed_mns0_per_s;
    });
}

tf_status tf_animate(const tf_face_model* face, const tf_timeline* timeline,
                     const tf_expression_simulator* simulator, const tf_lip_sync_options* options,
                     tf_animation** out) {
    return guard([&] {
        require_non_null(face, "face");
        require_non_null(timeline, "timeline");
        require_non_null(simulator, "simulator");
        require_non_null(out, "out");
        *out = new tf_animation{talkface::animate(face->model, timeline->timeline, simulator->simulator,
                                                  options != nullptr ? options->options
                                                                     : talkface::LipSyncOptions{})};
    });
}

void tf_animation_destroy(tf_animation* animation) {
    delete animation;
}

tf_status tf_animation_timing(const tf_animation* animation, double* out_fps, double* out_duration_s) {
    return guard([&] {
        require_non_null(animation, "animation");
        if (out_fps != nullptr) *out_fps = animation->animation.fps;
        if (out_duration_s != nullptr) *out_duration_s = animation->animation.duration_s;
    });
}

tf_status tf_animation_frame_count(const tf_animation* animation, size_t* out_count) {
    return guard([&] {
        require_non_null(animation, "animation");
        require_non_null(out_count, "out_count");
        *out_count = animation->animation.frames.size();
    });
}

tf_status tf_animation_frame_pose(const tf_animation* animation, size_t index, double* out_alpha_deg,
                                  double* out_beta_deg, double* out_gamma_deg) {
    return guard([&] {
        require_non_null(animation, "animation");
        require_non_null(out_alpha_deg, "out_alpha_deg");
        require_non_null(out_beta_deg, "out_beta_deg");
        require_non_null(out_gamma_deg, "out_gamma_deg");
        const talkface::Pose& pose = frame_at(animation, index).pose;
        *out_alpha_deg = pose.alpha_deg;
        *out_beta_deg = pose.beta_deg;
        *out_gamma_deg = pose.gamma_deg;
    });
}

tf_status tf_animation_frame_expression(const tf_animation* animation, size_t index, double* out_blink_left,
                                        double* out_blink_right, double* out_smile, double* out_brows) {
    return guard([&] {
        require_non_null(animation, "animation");
        require_non_null(out_blink_left, "out_blink_left");
        require_non_null(out_blink_right, "out_blink_right");
        require_non_null(out_smile, "out_smile");
        require_non_null(out_brows, "out_brows");
        const talkface::Expression& expression = frame_at(animation, index).expression;
        *out_blink_left = expression.blink_left;
        *out_blink_right = expression.blink_right;
        *out_smile = expression.smile;
        *out_brows = expression.brows;
    });
}

tf_status tf_animation_frame_mouth_controls(const tf_animation* animation, size_t index, double out_up[2],
                                            double out_down[2], double out_left[2], double out_right[2]) {
    return guard([&] {
        require_non_null(animation, "animation");
        require_non_null(out_up, "out_up");
        require_non_null(out_down, "out_down");
        require_non_null(out_left, "out_left");
        require_non_null(out_right, "out_right");
        const FaceState& frame = frame_at(animation, index);
        if (!frame.mouth) {
            throw talkface::Error(talkface::ErrorCode::internal,
                                  "internal error (a bug in talkface): frame " + std::to_string(index) +
                                      " has no mouth");
        }
        from_point(frame.mouth->up, out_up);
        from_point(frame.mouth->down, out_down);
        from_point(frame.mouth->left, out_left);
        from_point(frame.mouth->right, out_right);
    });
}

tf_status tf_animation_frame_state(const tf_animation* animation, size_t index, tf_face_state** out) {
    return guard([&] {
        require_non_null(animation, "animation");
        require_non_null(out, "out");
        *out = new tf_face_state{frame_at(animation, index)};
    });
}

tf_status tf_animation_mouth_key_frame_count(const tf_animation* animation, size_t* out_count) {
    return guard([&] {
        require_non_null(animation, "animation");
        require_non_null(out_count, "out_count");
        *out_count = animation->animation.mouth_key_frames.size();
    });
}

tf_status tf_animation_mouth_key_frame(const tf_animation* animation, size_t index, double* out_time_s,
                                       tf_mouth_shape* out_shape, int* out_has_syllable,
                                       size_t* out_syllable_index) {
    return guard([&] {
        require_non_null(animation, "animation");
        const talkface::MouthKeyFrame& key = item_at(animation->animation.mouth_key_frames, index, "key frame");
        if (out_time_s != nullptr) *out_time_s = key.time_s;
        if (out_shape != nullptr) *out_shape = static_cast<tf_mouth_shape>(key.shape);
        if (out_has_syllable != nullptr) *out_has_syllable = key.syllable ? 1 : 0;
        if (out_syllable_index != nullptr && key.syllable) *out_syllable_index = *key.syllable;
    });
}

tf_status tf_animation_event_count(const tf_animation* animation, size_t* out_count) {
    return guard([&] {
        require_non_null(animation, "animation");
        require_non_null(out_count, "out_count");
        *out_count = animation->animation.events.size();
    });
}

tf_status tf_animation_event(const tf_animation* animation, size_t index, tf_expression_event* out) {
    return guard([&] {
        require_non_null(animation, "animation");
        require_non_null(out, "out");
        *out = to_c_event(item_at(animation->animation.events, index, "event"));
    });
}

tf_status tf_animation_key_frames_json(const tf_animation* animation, char** out_json, size_t* out_len) {
    return guard([&] {
        require_non_null(animation, "animation");
        require_non_null(out_json, "out_json");
        talkface::capi::give_document(
            talkface::key_frames_json(animation->animation.mouth_key_frames, animation->animation.events,
                                      animation->animation.fps, animation->animation.duration_s),
            out_json, out_len);
    });
}

tf_status tf_animation_key_frames_tsv(const tf_animation* animation, char** out_tsv, size_t* out_len) {
    return guard([&] {
        require_non_null(animation, "animation");
        require_non_null(out_tsv, "out_tsv");
        talkface::capi::give_document(talkface::key_frames_tsv(animation->animation.mouth_key_frames), out_tsv,
                                      out_len);
    });
}

}  // extern "C"

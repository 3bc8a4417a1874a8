// tf_frame_options and tf_frame_renderer: the C face of talkface::FrameRenderer.
#include <utility>

#include "c_api_guard.hpp"
#include "c_api_handles.hpp"
#include "talkface/frame_renderer.hpp"

using talkface::FrameOptions;
using talkface::FrameRenderer;
using talkface::capi::enum_value;
using talkface::capi::guard;
using talkface::capi::require_non_null;

struct tf_frame_options {
    FrameOptions options;
};

struct tf_frame_renderer {
    FrameRenderer renderer;
};

extern "C" {

tf_status tf_frame_options_create(tf_frame_options** out) {
    return guard([&] {
        require_non_null(out, "out");
        *out = new tf_frame_options{};
    });
}

void tf_frame_options_destroy(tf_frame_options* options) {
    delete options;
}

tf_status tf_frame_options_set_size_px(tf_frame_options* options, int width_px, int height_px) {
    return guard([&] {
        require_non_null(options, "options");
        options->options.width_px = width_px;
        options->options.height_px = height_px;
    });
}

tf_status tf_frame_options_set_layout(tf_frame_options* options, tf_frame_layout layout) {
    return guard([&] {
        require_non_null(options, "options");
        // Checked by tf_frame_renderer_create, as every option is.
        options->options.layout = static_cast<talkface::FrameLayout>(enum_value(layout));
    });
}

tf_status tf_frame_options_set_background(tf_frame_options* options, const tf_rgb* colour) {
    return guard([&] {
        require_non_null(options, "options");
        options->options.background = talkface::capi::to_optional_rgb(colour);
    });
}

tf_status tf_frame_options_set_clothes(tf_frame_options* options, int draw_clothes, tf_rgb colour) {
    return guard([&] {
        require_non_null(options, "options");
        options->options.draw_clothes = draw_clothes != 0;
        options->options.clothes = talkface::capi::to_rgb(colour);
    });
}

tf_status tf_frame_options_set_look(tf_frame_options* options, tf_face_look look) {
    return guard([&] {
        require_non_null(options, "options");
        options->options.look = static_cast<talkface::FaceLook>(enum_value(look));
    });
}

tf_status tf_frame_options_set_stroke_width_in_d(tf_frame_options* options, double stroke_width_in_d) {
    return guard([&] {
        require_non_null(options, "options");
        options->options.stroke_width_in_d = stroke_width_in_d;
    });
}

tf_status tf_frame_options_set_face_placement(tf_frame_options* options, const double origin_px[2],
                                              double face_d_px) {
    return guard([&] {
        require_non_null(options, "options");
        talkface::capi::set_face_placement(options->options, origin_px, face_d_px);
    });
}

tf_status tf_frame_options_set_alpha(tf_frame_options* options, tf_alpha_mode alpha) {
    return guard([&] {
        require_non_null(options, "options");
        options->options.alpha = static_cast<talkface::AlphaMode>(enum_value(alpha));
    });
}

tf_status tf_frame_renderer_create(const tf_face_model* face, const tf_frame_options* options,
                                   tf_frame_renderer** out) {
    return guard([&] {
        require_non_null(face, "face");
        require_non_null(out, "out");
        *out = new tf_frame_renderer{FrameRenderer(face->model, options != nullptr ? options->options : FrameOptions{})};
    });
}

void tf_frame_renderer_destroy(tf_frame_renderer* renderer) {
    delete renderer;
}

tf_status tf_frame_renderer_size(const tf_frame_renderer* renderer, int* width_px, int* height_px) {
    return guard([&] {
        require_non_null(renderer, "renderer");
        require_non_null(width_px, "width_px");
        require_non_null(height_px, "height_px");
        *width_px = renderer->renderer.width_px();
        *height_px = renderer->renderer.height_px();
    });
}

tf_status tf_frame_renderer_set_background_image(tf_frame_renderer* renderer, const uint8_t* rgba, int width,
                                                 int height, size_t stride_bytes) {
    return guard([&] {
        require_non_null(renderer, "renderer");
        renderer->renderer.set_background_image(rgba, width, height, stride_bytes);
    });
}

tf_status tf_frame_renderer_render_rgba(tf_frame_renderer* renderer, const tf_face_state* state, uint8_t* rgba,
                                        size_t stride_bytes) {
    return guard([&] {
        require_non_null(renderer, "renderer");
        require_non_null(state, "state");
        renderer->renderer.render_frame_rgba(state->state, rgba, stride_bytes);
    });
}

}  // extern "C"

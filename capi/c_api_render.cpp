// tf_svg_options, tf_render_svg and tf_write_svg: the C face of talkface::SvgAnimator.
#include "c_api_guard.hpp"
#include "c_api_handles.hpp"

static_assert(TF_MAX_SVG_DECIMALS == talkface::kMaxSvgDecimals, "TF_MAX_SVG_DECIMALS");

using talkface::capi::guard;
using talkface::capi::animator_for;
using talkface::capi::require_non_null;

extern "C" {

tf_status tf_svg_options_create(tf_svg_options** out) {
    return guard([&] {
        require_non_null(out, "out");
        *out = new tf_svg_options{};
    });
}

void tf_svg_options_destroy(tf_svg_options* options) {
    delete options;
}

tf_status tf_svg_options_set_background(tf_svg_options* options, const tf_rgb* colour) {
    return guard([&] {
        require_non_null(options, "options");
        options->options.background = talkface::capi::to_optional_rgb(colour);
    });
}

tf_status tf_svg_options_set_clothes(tf_svg_options* options, int draw_clothes, tf_rgb colour) {
    return guard([&] {
        require_non_null(options, "options");
        options->options.draw_clothes = draw_clothes != 0;
        options->options.clothes = talkface::capi::to_rgb(colour);
    });
}

tf_status tf_svg_options_set_look(tf_svg_options* options, tf_face_look look) {
    return guard([&] {
        require_non_null(options, "options");
        // Checked when rendering, as every option is.
        options->options.look = static_cast<talkface::FaceLook>(talkface::capi::enum_value(look));
    });
}

tf_status tf_svg_options_set_stroke_width_in_d(tf_svg_options* options, double stroke_width_in_d) {
    return guard([&] {
        require_non_null(options, "options");
        options->options.stroke_width_in_d = stroke_width_in_d;
    });
}

tf_status tf_svg_options_set_decimals(tf_svg_options* options, int decimals) {
    return guard([&] {
        require_non_null(options, "options");
        options->options.decimals = decimals;
    });
}

tf_status tf_svg_options_set_size_px(tf_svg_options* options, int width_px, int height_px) {
    return guard([&] {
        require_non_null(options, "options");
        options->options.width_px = width_px;
        options->options.height_px = height_px;
    });
}

tf_status tf_render_svg(const tf_face_model* face, const tf_face_state* state, const tf_svg_options* options,
                        char** out_svg, size_t* out_len) {
    return guard([&] {
        require_non_null(face, "face");
        require_non_null(state, "state");
        require_non_null(out_svg, "out_svg");
        talkface::capi::give_document(animator_for(face, options).render_svg(state->state), out_svg,
                                      out_len);
    });
}

tf_status tf_write_svg(const tf_face_model* face, const tf_face_state* state, const tf_svg_options* options,
                       const char* path) {
    return guard([&] {
        require_non_null(face, "face");
        require_non_null(state, "state");
        require_non_null(path, "path");
        animator_for(face, options).write_svg(path, state->state);
    });
}

}  // extern "C"

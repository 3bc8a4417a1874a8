// tf_render_animation_svg, tf_web_page_options and tf_build_web_page: the C face of the temporal
// half of SvgAnimator and of web_page.hpp.
#include <string>

#include "c_api_guard.hpp"
#include "c_api_handles.hpp"
#include "talkface/web_page.hpp"

struct tf_web_page_options {
    talkface::WebPageOptions options;
};

struct tf_svg_animation_options {
    talkface::SvgAnimationOptions options;
};

using talkface::InvalidArgument;
using talkface::capi::animator_for;
using talkface::capi::enum_value;
using talkface::capi::guard;
using talkface::capi::progress_for;
using talkface::capi::require_non_null;

namespace {

talkface::AnimationEncoding to_encoding(const tf_animation_encoding& encoding) {
    const int value = enum_value(encoding);
    if (value != TF_ENCODING_KEYFRAMES && value != TF_ENCODING_FRAMES) {
        throw InvalidArgument("encoding", "expected TF_ENCODING_KEYFRAMES (0) or TF_ENCODING_FRAMES (1), got " +
                                              std::to_string(value));
    }
    return static_cast<talkface::AnimationEncoding>(value);
}

talkface::SvgAnimationOptions with_encoding(const tf_animation_encoding& encoding) {
    talkface::SvgAnimationOptions options;
    options.encoding = to_encoding(encoding);
    return options;
}

const talkface::SvgAnimationOptions& options_or_defaults(const tf_svg_animation_options* options) {
    static const talkface::SvgAnimationOptions defaults;
    return options != nullptr ? options->options : defaults;
}

void render_svg(const tf_face_model* face, const tf_animation* animation, const tf_svg_options* options,
                const talkface::SvgAnimationOptions& animation_options, tf_progress_fn progress,
                void* user_data, char** out_svg, size_t* out_len) {
    require_non_null(face, "face");
    require_non_null(animation, "animation");
    require_non_null(out_svg, "out_svg");
    talkface::capi::give_document(
        animator_for(face, options)
            .render_animation_svg(animation->animation, animation_options, progress_for(progress, user_data)),
        out_svg, out_len);
}

void write_svg(const tf_face_model* face, const tf_animation* animation, const tf_svg_options* options,
               const talkface::SvgAnimationOptions& animation_options, const char* path) {
    require_non_null(face, "face");
    require_non_null(animation, "animation");
    require_non_null(path, "path");
    animator_for(face, options).write_animation_svg(path, animation->animation, animation_options);
}

}  // namespace

extern "C" {

tf_status tf_render_animation_svg(const tf_face_model* face, const tf_animation* animation,
                                  const tf_svg_options* options, tf_animation_encoding encoding,
                                  tf_progress_fn progress, void* user_data, char** out_svg, size_t* out_len) {
    return guard([&] {
        render_svg(face, animation, options, with_encoding(encoding), progress, user_data, out_svg, out_len);
    });
}

tf_status tf_write_animation_svg(const tf_face_model* face, const tf_animation* animation,
                                 const tf_svg_options* options, tf_animation_encoding encoding, const char* path) {
    return guard([&] { write_svg(face, animation, options, with_encoding(encoding), path); });
}

tf_status tf_svg_animation_options_create(tf_svg_animation_options** out) {
    return guard([&] {
        require_non_null(out, "out");
        *out = new tf_svg_animation_options{};
    });
}

void tf_svg_animation_options_destroy(tf_svg_animation_options* options) {
    delete options;
}

tf_status tf_svg_animation_options_set_encoding(tf_svg_animation_options* options,
                                                tf_animation_encoding encoding) {
    return guard([&] {
        require_non_null(options, "options");
        options->options.encoding = to_encoding(encoding);
    });
}

tf_status tf_svg_animation_options_set_tolerance_px(tf_svg_animation_options* options, double tolerance_px) {
    return guard([&] {
        require_non_null(options, "options");
        options->options.tolerance_px = tolerance_px;
    });
}

tf_status tf_render_animation_svg_with_options(const tf_face_model* face, const tf_animation* animation,
                                               const tf_svg_options* options,
                                               const tf_svg_animation_options* animation_options,
                                               tf_progress_fn progress, void* user_data, char** out_svg,
                                               size_t* out_len) {
    return guard([&] {
        render_svg(face, animation, options, options_or_defaults(animation_options), progress, user_data,
                   out_svg, out_len);
    });
}

tf_status tf_write_animation_svg_with_options(const tf_face_model* face, const tf_animation* animation,
                                              const tf_svg_options* options,
                                              const tf_svg_animation_options* animation_options,
                                              const char* path) {
    return guard([&] { write_svg(face, animation, options, options_or_defaults(animation_options), path); });
}

tf_status tf_web_page_options_create(tf_web_page_options** out) {
    return guard([&] {
        require_non_null(out, "out");
        *out = new tf_web_page_options{};
    });
}

void tf_web_page_options_destroy(tf_web_page_options* options) {
    delete options;
}

tf_status tf_web_page_options_set_app(tf_web_page_options* options, tf_web_page_app app) {
    return guard([&] {
        require_non_null(options, "options");
        const int value = enum_value(app);
        if (value < TF_PAGE_PLAIN || value > TF_PAGE_AUDIOBOOK) {
            throw InvalidArgument("app", "expected TF_PAGE_PLAIN (0), TF_PAGE_ANNOUNCER (1) or TF_PAGE_AUDIOBOOK (2), got " +
                                             std::to_string(value));
        }
        options->options.app = static_cast<talkface::WebPageApp>(value);
    });
}

tf_status tf_web_page_options_set_title(tf_web_page_options* options, const char* title) {
    return guard([&] {
        require_non_null(options, "options");
        options->options.title = title != nullptr ? title : "";
    });
}

tf_status tf_web_page_options_add_link(tf_web_page_options* options, const char* text, const char* url) {
    return guard([&] {
        require_non_null(options, "options");
        require_non_null(text, "text");
        require_non_null(url, "url");
        options->options.links.push_back({text, url});
    });
}

tf_status tf_web_page_options_set_encoding(tf_web_page_options* options, tf_animation_encoding encoding) {
    return guard([&] {
        require_non_null(options, "options");
        options->options.animation.encoding = to_encoding(encoding);
    });
}

tf_status tf_web_page_options_set_tolerance_px(tf_web_page_options* options, double tolerance_px) {
    return guard([&] {
        require_non_null(options, "options");
        options->options.animation.tolerance_px = tolerance_px;
    });
}

tf_status tf_web_page_options_set_audio(tf_web_page_options* options, tf_web_page_audio audio, int bitrate_bps,
                                        const char* url) {
    return guard([&] {
        require_non_null(options, "options");
        const int value = enum_value(audio);
        if (value < TF_PAGE_AUDIO_COMPRESSED || value > TF_PAGE_AUDIO_LINK) {
            throw InvalidArgument("audio", "expected TF_PAGE_AUDIO_COMPRESSED (0), TF_PAGE_AUDIO_ORIGINAL (1) or "
                                           "TF_PAGE_AUDIO_LINK (2), got " + std::to_string(value));
        }
        options->options.audio = static_cast<talkface::WebPageAudio>(value);
        options->options.audio_bitrate_bps = bitrate_bps;
        options->options.audio_url = url != nullptr ? url : "";
    });
}

tf_status tf_web_page_options_set_stage(tf_web_page_options* options, int width_px, int height_px, tf_rgb colour,
                                        const char* image_path) {
    return guard([&] {
        require_non_null(options, "options");
        options->options.stage_width_px = width_px;
        options->options.stage_height_px = height_px;
        options->options.stage_colour = talkface::Rgb{colour.r, colour.g, colour.b};
        options->options.background_image_path = image_path != nullptr ? image_path : "";
    });
}

tf_status tf_web_page_options_set_face_placement(tf_web_page_options* options, const double origin_xy[2],
                                                 double d_px) {
    return guard([&] {
        require_non_null(options, "options");
        if (origin_xy != nullptr) {
            options->options.face_origin_px = talkface::capi::to_point(origin_xy);
        } else {
            options->options.face_origin_px.reset();
        }
        options->options.face_d_px = d_px;
    });
}

tf_status tf_build_web_page(const tf_face_model* face, const tf_svg_options* svg_options,
                            const tf_animation* animation, const tf_timeline* timeline, const char* audio_path,
                            const tf_web_page_options* page_options, tf_progress_fn progress, void* user_data,
                            char** out_html, size_t* out_len) {
    return guard([&] {
        require_non_null(face, "face");
        require_non_null(animation, "animation");
        require_non_null(timeline, "timeline");
        require_non_null(audio_path, "audio_path");
        require_non_null(out_html, "out_html");
        talkface::capi::give_document(
            talkface::build_web_page(animator_for(face, svg_options), animation->animation, timeline->timeline,
                                     audio_path, page_options != nullptr ? page_options->options
                                                                         : talkface::WebPageOptions{},
                                     progress_for(progress, user_data)),
            out_html, out_len);
    });
}

tf_status tf_write_web_page(const tf_face_model* face, const tf_svg_options* svg_options,
                            const tf_animation* animation, const tf_timeline* timeline, const char* audio_path,
                            const tf_web_page_options* page_options, const char* path) {
    return guard([&] {
        require_non_null(face, "face");
        require_non_null(animation, "animation");
        require_non_null(timeline, "timeline");
        require_non_null(audio_path, "audio_path");
        require_non_null(path, "path");
        talkface::write_web_page(path, animator_for(face, svg_options), animation->animation, timeline->timeline,
                                 audio_path,
                                 page_options != nullptr ? page_options->options : talkface::WebPageOptions{});
    });
}

}  // extern "C"

// tf_render_animation_lottie and tf_write_animation_lottie: the C face of
// SvgAnimator::render_animation_lottie().
#include "c_api_guard.hpp"
#include "c_api_handles.hpp"

using talkface::capi::animator_for;
using talkface::capi::guard;
using talkface::capi::progress_for;
using talkface::capi::require_non_null;

extern "C" {

tf_status tf_render_animation_lottie(const tf_face_model* face, const tf_animation* animation,
                                     const tf_svg_options* options, double tolerance_px, tf_progress_fn progress,
                                     void* user_data, char** out_json, size_t* out_len) {
    return guard([&] {
        require_non_null(face, "face");
        require_non_null(animation, "animation");
        require_non_null(out_json, "out_json");
        talkface::LottieOptions lottie;
        lottie.tolerance_px = tolerance_px;
        talkface::capi::give_document(animator_for(face, options).render_animation_lottie(
                                          animation->animation, lottie, progress_for(progress, user_data)),
                                      out_json, out_len);
    });
}

tf_status tf_write_animation_lottie(const tf_face_model* face, const tf_animation* animation,
                                    const tf_svg_options* options, double tolerance_px, const char* path) {
    return guard([&] {
        require_non_null(face, "face");
        require_non_null(animation, "animation");
        require_non_null(path, "path");
        talkface::LottieOptions lottie;
        lottie.tolerance_px = tolerance_px;
        animator_for(face, options).write_animation_lottie(path, animation->animation, lottie);
    });
}

}  // extern "C"

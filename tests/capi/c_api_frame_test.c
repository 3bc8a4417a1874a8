/* The C ABI of the raster renderer, driven from C: frames into a caller's buffer at its stride,
 * the announcer layout's background and clothes, transparency, a background picture, refusals. */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "talkface/talkface.h"

#include "c_check.h"

static int test_a_frame_fills_the_callers_buffer(void) {
    int failures = 0;
    tf_face_model *face = NULL;
    tf_frame_options *options = NULL;
    tf_frame_renderer *renderer = NULL;
    tf_face_state *state = NULL;
    const tf_rgb background = {10, 20, 30};
    const tf_rgb clothes = {200, 100, 50};
    int width = 0, height = 0;
    const size_t stride = 4 * 320 + 8;
    uint8_t *pixels = malloc(stride * 180);
    CHECK_OK(tf_face_model_default(&face));
    CHECK_OK(tf_frame_options_create(&options));
    CHECK_OK(tf_frame_options_set_size_px(options, 320, 180));
    CHECK_OK(tf_frame_options_set_background(options, &background));
    CHECK_OK(tf_frame_options_set_clothes(options, 1, clothes));
    CHECK_OK(tf_frame_renderer_create(face, options, &renderer));
    CHECK_OK(tf_frame_renderer_size(renderer, &width, &height));
    CHECK(width == 320 && height == 180);
    CHECK_OK(tf_face_state_create(&state));
    CHECK_OK(tf_face_state_set_pose(state, 5.0, -10.0, 3.0));
    CHECK_OK(tf_face_state_set_mouth_shape(state, face, TF_MOUTH_A));
    memset(pixels, 0xab, stride * 180);
    CHECK_OK(tf_frame_renderer_render_rgba(renderer, state, pixels, stride));
    /* The top-left corner is the background; the bottom middle the shirt; the padding untouched. */
    CHECK(pixels[0] == 10 && pixels[1] == 20 && pixels[2] == 30 && pixels[3] == 255);
    CHECK(pixels[170 * stride + 4 * 160] == 200 && pixels[170 * stride + 4 * 160 + 1] == 100);
    CHECK(pixels[4 * 320] == 0xab && pixels[stride - 1] == 0xab);
    /* The flat look draws the same frame without outlines: other pixels, the same background. */
    {
        tf_frame_renderer *flat = NULL;
        uint8_t *flat_pixels = malloc(stride * 180);
        CHECK_OK(tf_frame_options_set_look(options, TF_FACE_LOOK_FLAT));
        CHECK_OK(tf_frame_renderer_create(face, options, &flat));
        CHECK_OK(tf_frame_renderer_render_rgba(flat, state, flat_pixels, stride));
        CHECK(flat_pixels[0] == 10 && flat_pixels[1] == 20 && flat_pixels[2] == 30);
        CHECK(memcmp(pixels, flat_pixels, stride * 180) != 0);
        tf_frame_renderer_destroy(flat);
        free(flat_pixels);
        CHECK_OK(tf_frame_options_set_look(options, (tf_face_look)7));
        CHECK_FAILS_WITH(tf_frame_renderer_create(face, options, &flat), TF_ERR_INVALID_ARGUMENT, "look");
    }
    tf_face_state_destroy(state);
    tf_frame_renderer_destroy(renderer);
    tf_frame_options_destroy(options);
    tf_face_model_destroy(face);
    free(pixels);
    return failures;
}

static int test_a_transparent_frame_and_a_background_picture(void) {
    int failures = 0;
    tf_face_model *face = NULL;
    tf_frame_options *options = NULL;
    tf_frame_renderer *renderer = NULL;
    tf_face_state *state = NULL;
    uint8_t pixels[4 * 64 * 48];
    const uint8_t picture[4 * 2] = {0, 250, 0, 255, 0, 250, 0, 255};
    const double origin[2] = {32.0, 40.0};
    CHECK_OK(tf_face_model_default(&face));
    CHECK_OK(tf_face_state_create(&state));
    CHECK_OK(tf_frame_options_create(&options));
    CHECK_OK(tf_frame_options_set_size_px(options, 64, 48));
    CHECK_OK(tf_frame_options_set_background(options, NULL));
    CHECK_OK(tf_frame_options_set_alpha(options, TF_ALPHA_PREMULTIPLIED));
    CHECK_OK(tf_frame_options_set_face_placement(options, origin, 8.0));
    CHECK_OK(tf_frame_options_set_layout(options, TF_FRAME_LAYOUT_ANNOUNCER));
    CHECK_OK(tf_frame_renderer_create(face, options, &renderer));
    CHECK_OK(tf_frame_renderer_render_rgba(renderer, state, pixels, 4 * 64));
    CHECK(pixels[3] == 0);
    CHECK(pixels[4 * (64 * 30 + 32) + 3] == 255); /* the face, on O's 10 px above */
    CHECK_OK(tf_frame_renderer_set_background_image(renderer, picture, 2, 1, 8));
    CHECK_OK(tf_frame_renderer_render_rgba(renderer, state, pixels, 4 * 64));
    CHECK(pixels[0] == 0 && pixels[1] == 250 && pixels[3] == 255);
    tf_frame_renderer_destroy(renderer);
    tf_frame_options_destroy(options);
    tf_face_state_destroy(state);
    tf_face_model_destroy(face);
    return failures;
}

static int test_bad_arguments_are_refused_by_name(void) {
    int failures = 0;
    tf_face_model *face = NULL;
    tf_frame_options *options = NULL;
    tf_frame_renderer *renderer = NULL;
    tf_face_state *state = NULL;
    uint8_t pixels[4 * 16 * 16];
    CHECK_OK(tf_face_model_default(&face));
    CHECK_OK(tf_face_state_create(&state));
    CHECK_OK(tf_frame_options_create(&options));
    CHECK_OK(tf_frame_options_set_size_px(options, 7681, 100));
    CHECK_FAILS_WITH(tf_frame_renderer_create(face, options, &renderer), TF_ERR_INVALID_ARGUMENT, "width_px");
    CHECK(renderer == NULL);
    CHECK_OK(tf_frame_options_set_size_px(options, 16, 16));
    CHECK_OK(tf_frame_options_set_layout(options, (tf_frame_layout)9));
    CHECK_FAILS_WITH(tf_frame_renderer_create(face, options, &renderer), TF_ERR_INVALID_ARGUMENT, "layout");
    CHECK_OK(tf_frame_options_set_layout(options, TF_FRAME_LAYOUT_FACE));
    CHECK_FAILS_WITH(tf_frame_renderer_create(NULL, options, &renderer), TF_ERR_INVALID_ARGUMENT, "face");
    CHECK_OK(tf_frame_renderer_create(face, options, &renderer));
    CHECK_FAILS_WITH(tf_frame_renderer_render_rgba(renderer, state, NULL, 64), TF_ERR_INVALID_ARGUMENT, "rgba");
    CHECK_FAILS_WITH(tf_frame_renderer_render_rgba(renderer, state, pixels, 63), TF_ERR_INVALID_ARGUMENT,
                     "stride_bytes");
    CHECK_FAILS_WITH(tf_frame_renderer_render_rgba(renderer, NULL, pixels, 64), TF_ERR_INVALID_ARGUMENT, "state");
    CHECK_FAILS_WITH(tf_frame_options_set_alpha(NULL, TF_ALPHA_STRAIGHT), TF_ERR_INVALID_ARGUMENT, "options");
    tf_frame_renderer_destroy(renderer);
    tf_frame_renderer_destroy(NULL);
    tf_frame_options_destroy(options);
    tf_frame_options_destroy(NULL);
    tf_face_state_destroy(state);
    tf_face_model_destroy(face);
    return failures;
}

int main(void) {
    int failures = 0;
    failures += test_a_frame_fills_the_callers_buffer();
    failures += test_a_transparent_frame_and_a_background_picture();
    failures += test_bad_arguments_are_refused_by_name();
    return failures == 0 ? 0 : 1;
}

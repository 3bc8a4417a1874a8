/* The C ABI of talkface::VideoWriter: a short MP4 of a moving square with a tone, a GIF, the refusals,
 * and a writer destroyed unfinished leaving nothing. */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "c_check.h"

enum { kWidth = 160, kHeight = 120, kFrames = 15, kRate = 16000 };

static int file_exists(const char *path) {
    FILE *file = fopen(path, "rb");
    if (file == NULL) return 0;
    fclose(file);
    return 1;
}

static long file_size(const char *path) {
    FILE *file = fopen(path, "rb");
    long size = -1;
    if (file == NULL) return -1;
    if (fseek(file, 0, SEEK_END) == 0) size = ftell(file);
    fclose(file);
    return size;
}

static void fill_frame(uint8_t *rgba, int index) {
    int x, y;
    for (y = 0; y < kHeight; ++y) {
        for (x = 0; x < kWidth; ++x) {
            uint8_t *p = rgba + ((size_t)y * kWidth + (size_t)x) * 4;
            const int is_square = x >= 10 + 4 * index && x < 30 + 4 * index && y >= 50 && y < 70;
            p[0] = (uint8_t)(is_square ? 220 : 40);
            p[1] = (uint8_t)(is_square ? 30 : 90);
            p[2] = (uint8_t)(is_square ? 40 : 160);
            p[3] = 255;
        }
    }
}

static int test_writes_an_mp4(void) {
    int failures = 0;
    char path[1024];
    tf_video_options *options = NULL;
    tf_video_writer *writer = NULL;
    tf_video_format format = TF_VIDEO_WEBM;
    uint8_t *rgba = malloc((size_t)kWidth * kHeight * 4);
    float *samples = malloc(sizeof(float) * kRate / 2);
    size_t count = 0;
    int i;
    for (i = 0; i < kRate / 2; ++i) samples[i] = (float)(0.3 * sin(2.0 * 3.14159265 * 200.0 * i / kRate));
    snprintf(path, sizeof path, "%s/c_api_video.mp4", TF_TEST_OUTPUT_DIR);
    remove(path);

    CHECK_OK(tf_video_format_from_path(path, &format));
    CHECK(format == TF_VIDEO_MP4);
    CHECK_OK(tf_video_options_create(&options));
    CHECK_OK(tf_video_options_set_size(options, kWidth, kHeight));
    CHECK_OK(tf_video_options_set_fps(options, 30.0));
    CHECK_OK(tf_video_options_set_crf(options, 23));
    CHECK_OK(tf_check_video_options(path, options));
    CHECK_OK(tf_video_writer_open(path, options, &writer));
    CHECK_OK(tf_video_writer_add_audio(writer, samples, (size_t)kRate / 2, 1, kRate));
    for (i = 0; i < kFrames; ++i) {
        fill_frame(rgba, i);
        CHECK_OK(tf_video_writer_write_frame(writer, rgba, (size_t)kWidth * 4));
    }
    CHECK_OK(tf_video_writer_frame_count(writer, &count));
    CHECK(count == kFrames);
    CHECK(!file_exists(path));
    CHECK_OK(tf_video_writer_finish(writer));
    CHECK(file_size(path) > 1000);
    CHECK_FAILS_WITH(tf_video_writer_finish(writer), TF_ERR_INVALID_ARGUMENT, "finished already");
    tf_video_writer_destroy(writer);
    tf_video_options_destroy(options);
    free(rgba);
    free(samples);
    return failures;
}

/* A GIF, looping: "GIF89a", its frames written at finish with one palette. */
static int test_writes_a_gif(void) {
    int failures = 0;
    char path[1024];
    char head[7] = {0};
    tf_video_options *options = NULL;
    tf_video_writer *writer = NULL;
    uint8_t *rgba = malloc((size_t)kWidth * kHeight * 4);
    FILE *file = NULL;
    int i;
    snprintf(path, sizeof path, "%s/c_api_video.gif", TF_TEST_OUTPUT_DIR);
    remove(path);
    CHECK_OK(tf_video_options_create(&options));
    CHECK_OK(tf_video_options_set_size(options, kWidth, kHeight));
    CHECK_OK(tf_video_options_set_fps(options, 10.0));
    CHECK_OK(tf_video_writer_open(path, options, &writer));
    for (i = 0; i < kFrames; ++i) {
        fill_frame(rgba, i);
        CHECK_OK(tf_video_writer_write_frame(writer, rgba, (size_t)kWidth * 4));
    }
    CHECK(!file_exists(path));
    CHECK_OK(tf_video_writer_finish(writer));
    file = fopen(path, "rb");
    CHECK(file != NULL);
    if (file != NULL) {
        CHECK(fread(head, 1, 6, file) == 6);
        fclose(file);
    }
    CHECK(strcmp(head, "GIF89a") == 0);
    tf_video_writer_destroy(writer);
    tf_video_options_destroy(options);
    free(rgba);
    return failures;
}

static int test_refusals_name_the_problem(void) {
    int failures = 0;
    char path[1024];
    tf_video_options *options = NULL;
    tf_video_writer *writer = NULL;
    tf_video_format format = TF_VIDEO_MP4;
    uint8_t pixel[4] = {0, 0, 0, 255};

    CHECK_FAILS_WITH(tf_video_format_from_path("talk.avi", &format), TF_ERR_INVALID_ARGUMENT, "\".avi\"");
    CHECK_OK(tf_video_format_from_path("chat.gif", &format));
    CHECK(format == TF_VIDEO_GIF);
    CHECK_OK(tf_video_options_create(&options));
    CHECK_OK(tf_video_options_set_size(options, 641, 480));
    CHECK_FAILS_WITH(tf_check_video_options("a.mp4", options), TF_ERR_INVALID_ARGUMENT, "even width and height");
    CHECK_OK(tf_video_options_set_size(options, 8000, 4000));
    CHECK_FAILS_WITH(tf_check_video_options("a.mp4", options), TF_ERR_INVALID_ARGUMENT, "7680x4320");
    CHECK_OK(tf_video_options_set_size(options, 640, 480));
    CHECK_OK(tf_video_options_set_fps(options, 200.0));
    CHECK_FAILS_WITH(tf_check_video_options("a.mp4", options), TF_ERR_INVALID_ARGUMENT, "fps: expected 1..120");
    CHECK_OK(tf_video_options_set_fps(options, 60.0));
    CHECK_FAILS_WITH(tf_check_video_options("a.gif", options), TF_ERR_INVALID_ARGUMENT, "fps: expected 1..50");
    CHECK_OK(tf_video_options_set_fps(options, 25.0));
    CHECK_OK(tf_video_options_set_transparent(options, 1));
    CHECK_FAILS_WITH(tf_check_video_options("a.mp4", options), TF_ERR_INVALID_ARGUMENT, "no alpha channel");
    CHECK_OK(tf_check_video_options("a.webm", options));
    CHECK_FAILS_WITH(tf_video_writer_open(NULL, options, &writer), TF_ERR_INVALID_ARGUMENT, "path");

    /* Destroyed unfinished: nothing is left. */
    snprintf(path, sizeof path, "%s/c_api_video_dropped.webm", TF_TEST_OUTPUT_DIR);
    remove(path);
    CHECK_OK(tf_video_options_set_size(options, 2, 2));
    CHECK_OK(tf_video_writer_open(path, options, &writer));
    CHECK_FAILS_WITH(tf_video_writer_write_frame(writer, pixel, 4), TF_ERR_INVALID_ARGUMENT, "stride_bytes");
    CHECK_FAILS_WITH(tf_video_writer_add_audio_file(writer, "/no/such/speech.wav"), TF_ERR_FILE, "speech.wav");
    tf_video_writer_destroy(writer);
    CHECK(!file_exists(path));
    tf_video_writer_destroy(NULL);
    tf_video_options_destroy(NULL);
    tf_video_options_destroy(options);
    return failures;
}

static int count_progress(double fraction, const char *stage, void *user_data) {
    int *calls = user_data;
    (void)fraction;
    (void)stage;
    ++*calls;
    return 0;
}

static int cancel_at_once(double fraction, const char *stage, void *user_data) {
    (void)fraction;
    (void)stage;
    (void)user_data;
    return 1;
}

/* The default face's animation of `seconds` of silence, or NULL. */
static tf_animation* silent_animation(const tf_face_model* face, double seconds) {
    tf_timeline* timeline = NULL;
    tf_expression_simulator* simulator = NULL;
    tf_animation* animation = NULL;
    if (tf_timeline_create(&timeline) == TF_OK && tf_timeline_set_duration_s(timeline, seconds) == TF_OK &&
        tf_expression_simulator_create(timeline, 3, "normal", &simulator) == TF_OK) {
        tf_animate(face, timeline, simulator, NULL, &animation);
    }
    tf_expression_simulator_destroy(simulator);
    tf_timeline_destroy(timeline);
    return animation;
}

/* 160 x 90 at 10 fps, or NULL. */
static tf_video_options* small_video_options(void) {
    tf_video_options* options = NULL;
    if (tf_video_options_create(&options) == TF_OK && (tf_video_options_set_size(options, 160, 90) != TF_OK ||
                                                       tf_video_options_set_fps(options, 10.0) != TF_OK)) {
        tf_video_options_destroy(options);
        options = NULL;
    }
    return options;
}

static int test_renders_the_face(void) {
    int failures = 0;
    char path[1024];
    tf_face_model* face = NULL;
    tf_animation *animation = NULL;
    tf_video_options *options = NULL;
    tf_video_look *look = NULL;
    const tf_rgb white = {255, 255, 255};
    const double origin[2] = {80.0, 80.0};
    int calls = 0;
    snprintf(path, sizeof path, "%s/c_api_face_video.webm", TF_TEST_OUTPUT_DIR);
    remove(path);
    CHECK_OK(tf_face_model_default(&face));
    animation = silent_animation(face, 0.5);
    options = small_video_options();
    CHECK(animation != NULL && options != NULL);
    CHECK_OK(tf_video_look_create(&look));
    CHECK_OK(tf_video_look_set_layout(look, TF_FRAME_LAYOUT_ANNOUNCER));
    CHECK_OK(tf_video_look_set_face_look(look, TF_FACE_LOOK_FLAT));
    CHECK_FAILS_WITH(tf_video_look_set_face_look(look, (tf_face_look)5), TF_ERR_INVALID_ARGUMENT, "face_look");
    CHECK_OK(tf_video_look_set_background(look, &white, NULL));
    CHECK_OK(tf_video_look_set_face_placement(look, origin, 20.0));
    CHECK_FAILS_WITH(tf_video_look_set_layout(look, (tf_frame_layout)7), TF_ERR_INVALID_ARGUMENT, "layout");
    CHECK_OK(tf_render_video(path, face, animation, NULL, options, look, count_progress, &calls));
    CHECK(calls > 1);
    CHECK(file_size(path) > 100);
    remove(path);
    CHECK_FAILS_WITH(tf_render_video(path, face, animation, NULL, options, look, cancel_at_once, NULL),
                     TF_ERR_CANCELLED, "cancelled");
    CHECK(!file_exists(path));
    CHECK_FAILS_WITH(tf_render_video(path, NULL, animation, NULL, options, look, NULL, NULL), TF_ERR_INVALID_ARGUMENT,
                     "face");
    tf_video_look_destroy(look);
    tf_video_look_destroy(NULL);
    tf_video_options_destroy(options);
    tf_animation_destroy(animation);
    tf_face_model_destroy(face);
    return failures;
}

/* 1 if the two files' bytes differ (or either cannot be read). */
static int files_differ(const char* a, const char* b) {
    FILE* file_a = fopen(a, "rb");
    FILE* file_b = fopen(b, "rb");
    int differ = file_a == NULL || file_b == NULL;
    while (!differ) {
        const int byte_a = fgetc(file_a);
        const int byte_b = fgetc(file_b);
        differ = byte_a != byte_b;
        if (byte_a == EOF) break;
    }
    if (file_a != NULL) fclose(file_a);
    if (file_b != NULL) fclose(file_b);
    return differ;
}

/* The look's clothes and outline width reach the frames: one frame as PNG with the clothes and one
 * without differ, and an outline width that is not > 0 is refused naming it. */
static int test_the_look_sets_clothes_and_outline(void) {
    int failures = 0;
    char with_clothes[1024], without_clothes[1024], with_frame[1024], without_frame[1024];
    tf_face_model* face = NULL;
    tf_animation* animation = NULL;
    tf_video_options* options = NULL;
    tf_video_look* look = NULL;
    const tf_rgb clothes = {200, 40, 40};
    snprintf(with_clothes, sizeof with_clothes, "%s/c_api_clothes.png", TF_TEST_OUTPUT_DIR);
    snprintf(without_clothes, sizeof without_clothes, "%s/c_api_no_clothes.png", TF_TEST_OUTPUT_DIR);
    snprintf(with_frame, sizeof with_frame, "%s/c_api_clothes-000000.png", TF_TEST_OUTPUT_DIR);
    snprintf(without_frame, sizeof without_frame, "%s/c_api_no_clothes-000000.png", TF_TEST_OUTPUT_DIR);
    CHECK_OK(tf_face_model_default(&face));
    animation = silent_animation(face, 0.1);
    options = small_video_options();
    CHECK(animation != NULL && options != NULL);
    CHECK_OK(tf_video_look_create(&look));
    CHECK_OK(tf_video_look_set_layout(look, TF_FRAME_LAYOUT_FACE));
    CHECK_OK(tf_video_look_set_clothes(look, 1, clothes));
    CHECK_OK(tf_render_video(with_clothes, face, animation, NULL, options, look, NULL, NULL));
    CHECK_OK(tf_video_look_set_clothes(look, 0, clothes));
    CHECK_OK(tf_render_video(without_clothes, face, animation, NULL, options, look, NULL, NULL));
    CHECK(file_size(with_frame) > 100 && file_size(without_frame) > 100);
    CHECK(files_differ(with_frame, without_frame));
    CHECK_OK(tf_video_look_set_stroke_width_in_d(look, -1.0));
    CHECK_FAILS_WITH(tf_render_video(with_clothes, face, animation, NULL, options, look, NULL, NULL),
                     TF_ERR_INVALID_ARGUMENT, "stroke_width_in_d");
    CHECK_FAILS_WITH(tf_video_look_set_clothes(NULL, 1, clothes), TF_ERR_INVALID_ARGUMENT, "look");
    CHECK_FAILS_WITH(tf_video_look_set_stroke_width_in_d(NULL, 0.02), TF_ERR_INVALID_ARGUMENT, "look");
    remove(with_frame);
    remove(without_frame);
    tf_video_look_destroy(look);
    tf_video_options_destroy(options);
    tf_animation_destroy(animation);
    tf_face_model_destroy(face);
    return failures;
}

int main(void) {
    int failures = 0;
    failures += test_writes_an_mp4();
    failures += test_writes_a_gif();
    failures += test_renders_the_face();
    failures += test_the_look_sets_clothes_and_outline();
    failures += test_refusals_name_the_problem();
    if (failures != 0) fprintf(stderr, "%d check(s) failed\n", failures);
    return failures == 0 ? 0 : 1;
}

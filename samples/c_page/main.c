/* A talking-face web page made end to end through the C ABI (talkface.h): transcript, alignment,
 * simulated expressions, animation, page. What a C program (or a language binding with a C FFI)
 * does to use talkface.
 *
 *   c_page AUDIO TRANSCRIPT OUT.html
 */
#include <stdio.h>

#include <talkface/talkface.h>

/* Prints the failed call and the library's message; returns 1 for main. */
static int failed(const char *call, tf_status status) {
    fprintf(stderr, "c_page: %s: %s: %s\n", call, tf_status_name(status), tf_last_error_message());
    return 1;
}

int main(int argc, char **argv) {
    tf_face_model *face = NULL;
    tf_timeline *transcript = NULL;
    tf_timeline *timeline = NULL;
    tf_expression_simulator *simulator = NULL;
    tf_animation *animation = NULL;
    tf_web_page_options *page = NULL;
    tf_status status;
    int result = 0;
    size_t frames = 0;

    if (argc != 4) {
        fprintf(stderr, "usage: c_page AUDIO TRANSCRIPT OUT.html\n");
        return 2;
    }
    /* Every handle starts NULL and every destroy accepts NULL: one clean-up path for all exits. */
    if ((status = tf_face_model_default(&face)) != TF_OK) {
        result = failed("tf_face_model_default", status);
    } else if ((status = tf_load_transcript(argv[2], &transcript)) != TF_OK) {
        result = failed("tf_load_transcript", status);
    } else if ((status = tf_align_file(argv[1], transcript, NULL, NULL, NULL, &timeline)) != TF_OK) {
        result = failed("tf_align_file", status);
    } else if ((status = tf_expression_simulator_create(timeline, 5, NULL, &simulator)) != TF_OK) {
        result = failed("tf_expression_simulator_create", status);
    } else if ((status = tf_animate(face, timeline, simulator, NULL, &animation)) != TF_OK) {
        result = failed("tf_animate", status);
    } else if ((status = tf_web_page_options_create(&page)) != TF_OK) {
        result = failed("tf_web_page_options_create", status);
    } else if ((status = tf_web_page_options_set_title(page, "talkface from C")) != TF_OK) {
        result = failed("tf_web_page_options_set_title", status);
    } else if ((status = tf_write_web_page(face, NULL, animation, timeline, argv[1], page, argv[3])) != TF_OK) {
        result = failed("tf_write_web_page", status);
    } else {
        tf_animation_frame_count(animation, &frames);
        printf("wrote %s: %zu frames (talkface %s)\n", argv[3], frames, tf_version());
    }
    tf_web_page_options_destroy(page);
    tf_animation_destroy(animation);
    tf_expression_simulator_destroy(simulator);
    tf_timeline_destroy(timeline);
    tf_timeline_destroy(transcript);
    tf_face_model_destroy(face);
    return result;
}

/* Renders the default face through the installed C ABI and, given a folder, writes a one-frame PNG
 * sequence there: libtalkface opens FFmpeg's module (LIBDIR/talkface/) for it. */
#include <stdio.h>
#include <string.h>
#include <talkface/talkface.h>

/* A 16 x 16 frame, grey, as FOLDER/frame-000000.png. */
static int write_frame(const char *folder) {
    char path[4096];
    unsigned char rgba[16 * 16 * 4];
    tf_video_options *options = NULL;
    tf_video_writer *writer = NULL;
    int ok;
    snprintf(path, sizeof path, "%s/frame.png", folder);
    memset(rgba, 128, sizeof rgba);
    ok = tf_video_options_create(&options) == TF_OK && tf_video_options_set_size(options, 16, 16) == TF_OK &&
         tf_video_writer_open(path, options, &writer) == TF_OK &&
         tf_video_writer_write_frame(writer, rgba, 16 * 4) == TF_OK && tf_video_writer_finish(writer) == TF_OK;
    printf("C: a video frame in %s%s%s\n", folder, ok ? "" : ", error: ", ok ? "" : tf_last_error_message());
    tf_video_writer_destroy(writer);
    tf_video_options_destroy(options);
    return ok;
}

int main(int argc, char **argv) {
    tf_face_model *face = NULL;
    tf_face_state *state = NULL;
    char *svg = NULL;
    size_t length = 0;
    int ok = tf_face_model_default(&face) == TF_OK && tf_face_state_create(&state) == TF_OK &&
             tf_render_svg(face, state, NULL, &svg, &length) == TF_OK && strncmp(svg, "<?xml", 5) == 0;
    printf("C: talkface %s, %lu bytes of SVG%s%s\n", tf_version(), (unsigned long)length, ok ? "" : ", error: ",
           ok ? "" : tf_last_error_message());
    tf_free(svg);
    tf_face_state_destroy(state);
    tf_face_model_destroy(face);
    if (ok && argc > 1) ok = write_frame(argv[1]);
    return ok ? 0 : 1;
}

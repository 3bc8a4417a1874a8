/* Renders the default face through the installed C ABI. */
#include <stdio.h>
#include <string.h>
#include <talkface/talkface.h>

int main(void) {
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
    return ok ? 0 : 1;
}

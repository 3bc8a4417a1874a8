/* The C ABI driven from C: ownership, NULL tolerance, error codes and messages, thread-local errors.
 * Each test_ function returns its failure count; main exits non-zero if any check failed. */
#define _POSIX_C_SOURCE 200809L /* pthread_barrier_t */

#include <math.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "talkface/talkface.h"

#include "c_check.h"

static const char *output_path(const char *name, char *buffer, size_t size) {
    snprintf(buffer, size, "%s/%s", TF_TEST_OUTPUT_DIR, name);
    return buffer;
}

static int write_text_file(const char *path, const char *text) {
    FILE *file = fopen(path, "w");
    if (file == NULL) return 0;
    fputs(text, file);
    return fclose(file) == 0;
}

static int test_default_face_is_created_and_destroyed(void) {
    int failures = 0;
    tf_face_model *face = NULL;
    const char *name = NULL;
    double d_px = 0.0;
    CHECK_OK(tf_face_model_default(&face));
    CHECK(face != NULL);
    CHECK_OK(tf_face_model_name(face, &name));
    CHECK(name != NULL);
    CHECK_OK(tf_face_model_fapu(face, "d", &d_px));
    CHECK(d_px > 0.0);
    tf_face_model_destroy(face);
    return failures;
}

static int test_destroy_accepts_null(void) {
    tf_face_model_destroy(NULL);
    tf_lifted_face_destroy(NULL);
    tf_face_state_destroy(NULL);
    tf_projected_face_destroy(NULL);
    tf_svg_options_destroy(NULL);
    tf_free(NULL);
    return 0;
}

static int test_point_and_fapu_tables(void) {
    int failures = 0;
    CHECK(tf_face_point_count() == 72);
    CHECK(strcmp(tf_face_point_id(0), "hair.1") == 0);
    CHECK(strcmp(tf_face_point_id(71), "EyeballRight") == 0);
    CHECK(tf_face_point_id(72) == NULL);
    CHECK(tf_face_fapu_count() == 12);
    CHECK(strcmp(tf_face_fapu_name(0), "d") == 0);
    CHECK(strcmp(tf_face_fapu_name(11), "r2") == 0);
    CHECK(tf_face_fapu_name(12) == NULL);
    return failures;
}

static int test_setters_are_read_back_by_getters(void) {
    int failures = 0;
    tf_face_model *face = NULL;
    double x = 0.0, y = 0.0, value_px = 0.0;
    const char *name = NULL;
    tf_rgb colour = {0, 0, 0};
    const tf_rgb teal = {0x12, 0x80, 0x80};
    CHECK_OK(tf_face_model_default(&face));
    CHECK_OK(tf_face_model_set_point(face, "3.2", 123.5, 45.25));
    CHECK_OK(tf_face_model_point(face, "3.2", &x, &y));
    CHECK(x == 123.5 && y == 45.25);
    CHECK_OK(tf_face_model_set_fapu(face, "MW0", 33.5));
    CHECK_OK(tf_face_model_fapu(face, "MW0", &value_px));
    CHECK(value_px == 33.5);
    CHECK_OK(tf_face_model_set_name(face, "teal face"));
    CHECK_OK(tf_face_model_name(face, &name));
    CHECK(strcmp(name, "teal face") == 0);
    CHECK_OK(tf_face_model_set_color(face, TF_FACE_COLOR_IRIS, teal));
    CHECK_OK(tf_face_model_color(face, TF_FACE_COLOR_IRIS, &colour));
    CHECK(colour.r == teal.r && colour.g == teal.g && colour.b == teal.b);
    CHECK_FAILS_WITH(tf_face_model_point(face, "8.5", &x, &y), TF_ERR_INVALID_ARGUMENT, "\"8.5\"");
    CHECK(x == 123.5); /* outputs unchanged on failure */
    CHECK_FAILS_WITH(tf_face_model_set_fapu(face, "MW0", -1.0), TF_ERR_INVALID_ARGUMENT, "MW0");
    CHECK_FAILS_WITH(tf_face_model_set_color(face, (tf_face_color)42, teal), TF_ERR_INVALID_ARGUMENT,
                     "which");
    tf_face_model_destroy(face);
    return failures;
}

static int test_colours_round_trip_through_hex(void) {
    int failures = 0;
    tf_rgb colour = {0, 0, 0};
    char hex[8] = {0};
    CHECK_OK(tf_rgb_from_hex("#A0b1C2", &colour));
    CHECK(colour.r == 0xa0 && colour.g == 0xb1 && colour.b == 0xc2);
    CHECK_OK(tf_rgb_to_hex(colour, hex));
    CHECK(strcmp(hex, "#a0b1c2") == 0);
    CHECK_FAILS_WITH(tf_rgb_from_hex("teal", &colour), TF_ERR_INVALID_ARGUMENT, "text");
    return failures;
}

/* Every point and FAPU of a and b are equal, and tf_face_model_equal agrees. */
static int check_faces_equal(const tf_face_model *a, const tf_face_model *b) {
    int failures = 0;
    int is_equal = 0;
    size_t i;
    for (i = 0; i < tf_face_point_count(); ++i) {
        double ax = 0.0, ay = 0.0, bx = 1.0, by = 1.0;
        CHECK_OK(tf_face_model_point(a, tf_face_point_id(i), &ax, &ay));
        CHECK_OK(tf_face_model_point(b, tf_face_point_id(i), &bx, &by));
        if (ax != bx || ay != by) fprintf(stderr, "point %s differs\n", tf_face_point_id(i));
        CHECK(ax == bx && ay == by);
    }
    for (i = 0; i < tf_face_fapu_count(); ++i) {
        double a_px = 0.0, b_px = 1.0;
        CHECK_OK(tf_face_model_fapu(a, tf_face_fapu_name(i), &a_px));
        CHECK_OK(tf_face_model_fapu(b, tf_face_fapu_name(i), &b_px));
        if (a_px != b_px) fprintf(stderr, "FAPU %s differs\n", tf_face_fapu_name(i));
        CHECK(a_px == b_px);
    }
    CHECK_OK(tf_face_model_equal(a, b, &is_equal));
    CHECK(is_equal == 1);
    return failures;
}

static int test_saved_face_loads_back_equal(void) {
    int failures = 0;
    char path[1024];
    tf_face_model *face = NULL, *loaded = NULL;
    CHECK_OK(tf_face_model_default(&face));
    /* An odd value, so a lossy number format would show. */
    CHECK_OK(tf_face_model_set_point(face, "8.3", 101.0 / 3.0, 1e-7));
    CHECK_OK(tf_face_model_save(face, output_path("c_api_saved_face.xml", path, sizeof path)));
    CHECK_OK(tf_face_model_load(path, &loaded));
    if (loaded != NULL) failures += check_faces_equal(face, loaded);
    tf_face_model_destroy(loaded);
    tf_face_model_destroy(face);
    return failures;
}

static int test_xml_text_round_trips(void) {
    int failures = 0;
    tf_face_model *face = NULL, *parsed = NULL, *copy = NULL;
    char *xml = NULL;
    size_t length = 0;
    CHECK_OK(tf_face_model_default(&face));
    CHECK_OK(tf_face_model_to_xml(face, &xml, &length));
    CHECK(xml != NULL && strlen(xml) == length);
    CHECK_OK(tf_face_model_from_xml(xml, length, "face.xml", &parsed));
    if (parsed != NULL) failures += check_faces_equal(face, parsed);
    CHECK_OK(tf_face_model_clone(face, &copy));
    if (copy != NULL) failures += check_faces_equal(face, copy);
    tf_free(xml);
    tf_face_model_destroy(copy);
    tf_face_model_destroy(parsed);
    tf_face_model_destroy(face);
    return failures;
}

static int test_bad_path_gives_file_error_naming_it(void) {
    int failures = 0;
    const char *path = "/nonexistent/talkface/missing-face.xml";
    tf_face_model *face = NULL;
    CHECK_FAILS_WITH(tf_face_model_load(path, &face), TF_ERR_FILE, path);
    CHECK(face == NULL);
    CHECK_OK(tf_face_model_default(&face));
    CHECK_FAILS_WITH(tf_face_model_save(face, "/nonexistent/talkface/out.xml"), TF_ERR_FILE,
                     "/nonexistent/talkface/out.xml");
    tf_face_model_destroy(face);
    return failures;
}

static int test_broken_xml_gives_parse_error_naming_the_line(void) {
    int failures = 0;
    const char *broken = "<?xml version=\"1.0\"?>\n<face version=\"1\">\n  <point id=\"3.2\" x=\"1\"\n";
    char path[1024];
    tf_face_model *face = NULL;
    CHECK_FAILS_WITH(tf_face_model_from_xml(broken, strlen(broken), "face.xml", &face), TF_ERR_PARSE,
                     "face.xml:");
    CHECK(face == NULL);
    /* "face.xml:" followed by a line number. */
    {
        const char *where = strstr(tf_last_error_message(), "face.xml:");
        CHECK(where != NULL && where[9] >= '1' && where[9] <= '9');
    }
    CHECK(write_text_file(output_path("c_api_broken_face.xml", path, sizeof path), broken));
    CHECK_FAILS_WITH(tf_face_model_load(path, &face), TF_ERR_PARSE, path);
    CHECK(face == NULL);
    CHECK_FAILS_WITH(tf_face_model_from_xml(broken, strlen(broken), NULL, &face), TF_ERR_PARSE,
                     "<string>");
    return failures;
}

static int test_a_future_face_version_is_refused_naming_the_version_read(void) {
    int failures = 0;
    const char *future = "<?xml version=\"1.0\"?>\n<talkface-face version=\"999\" name=\"x\"/>\n";
    tf_face_model *face = NULL;
    CHECK_FAILS_WITH(tf_face_model_from_xml(future, strlen(future), "future.xml", &face), TF_ERR_PARSE,
                     "future.xml:2:16: attribute version: version 999 is newer than this library reads (up to 1)");
    CHECK(face == NULL);
    return failures;
}

static int test_null_arguments_are_named(void) {
    int failures = 0;
    tf_face_model *face = NULL;
    tf_face_state *state = NULL;
    double x = 0.0, y = 0.0;
    char *svg = NULL;
    CHECK_FAILS_WITH(tf_face_model_load(NULL, &face), TF_ERR_INVALID_ARGUMENT, "path");
    CHECK_FAILS_WITH(tf_face_model_load("face.xml", NULL), TF_ERR_INVALID_ARGUMENT, "out");
    CHECK_FAILS_WITH(tf_face_model_default(NULL), TF_ERR_INVALID_ARGUMENT, "out");
    CHECK_FAILS_WITH(tf_face_model_point(NULL, "3.2", &x, &y), TF_ERR_INVALID_ARGUMENT, "face");
    CHECK_OK(tf_face_model_default(&face));
    CHECK_FAILS_WITH(tf_face_model_point(face, NULL, &x, &y), TF_ERR_INVALID_ARGUMENT, "id");
    CHECK_FAILS_WITH(tf_face_model_point(face, "3.2", NULL, &y), TF_ERR_INVALID_ARGUMENT, "out_x");
    CHECK_FAILS_WITH(tf_face_model_to_xml(face, NULL, NULL), TF_ERR_INVALID_ARGUMENT, "out_xml");
    CHECK_FAILS_WITH(tf_face_state_set_pose(NULL, 0.0, 0.0, 0.0), TF_ERR_INVALID_ARGUMENT, "state");
    CHECK_OK(tf_face_state_create(&state));
    CHECK_FAILS_WITH(tf_render_svg(face, NULL, NULL, &svg, NULL), TF_ERR_INVALID_ARGUMENT, "state");
    CHECK_FAILS_WITH(tf_render_svg(face, state, NULL, NULL, NULL), TF_ERR_INVALID_ARGUMENT, "out_svg");
    CHECK(svg == NULL);
    CHECK_FAILS_WITH(tf_rotation3d_matrix(0.0, 0.0, 0.0, NULL), TF_ERR_INVALID_ARGUMENT, "out_matrix");
    tf_face_state_destroy(state);
    tf_face_model_destroy(face);
    return failures;
}

static int test_out_of_range_pose_names_the_angle(void) {
    int failures = 0;
    tf_face_state *state = NULL;
    CHECK_OK(tf_face_state_create(&state));
    CHECK_OK(tf_face_state_set_pose(state, 15.0, -15.0, 0.0));
    CHECK_FAILS_WITH(tf_face_state_set_pose(state, 0.0, 20.0, 0.0), TF_ERR_INVALID_ARGUMENT, "beta_deg");
    CHECK_FAILS_WITH(tf_face_state_set_pose(state, NAN, 0.0, 0.0), TF_ERR_INVALID_ARGUMENT, "alpha_deg");
    CHECK_FAILS_WITH(tf_face_state_set_blink(state, 0.0, 1.5), TF_ERR_INVALID_ARGUMENT, "blink_right");
    CHECK_FAILS_WITH(tf_face_state_set_smile(state, -0.1), TF_ERR_INVALID_ARGUMENT, "smile");
    CHECK_FAILS_WITH(tf_rotation3d_matrix(0.0, INFINITY, 0.0, (double[9]){0}), TF_ERR_INVALID_ARGUMENT,
                     "beta");
    tf_face_state_destroy(state);
    return failures;
}

static int test_render_returns_an_svg_of_the_stated_length(void) {
    int failures = 0;
    tf_face_model *face = NULL;
    tf_face_state *state = NULL;
    tf_svg_options *options = NULL;
    const tf_rgb white = {255, 255, 255};
    char *svg = NULL;
    size_t length = 0;
    char path[1024];
    FILE *file;
    char head[6] = {0};
    CHECK_OK(tf_face_model_default(&face));
    CHECK_OK(tf_face_state_create(&state));
    CHECK_OK(tf_face_state_set_pose(state, 5.0, 12.0, -3.0));
    CHECK_OK(tf_face_state_set_blink(state, 0.5, 0.5));
    CHECK_OK(tf_face_state_set_smile(state, 0.3));
    CHECK_OK(tf_face_state_set_brows(state, 0.2));
    CHECK_OK(tf_face_state_set_mouth_shape(state, face, TF_MOUTH_A));
    CHECK_OK(tf_render_svg(face, state, NULL, &svg, &length));
    CHECK(svg != NULL && strlen(svg) == length && strncmp(svg, "<?xml", 5) == 0);
    CHECK(svg != NULL && strstr(svg, "</svg>") != NULL);
    tf_free(svg);
    svg = NULL;

    CHECK_OK(tf_svg_options_create(&options));
    CHECK_OK(tf_svg_options_set_background(options, NULL));
    CHECK_OK(tf_svg_options_set_clothes(options, 0, white));
    CHECK_OK(tf_svg_options_set_stroke_width_in_d(options, 0.05));
    CHECK_OK(tf_svg_options_set_decimals(options, 3));
    CHECK_OK(tf_svg_options_set_size_px(options, 400, 500));
    CHECK_OK(tf_face_state_set_neutral_mouth(state));
    CHECK_OK(tf_render_svg(face, state, options, &svg, NULL));
    CHECK(svg != NULL && strncmp(svg, "<?xml", 5) == 0);
    tf_free(svg);

    CHECK_OK(tf_write_svg(face, state, options, output_path("c_api_face.svg", path, sizeof path)));
    file = fopen(path, "r");
    CHECK(file != NULL);
    if (file != NULL) {
        CHECK(fread(head, 1, 5, file) == 5 && strcmp(head, "<?xml") == 0);
        fclose(file);
    }
    CHECK_FAILS_WITH(tf_write_svg(face, state, NULL, "/nonexistent/talkface/face.svg"), TF_ERR_FILE,
                     "/nonexistent/talkface/face.svg");

    /* The flat look: no outline anywhere but the two upper lids' bands (the first stroke is the
       left lid's, the second the right's, none after); a look that is not one is refused when
       rendering. */
    CHECK_OK(tf_svg_options_set_look(options, TF_FACE_LOOK_FLAT));
    CHECK_OK(tf_render_svg(face, state, options, &svg, NULL));
    CHECK(svg != NULL);
    if (svg != NULL) {
        const char* left_lid = strstr(svg, "class=\"eye-left-lid\"");
        const char* right_lid = strstr(svg, "class=\"eye-right-lid\"");
        const char* first = strstr(svg, "stroke-width");
        const char* second = first != NULL ? strstr(first + 1, "stroke-width") : NULL;
        CHECK(left_lid != NULL && right_lid != NULL);
        CHECK(first != NULL && left_lid != NULL && first > left_lid && (right_lid == NULL || first < right_lid));
        CHECK(second != NULL && right_lid != NULL && second > right_lid);
        CHECK(second != NULL && strstr(second + 1, "stroke-width") == NULL);
    }
    tf_free(svg);
    svg = NULL;
    CHECK_OK(tf_svg_options_set_look(options, (tf_face_look)7));
    CHECK_FAILS_WITH(tf_render_svg(face, state, options, &svg, NULL), TF_ERR_INVALID_ARGUMENT, "look");
    CHECK(svg == NULL);
    CHECK_OK(tf_svg_options_set_look(options, TF_FACE_LOOK_OUTLINED));

    CHECK_OK(tf_svg_options_set_decimals(options, 99));
    svg = NULL;
    CHECK(tf_render_svg(face, state, options, &svg, NULL) == TF_ERR_INVALID_ARGUMENT);
    CHECK(svg == NULL);
    tf_svg_options_destroy(options);
    tf_face_state_destroy(state);
    tf_face_model_destroy(face);
    return failures;
}

static int test_status_names(void) {
    int failures = 0;
    CHECK(strcmp(tf_status_name(TF_OK), "TF_OK") == 0);
    CHECK(strcmp(tf_status_name(TF_ERR_INVALID_ARGUMENT), "TF_ERR_INVALID_ARGUMENT") == 0);
    CHECK(strcmp(tf_status_name(TF_ERR_FILE), "TF_ERR_FILE") == 0);
    CHECK(strcmp(tf_status_name(TF_ERR_PARSE), "TF_ERR_PARSE") == 0);
    CHECK(strcmp(tf_status_name(TF_ERR_ALIGNMENT), "TF_ERR_ALIGNMENT") == 0);
    CHECK(strcmp(tf_status_name(TF_ERR_CANCELLED), "TF_ERR_CANCELLED") == 0);
    CHECK(strcmp(tf_status_name(TF_ERR_OUT_OF_MEMORY), "TF_ERR_OUT_OF_MEMORY") == 0);
    CHECK(strcmp(tf_status_name(TF_ERR_INTERNAL), "TF_ERR_INTERNAL") == 0);
    CHECK(strcmp(tf_status_name((tf_status)99), "TF_ERR_UNKNOWN") == 0);
    CHECK(tf_version() != NULL && tf_version()[0] != '\0');
    return failures;
}

static int test_rotation_matrix_is_orthonormal(void) {
    int failures = 0;
    const double tolerance = 1e-12;
    double alpha, beta, gamma;
    for (alpha = -15.0; alpha <= 15.0; alpha += 7.5) {
        for (beta = -15.0; beta <= 15.0; beta += 7.5) {
            for (gamma = -15.0; gamma <= 15.0; gamma += 7.5) {
                double r[9];
                double p[3] = {3.0, -2.0, 5.0}, q[3], back[3];
                double det;
                int i, j, k;
                CHECK_OK(tf_rotation3d_matrix(alpha, beta, gamma, r));
                for (i = 0; i < 3; ++i) {
                    for (j = 0; j < 3; ++j) {
                        double dot = 0.0;
                        for (k = 0; k < 3; ++k) dot += r[3 * i + k] * r[3 * j + k];
                        if (fabs(dot - (i == j ? 1.0 : 0.0)) > tolerance) {
                            fprintf(stderr, "alpha %g beta %g gamma %g: (R R^T)[%d][%d] = %.17g\n",
                                    alpha, beta, gamma, i, j, dot);
                        }
                        CHECK(fabs(dot - (i == j ? 1.0 : 0.0)) <= tolerance);
                    }
                }
                det = r[0] * (r[4] * r[8] - r[5] * r[7]) - r[1] * (r[3] * r[8] - r[5] * r[6]) +
                      r[2] * (r[3] * r[7] - r[4] * r[6]);
                CHECK(fabs(det - 1.0) <= tolerance);
                CHECK_OK(tf_rotation3d_rotate(alpha, beta, gamma, p, q));
                CHECK(fabs(q[0] - (r[0] * p[0] + r[1] * p[1] + r[2] * p[2])) <= tolerance);
                CHECK_OK(tf_rotation3d_unrotate(alpha, beta, gamma, q, back));
                CHECK(fabs(back[0] - p[0]) <= tolerance && fabs(back[1] - p[1]) <= tolerance &&
                      fabs(back[2] - p[2]) <= tolerance);
            }
        }
    }
    return failures;
}

static int test_mouth_shape_names_round_trip(void) {
    int failures = 0;
    int value;
    tf_mouth_shape parsed = TF_MOUTH_M;
    tf_face_model *face = NULL, *open_mouth = NULL;
    double up[2], down[2], left[2], right[2], neutral_up[2], neutral_down[2], neutral_left[2],
        neutral_right[2];
    for (value = 0; value < TF_MOUTH_SHAPE_COUNT; ++value) {
        const char *name = tf_mouth_shape_name((tf_mouth_shape)value);
        CHECK(name != NULL);
        CHECK_OK(tf_mouth_shape_from_name(name, &parsed));
        CHECK((int)parsed == value);
    }
    CHECK(strcmp(tf_mouth_shape_name(TF_MOUTH_H_PRIME), "h'") == 0);
    CHECK_OK(tf_mouth_shape_from_name("h_prime", &parsed));
    CHECK(parsed == TF_MOUTH_H_PRIME);
    CHECK(tf_mouth_shape_name((tf_mouth_shape)TF_MOUTH_SHAPE_COUNT) == NULL);
    CHECK_FAILS_WITH(tf_mouth_shape_from_name("q", &parsed), TF_ERR_INVALID_ARGUMENT, "q");

    CHECK_OK(tf_face_model_default(&face));
    CHECK_OK(tf_neutral_mouth_controls(face, neutral_up, neutral_down, neutral_left, neutral_right));
    CHECK_OK(tf_mouth_controls(face, TF_MOUTH_A, up, down, left, right));
    CHECK(down[1] - up[1] > neutral_down[1] - neutral_up[1]); /* a opens the mouth */
    CHECK(left[0] < right[0]);                                /* corners never cross */
    CHECK_OK(tf_apply_mouth(face, up, down, left, right, &open_mouth));
    {
        double x = 0.0, y = 0.0;
        CHECK_OK(tf_face_model_point(open_mouth, "8.2", &x, &y));
        CHECK(x == down[0] && y == down[1]);
    }
    CHECK_FAILS_WITH(tf_mouth_controls(face, (tf_mouth_shape)12, up, down, left, right),
                     TF_ERR_INVALID_ARGUMENT, "shape");
    tf_face_model_destroy(open_mouth);
    tf_face_model_destroy(face);
    return failures;
}

static int test_expression_changes_the_eyes(void) {
    int failures = 0;
    tf_face_model *face = NULL, *blinking = NULL;
    double open_top = 0.0, closed_top = 0.0, x = 0.0;
    CHECK_OK(tf_face_model_default(&face));
    CHECK_OK(tf_apply_expression(face, 1.0, 0.0, 0.0, 0.0, &blinking));
    CHECK_OK(tf_face_model_point(face, "3.2", &x, &open_top));
    CHECK_OK(tf_face_model_point(blinking, "3.2", &x, &closed_top));
    CHECK(closed_top > open_top); /* the upper lid moves down (y down) */
    CHECK_FAILS_WITH(tf_apply_expression(face, 0.0, 0.0, 2.0, 0.0, &blinking), TF_ERR_INVALID_ARGUMENT,
                     "smile");
    tf_face_model_destroy(blinking);
    tf_face_model_destroy(face);
    return failures;
}

static int test_lift_and_place(void) {
    int failures = 0;
    tf_face_model *face = NULL, *placed = NULL;
    tf_lifted_face *lifted = NULL;
    size_t count = 0;
    const char *id = NULL;
    double origin_x = 0.0, origin_y = 0.0, d_px = 0.0, xyz[3], x = 0.0, y = 0.0, depth = 0.0;
    double eye_x = 0.0, eye_y = 0.0;
    CHECK_OK(tf_face_model_default(&face));
    CHECK_OK(tf_lift_face(face, &lifted));
    CHECK_OK(tf_lifted_face_point_count(lifted, &count));
    CHECK(count == 89);
    CHECK_OK(tf_lifted_face_point_id(lifted, 72, &id));
    CHECK(id != NULL && strcmp(id, "A") == 0);
    CHECK_FAILS_WITH(tf_lifted_face_point_id(lifted, 89, &id), TF_ERR_INVALID_ARGUMENT, "index");
    CHECK_OK(tf_lifted_face_origin(lifted, &origin_x, &origin_y, &d_px));
    CHECK(d_px > 0.0);
    CHECK_OK(tf_lifted_face_local(lifted, "3.2", xyz));
    CHECK_OK(tf_face_model_point(face, "3.2", &eye_x, &eye_y));
    /* The local frame: x towards the image left, y up, from O; back to the image exactly. */
    CHECK(origin_x - xyz[0] == eye_x && origin_y - xyz[1] == eye_y);
    CHECK_OK(tf_depth_in_d("A", &depth));
    CHECK_FAILS_WITH(tf_depth_in_d("Z9", &depth), TF_ERR_INVALID_ARGUMENT, "Z9");
    CHECK_OK(tf_rotation_origin(face, &x, &y));
    CHECK(x == origin_x && y == origin_y);

    CHECK_OK(tf_place_face(face, 300.0, 400.0, 2.0 * d_px, &placed));
    CHECK_OK(tf_rotation_origin(placed, &x, &y));
    CHECK(fabs(x - 300.0) < 1e-9 && fabs(y - 400.0) < 1e-9);
    CHECK_OK(tf_face_model_fapu(placed, "d", &depth));
    CHECK(fabs(depth - 2.0 * d_px) < 1e-9);
    CHECK_FAILS_WITH(tf_place_face(face, 0.0, 0.0, -1.0, &placed), TF_ERR_INVALID_ARGUMENT, "d_px");
    tf_face_model_destroy(placed);
    tf_lifted_face_destroy(lifted);
    tf_face_model_destroy(face);
    return failures;
}

static int test_projection_getters(void) {
    int failures = 0;
    tf_face_model *face = NULL, *drawn = NULL;
    tf_face_state *state = NULL;
    tf_projected_face *projected = NULL;
    size_t count = 0, i;
    const char *id = NULL;
    const char *contour[3] = {NULL, NULL, NULL};
    tf_side side = TF_SIDE_RIGHT;
    double x = 0.0, y = 0.0, origin_x = 0.0, origin_y = 0.0, d_px = 0.0;
    const double up[2] = {100.0, 200.0}, down[2] = {100.0, 220.0}, left[2] = {80.0, 210.0},
                 right[2] = {120.0, 210.0};
    CHECK_OK(tf_face_model_default(&face));
    CHECK_OK(tf_face_state_create(&state));
    CHECK_OK(tf_project_face(face, state, &projected));
    CHECK_OK(tf_projected_face_point_count(projected, &count));
    CHECK(count == 89);
    CHECK_OK(tf_projected_face_point_id(projected, 0, &id));
    CHECK(id != NULL && strcmp(id, "hair.1") == 0);
    /* A frontal, neutral projection draws every model point where the model has it. */
    for (i = 0; i < tf_face_point_count(); ++i) {
        double model_x = 0.0, model_y = 0.0;
        const char *point_id = tf_face_point_id(i);
        if (strncmp(point_id, "Eyeball", 7) == 0) continue; /* pupils follow the gaze */
        CHECK_OK(tf_face_model_point(face, point_id, &model_x, &model_y));
        CHECK_OK(tf_projected_face_point(projected, point_id, &x, &y));
        CHECK(fabs(x - model_x) < 1e-9 && fabs(y - model_y) < 1e-9);
    }
    CHECK_OK(tf_projected_face_contour(projected, TF_SIDE_LEFT, contour));
    CHECK(contour[0] != NULL && strcmp(contour[0], "11.2") == 0);
    CHECK_FAILS_WITH(tf_projected_face_contour(projected, (tf_side)2, contour), TF_ERR_INVALID_ARGUMENT,
                     "side");
    CHECK_OK(tf_projected_face_nose_bridge(projected, &side));
    CHECK(side == TF_SIDE_LEFT || side == TF_SIDE_RIGHT);
    CHECK_OK(tf_projected_face_origin(projected, &origin_x, &origin_y, &d_px));
    CHECK(d_px > 0.0);
    CHECK_OK(tf_projected_face_face(projected, &drawn));
    CHECK(drawn != NULL);
    CHECK_FAILS_WITH(tf_projected_face_point(projected, "Z", &x, &y), TF_ERR_INVALID_ARGUMENT, "Z");
    tf_projected_face_destroy(projected);
    projected = NULL;

    CHECK_OK(tf_face_state_set_mouth_controls(state, up, down, left, right));
    CHECK_OK(tf_project_face(face, state, &projected));
    CHECK_OK(tf_projected_face_point(projected, "8.2", &x, &y));
    CHECK(fabs(x - 100.0) < 1e-9 && fabs(y - 220.0) < 1e-9);
    tf_projected_face_destroy(projected);
    tf_face_model_destroy(drawn);
    tf_face_state_destroy(state);
    tf_face_model_destroy(face);
    return failures;
}

/* Two threads: one fails, one succeeds; each must see only its own last error. */
typedef struct thread_case {
    pthread_barrier_t *barrier;
    int should_fail;
    int failures;
} thread_case;

static void *run_thread_case(void *argument) {
    thread_case *self = (thread_case *)argument;
    int failures = 0;
    tf_face_model *face = NULL;
    const char *path = "/nonexistent/thread-local.xml";
    if (self->should_fail) {
        CHECK(tf_face_model_load(path, &face) == TF_ERR_FILE);
        pthread_barrier_wait(self->barrier); /* fails first ... */
        pthread_barrier_wait(self->barrier); /* ... then the other thread succeeds */
        CHECK(strstr(tf_last_error_message(), path) != NULL);
    } else {
        pthread_barrier_wait(self->barrier);
        CHECK_OK(tf_face_model_default(&face));
        pthread_barrier_wait(self->barrier);
        CHECK(strcmp(tf_last_error_message(), "") == 0);
    }
    tf_face_model_destroy(face);
    self->failures = failures;
    return NULL;
}

static int test_last_error_is_thread_local(void) {
    int failures = 0;
    pthread_barrier_t barrier;
    pthread_t threads[2];
    thread_case cases[2];
    int i;
    tf_face_model *face = NULL;
    CHECK(tf_face_model_default(NULL) == TF_ERR_INVALID_ARGUMENT);
    pthread_barrier_init(&barrier, NULL, 2);
    for (i = 0; i < 2; ++i) {
        cases[i].barrier = &barrier;
        cases[i].should_fail = i == 0;
        cases[i].failures = 0;
        CHECK(pthread_create(&threads[i], NULL, run_thread_case, &cases[i]) == 0);
    }
    for (i = 0; i < 2; ++i) {
        pthread_join(threads[i], NULL);
        failures += cases[i].failures;
    }
    pthread_barrier_destroy(&barrier);
    /* The main thread's own failure is untouched by both. */
    CHECK(strstr(tf_last_error_message(), "out") != NULL);
    CHECK_OK(tf_face_model_default(&face));
    CHECK(strcmp(tf_last_error_message(), "") == 0);
    tf_face_model_destroy(face);
    return failures;
}

int main(void) {
    int failures = 0;
    failures += test_default_face_is_created_and_destroyed();
    failures += test_destroy_accepts_null();
    failures += test_point_and_fapu_tables();
    failures += test_setters_are_read_back_by_getters();
    failures += test_colours_round_trip_through_hex();
    failures += test_saved_face_loads_back_equal();
    failures += test_xml_text_round_trips();
    failures += test_bad_path_gives_file_error_naming_it();
    failures += test_broken_xml_gives_parse_error_naming_the_line();
    failures += test_a_future_face_version_is_refused_naming_the_version_read();
    failures += test_null_arguments_are_named();
    failures += test_out_of_range_pose_names_the_angle();
    failures += test_render_returns_an_svg_of_the_stated_length();
    failures += test_status_names();
    failures += test_rotation_matrix_is_orthonormal();
    failures += test_mouth_shape_names_round_trip();
    failures += test_expression_changes_the_eyes();
    failures += test_lift_and_place();
    failures += test_projection_getters();
    failures += test_last_error_is_thread_local();
    if (failures != 0) {
        fprintf(stderr, "c_api_test: %d check(s) failed\n", failures);
        return EXIT_FAILURE;
    }
    printf("c_api_test: all checks passed\n");
    return EXIT_SUCCESS;
}

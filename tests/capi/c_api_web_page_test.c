/* The C ABI of the animation as SVG and as Lottie and of the web page, driven from C: both
 * encodings, the Lottie document, a page whose hostile texts stay text, refused links, and
 * all-or-nothing writes. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "talkface/talkface.h"

#include "c_check.h"

static const char *const kSpeech = TALKFACE_SOURCE_DIR "/samples/speech/demo.ogg";
static const char *const kHostile = "</script><img src=x onerror=alert(1)>\"'&";

/* One sentence with a hostile text, "ma1 ma1 hao3" spoken from 0.5 s, 2 s long. */
static tf_timeline *new_timeline(void) {
    tf_timeline *timeline = NULL;
    if (tf_timeline_create(&timeline) != TF_OK) return NULL;
    tf_timeline_add_sentence(timeline, kHostile, 0.5, 1.25);
    tf_timeline_add_syllable(timeline, "\xe5\xaa\xbd", "ma1", 0, 0.5, 0.75);
    tf_timeline_add_syllable(timeline, "\xe5\xaa\xbd", "ma1", 0, 0.75, 1.0);
    tf_timeline_add_syllable(timeline, "\xe5\xa5\xbd", "hao3", 0, 1.0, 1.25);
    tf_timeline_set_duration_s(timeline, 2.0);
    return timeline;
}

static int test_animation_svg(const tf_face_model *face, const tf_animation *animation) {
    int failures = 0;
    char *svg = NULL;
    size_t length = 0;
    CHECK_OK(tf_render_animation_svg(face, animation, NULL, TF_ENCODING_KEYFRAMES, NULL, NULL, &svg, &length));
    CHECK(svg != NULL && strlen(svg) == length);
    CHECK(svg != NULL && strstr(svg, "<animate attributeName=\"d\"") != NULL);
    CHECK(svg != NULL && strstr(svg, "class=\"tf-animation\"") != NULL);
    tf_free(svg);
    svg = NULL;
    CHECK_OK(tf_render_animation_svg(face, animation, NULL, TF_ENCODING_FRAMES, NULL, NULL, &svg, NULL));
    CHECK(svg != NULL && strstr(svg, "<set attributeName=\"visibility\"") != NULL);
    tf_free(svg);
    CHECK_FAILS_WITH(tf_render_animation_svg(face, animation, NULL, (tf_animation_encoding)7, NULL, NULL, &svg, NULL),
                     TF_ERR_INVALID_ARGUMENT, "encoding");
    CHECK_FAILS_WITH(tf_write_animation_svg(face, animation, NULL, TF_ENCODING_KEYFRAMES, "/nonexistent/dir/a.svg"),
                     TF_ERR_FILE, "/nonexistent/dir/a.svg");
    return failures;
}

/* The tolerance of tf_svg_animation_options: the defaults give tf_render_animation_svg's document,
 * a coarser tolerance fewer key frames (a shorter document), and a tolerance of 0 is refused by name,
 * from the SVG calls and from the page. */
static int test_animation_svg_options(const tf_face_model* face, const tf_animation* animation,
                                      const tf_timeline* timeline) {
    int failures = 0;
    tf_svg_animation_options* options = NULL;
    tf_web_page_options* page_options = NULL;
    char* plain = NULL;
    char* svg = NULL;
    char* html = NULL;
    size_t plain_length = 0;
    size_t length = 0;
    char path[512];
    CHECK_OK(tf_render_animation_svg(face, animation, NULL, TF_ENCODING_KEYFRAMES, NULL, NULL, &plain,
                                     &plain_length));
    CHECK_OK(tf_render_animation_svg_with_options(face, animation, NULL, NULL, NULL, NULL, &svg, &length));
    CHECK(plain != NULL && svg != NULL && length == plain_length && strcmp(plain, svg) == 0);
    tf_free(svg);
    svg = NULL;
    CHECK_OK(tf_svg_animation_options_create(&options));
    CHECK_OK(tf_svg_animation_options_set_tolerance_px(options, 3.0));
    CHECK_OK(tf_render_animation_svg_with_options(face, animation, NULL, options, NULL, NULL, &svg, &length));
    CHECK(svg != NULL && length < plain_length);
    tf_free(svg);
    svg = NULL;
    CHECK_OK(tf_svg_animation_options_set_encoding(options, TF_ENCODING_FRAMES));
    CHECK_OK(tf_render_animation_svg_with_options(face, animation, NULL, options, NULL, NULL, &svg, NULL));
    CHECK(svg != NULL && strstr(svg, "<set attributeName=\"visibility\"") != NULL);
    tf_free(svg);
    svg = NULL;
    CHECK_FAILS_WITH(tf_svg_animation_options_set_encoding(options, (tf_animation_encoding)7),
                     TF_ERR_INVALID_ARGUMENT, "encoding");
    CHECK_OK(tf_svg_animation_options_set_encoding(options, TF_ENCODING_KEYFRAMES));
    CHECK_OK(tf_svg_animation_options_set_tolerance_px(options, 0.0));
    CHECK_FAILS_WITH(
        tf_render_animation_svg_with_options(face, animation, NULL, options, NULL, NULL, &svg, NULL),
        TF_ERR_INVALID_ARGUMENT, "tolerance_px");
    CHECK(svg == NULL);
    snprintf(path, sizeof path, "%s/c_api_tolerance.svg", TF_TEST_OUTPUT_DIR);
    CHECK_FAILS_WITH(tf_write_animation_svg_with_options(face, animation, NULL, options, path),
                     TF_ERR_INVALID_ARGUMENT, "tolerance_px");
    CHECK_OK(tf_write_animation_svg_with_options(face, animation, NULL, NULL, path));
    CHECK_FAILS_WITH(tf_svg_animation_options_set_tolerance_px(NULL, 0.3), TF_ERR_INVALID_ARGUMENT,
                     "options");
    tf_svg_animation_options_destroy(options);
    tf_svg_animation_options_destroy(NULL);

    CHECK_OK(tf_web_page_options_create(&page_options));
    CHECK_OK(tf_web_page_options_set_audio(page_options, TF_PAGE_AUDIO_LINK, 0, "speech.ogg"));
    CHECK_OK(tf_web_page_options_set_tolerance_px(page_options, -1.0));
    CHECK_FAILS_WITH(
        tf_build_web_page(face, NULL, animation, timeline, kSpeech, page_options, NULL, NULL, &html, NULL),
        TF_ERR_INVALID_ARGUMENT, "tolerance_px");
    CHECK(html == NULL);
    CHECK_OK(tf_web_page_options_set_tolerance_px(page_options, 3.0));
    CHECK_OK(tf_build_web_page(face, NULL, animation, timeline, kSpeech, page_options, NULL, NULL, &html,
                               &length));
    tf_free(html);
    html = NULL;
    CHECK_OK(tf_web_page_options_set_tolerance_px(page_options, 0.3));
    CHECK_OK(tf_build_web_page(face, NULL, animation, timeline, kSpeech, page_options, NULL, NULL, &html,
                               &plain_length));
    CHECK(length < plain_length);
    tf_free(html);
    tf_free(plain);
    tf_web_page_options_destroy(page_options);
    return failures;
}

static int test_animation_lottie(const tf_face_model *face, const tf_animation *animation) {
    int failures = 0;
    char *json = NULL;
    size_t length = 0;
    char path[512];
    FILE *file = NULL;
    tf_svg_options *options = NULL;
    CHECK_OK(tf_svg_options_create(&options));
    CHECK_OK(tf_svg_options_set_background(options, NULL));
    CHECK_OK(tf_render_animation_lottie(face, animation, options, 0.3, NULL, NULL, &json, &length));
    CHECK(json != NULL && strlen(json) == length);
    CHECK(json != NULL && strncmp(json, "{\"v\":\"5.7.4\",\"fr\":25,", 19) == 0);
    /* The mouth moves (an animated Bezier path); no background layer without a colour. */
    CHECK(json != NULL && strstr(json, "\"nm\":\"lips\",\"it\":[{\"ty\":\"sh\",\"ks\":{\"a\":1,") != NULL);
    CHECK(json != NULL && strstr(json, "\"nm\":\"background\"") == NULL);
    tf_free(json);
    tf_svg_options_destroy(options);
    CHECK_FAILS_WITH(tf_render_animation_lottie(face, animation, NULL, 0.0, NULL, NULL, &json, NULL),
                     TF_ERR_INVALID_ARGUMENT, "tolerance_px");
    CHECK_FAILS_WITH(tf_render_animation_lottie(face, NULL, NULL, 0.3, NULL, NULL, &json, NULL),
                     TF_ERR_INVALID_ARGUMENT, "animation");
    snprintf(path, sizeof path, "%s/c_api_face.json", TF_TEST_OUTPUT_DIR);
    CHECK_OK(tf_write_animation_lottie(face, animation, NULL, 0.3, path));
    file = fopen(path, "rb");
    CHECK(file != NULL);
    if (file != NULL) fclose(file);
    CHECK_FAILS_WITH(tf_write_animation_lottie(face, animation, NULL, 0.3, "/nonexistent/dir/a.json"), TF_ERR_FILE,
                     "/nonexistent/dir/a.json");
    return failures;
}

static int test_web_page(const tf_face_model *face, const tf_animation *animation, const tf_timeline *timeline) {
    int failures = 0;
    tf_web_page_options *options = NULL;
    char *html = NULL;
    size_t length = 0;
    double origin[2] = {600.0, 330.0};
    tf_rgb stage = {0x20, 0x30, 0x40};
    char path[512];
    FILE *file = NULL;
    CHECK_OK(tf_web_page_options_create(&options));
    CHECK_OK(tf_web_page_options_set_app(options, TF_PAGE_AUDIOBOOK));
    CHECK_OK(tf_web_page_options_set_title(options, kHostile));
    CHECK_OK(tf_web_page_options_add_link(options, kHostile, "https://example.org/a?b=1&c=2"));
    CHECK_OK(tf_build_web_page(face, NULL, animation, timeline, kSpeech, options, NULL, NULL, &html, &length));
    CHECK(html != NULL && strlen(html) == length);
    CHECK(html != NULL && strstr(html, "<img") == NULL);
    CHECK(html != NULL && strstr(html, "&lt;/script&gt;&lt;img src=x onerror=alert(1)&gt;&quot;&#39;&amp;") != NULL);
    CHECK(html != NULL && strstr(html, "data:audio/webm;base64,") != NULL);
    tf_free(html);
    CHECK_OK(tf_web_page_options_set_audio(options, TF_PAGE_AUDIO_ORIGINAL, 0, NULL));
    html = NULL;
    CHECK_OK(tf_build_web_page(face, NULL, animation, timeline, kSpeech, options, NULL, NULL, &html, NULL));
    CHECK(html != NULL && strstr(html, "data:audio/ogg;base64,") != NULL);
    tf_free(html);
    CHECK_OK(tf_web_page_options_set_audio(options, TF_PAGE_AUDIO_COMPRESSED, 500, NULL));
    html = NULL;
    CHECK_FAILS_WITH(tf_build_web_page(face, NULL, animation, timeline, kSpeech, options, NULL, NULL, &html, NULL),
                     TF_ERR_INVALID_ARGUMENT, "audio_bitrate_bps");
    CHECK(html == NULL);
    CHECK_FAILS_WITH(tf_web_page_options_set_audio(options, (tf_web_page_audio)3, 0, NULL), TF_ERR_INVALID_ARGUMENT,
                     "TF_PAGE_AUDIO_LINK");

    CHECK_OK(tf_web_page_options_set_app(options, TF_PAGE_ANNOUNCER));
    CHECK_OK(tf_web_page_options_set_stage(options, 800, 450, stage, NULL));
    CHECK_OK(tf_web_page_options_set_face_placement(options, origin, 60.0));
    CHECK_OK(tf_web_page_options_set_encoding(options, TF_ENCODING_FRAMES));
    CHECK_OK(tf_web_page_options_set_audio(options, TF_PAGE_AUDIO_LINK, 0, "speech.ogg"));
    html = NULL;
    CHECK_OK(tf_build_web_page(face, NULL, animation, timeline, kSpeech, options, NULL, NULL, &html, NULL));
    CHECK(html != NULL && strstr(html, "src=\"speech.ogg\"") != NULL);
    CHECK(html != NULL && strstr(html, "class=\"tf-stage\"") != NULL);
    tf_free(html);

    CHECK_FAILS_WITH(tf_web_page_options_set_app(options, (tf_web_page_app)9), TF_ERR_INVALID_ARGUMENT, "app");
    CHECK_OK(tf_web_page_options_add_link(options, "run", "javascript:alert(1)"));
    html = NULL;
    CHECK_FAILS_WITH(tf_build_web_page(face, NULL, animation, timeline, kSpeech, options, NULL, NULL, &html, NULL),
                     TF_ERR_INVALID_ARGUMENT, "links[1].url");
    CHECK(html == NULL);

    /* A failed write leaves an earlier page as it was. */
    snprintf(path, sizeof path, "%s/c_api_page.html", TF_TEST_OUTPUT_DIR);
    file = fopen(path, "w");
    if (file != NULL) {
        fputs("old", file);
        fclose(file);
    }
    CHECK_FAILS_WITH(tf_write_web_page(face, NULL, animation, timeline, kSpeech, options, path),
                     TF_ERR_INVALID_ARGUMENT, "javascript");
    file = fopen(path, "r");
    CHECK(file != NULL);
    if (file != NULL) {
        char content[8] = {0};
        CHECK(fread(content, 1, sizeof content - 1, file) == 3 && strcmp(content, "old") == 0);
        fclose(file);
    }
    CHECK_FAILS_WITH(tf_write_web_page(face, NULL, animation, timeline, "/nonexistent/speech.ogg", NULL, path),
                     TF_ERR_FILE, "/nonexistent/speech.ogg");
    CHECK_FAILS_WITH(tf_build_web_page(face, NULL, animation, NULL, kSpeech, NULL, NULL, NULL, &html, NULL),
                     TF_ERR_INVALID_ARGUMENT, "timeline");
    tf_web_page_options_destroy(options);
    tf_web_page_options_destroy(NULL);
    return failures;
}

int main(void) {
    int failures = 0;
    tf_face_model *face = NULL;
    tf_timeline *timeline = new_timeline();
    tf_expression_simulator *simulator = NULL;
    tf_animation *animation = NULL;
    CHECK(timeline != NULL);
    CHECK_OK(tf_face_model_default(&face));
    CHECK_OK(tf_expression_simulator_create(timeline, 7, NULL, &simulator));
    CHECK_OK(tf_animate(face, timeline, simulator, NULL, &animation));
    if (face != NULL && animation != NULL) {
        failures += test_animation_svg(face, animation);
        failures += test_animation_svg_options(face, animation, timeline);
        failures += test_animation_lottie(face, animation);
        failures += test_web_page(face, animation, timeline);
    }
    tf_animation_destroy(animation);
    tf_expression_simulator_destroy(simulator);
    tf_timeline_destroy(timeline);
    tf_face_model_destroy(face);
    if (failures == 0) printf("c_api_web_page_test: all checks passed\n");
    return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}

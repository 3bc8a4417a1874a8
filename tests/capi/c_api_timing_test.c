/* The C ABI of timing exports and imports: Rhubarb cues and a TextGrid from a built timeline and
 * its animation, every import format read back, refusals naming the file and where the texts part. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "talkface/talkface.h"

#include "c_check.h"

/* "你好。" spoken 0.5-1.0 s, 1.5 s of audio. */
static tf_timeline *new_transcript(void) {
    const char *text = "\xe4\xbd\xa0\xe5\xa5\xbd\xe3\x80\x82";
    tf_timeline *timeline = NULL;
    if (tf_read_transcript(text, strlen(text), NULL, &timeline) != TF_OK) return NULL;
    return timeline;
}

static int test_export_and_read_back(void) {
    int failures = 0;
    tf_timeline *transcript = new_transcript();
    tf_timeline *timeline = NULL;
    tf_timeline *back = NULL;
    tf_face_model *face = NULL;
    tf_expression_simulator *simulator = NULL;
    tf_animation *animation = NULL;
    char *document = NULL;
    size_t length = 0;
    double start_s = 0.0;
    double end_s = 0.0;
    const char *words = "[{\"text\": \"\xe4\xbd\xa0\xe5\xa5\xbd\", \"start\": 0.5, \"end\": 1.0}]";
    const char *parted = "[{\"text\": \"\xe4\xbd\xa0\",\"start\": 0.5, \"end\": 0.75},\n"
                         " {\"text\": \"\xe4\xbb\xac\", \"start\": 0.75, \"end\": 1.0}]";
    const char *formats[] = {"textgrid", "srt", "vtt", "words-json", "timeline-json"};
    size_t k;
    CHECK(transcript != NULL);
    CHECK_OK(tf_read_timing_string(words, strlen(words), "words-json", transcript, 1.5, "words.json", &timeline));
    CHECK_OK(tf_timeline_syllable_times(timeline, 1, &start_s, &end_s, NULL, NULL));
    CHECK(start_s == 0.75 && end_s == 1.0);
    CHECK_OK(tf_face_model_default(&face));
    CHECK_OK(tf_expression_simulator_create(timeline, 7, NULL, &simulator));
    CHECK_OK(tf_animate(face, timeline, simulator, NULL, &animation));
    CHECK_OK(tf_export_to_string(timeline, animation, "rhubarb-tsv", NULL, &document, &length));
    CHECK(strlen(document) == length);
    CHECK(strncmp(document, "0.00\tX\n", 7) == 0);
    CHECK(strstr(document, "\n1.50\tX\n") != NULL);
    tf_free(document);
    document = NULL;
    CHECK_FAILS_WITH(tf_export_to_string(timeline, animation, "lottie", NULL, &document, NULL),
                     TF_ERR_INVALID_ARGUMENT, "\"lottie\" is not an export format");
    CHECK_FAILS_WITH(tf_export_to_file("cues.xyz", timeline, animation, NULL, NULL), TF_ERR_INVALID_ARGUMENT,
                     "suffix \".xyz\"");
    for (k = 0; k < sizeof formats / sizeof formats[0]; ++k) {
        CHECK_OK(tf_write_timing_string(timeline, formats[k], &document, &length));
        CHECK_OK(tf_read_timing_string(document, length, formats[k], transcript, 1.5, NULL, &back));
        CHECK_OK(tf_timeline_syllable_times(back, 0, &start_s, &end_s, NULL, NULL));
        if (!(start_s == 0.5 && end_s == 0.75)) {
            printf("  round trip through %s: %g-%g s\n", formats[k], start_s, end_s);
            ++failures;
        }
        tf_free(document);
        tf_timeline_destroy(back);
        back = NULL;
    }
    CHECK_FAILS_WITH(tf_read_timing_string(parted, strlen(parted), "json", transcript, 1.5, "w.json", &back),
                     TF_ERR_PARSE, "w.json:2: \"\xe4\xbb\xac\": \"\xe4\xbb\xac\" parts from the transcript at sentence 1");
    CHECK(back == NULL);
    CHECK_FAILS_WITH(tf_read_timing_string(words, strlen(words), "words-json", transcript, 0.9, "w.json", &back),
                     TF_ERR_PARSE, "past the end of the audio (0.9 s)");
    CHECK_FAILS_WITH(tf_read_timing_file("/no/such/dir/t.TextGrid", transcript, 1.5, NULL, &back), TF_ERR_FILE,
                     "/no/such/dir/t.TextGrid");
    CHECK_FAILS_WITH(tf_read_timing_string(NULL, 0, "srt", transcript, 1.5, NULL, &back), TF_ERR_INVALID_ARGUMENT,
                     "text");
    tf_animation_destroy(animation);
    tf_expression_simulator_destroy(simulator);
    tf_face_model_destroy(face);
    tf_timeline_destroy(timeline);
    tf_timeline_destroy(transcript);
    return failures;
}

int main(void) {
    int failures = 0;
    failures += test_export_and_read_back();
    if (failures != 0) {
        printf("%d check(s) failed\n", failures);
        return 1;
    }
    printf("all checks passed\n");
    return 0;
}

/* The C ABI of the speech aligner, driven from C: a clip aligned from its file and from samples read
 * here, options and their checks, progress and cancellation, and errors that name what was wrong. */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "talkface/talkface.h"

#include "c_check.h"

#define CLIP_DIR TALKFACE_SOURCE_DIR "/tests/data/speech/"
#define AUDIO_DIR TALKFACE_SOURCE_DIR "/tests/data/audio/"

/* 3.09 s, 16 kHz mono 16-bit: 小朋友們在公園裡放風箏。 (tests/data/speech/README.md) */
static const char kClipPath[] = CLIP_DIR "one_sentence.wav";
static const char kTranscriptPath[] = CLIP_DIR "one_sentence.txt";
static const double kClipDurationS = 3.09052;
static const size_t kClipSyllables = 11;

/* A 16-bit PCM WAV file's samples as floats in -1..1 (libsndfile's scaling: x / 32768), or NULL
 * for anything else. The caller frees *out. Enough for the test clips, not a general reader. */
static float *read_wav_16(const char *path, size_t *out_frame_count, int *out_channel_count,
                          int *out_sample_rate_hz) {
    unsigned char header[12];
    unsigned char chunk[8];
    unsigned char format[16];
    int has_format = 0;
    float *samples = NULL;
    FILE *file = fopen(path, "rb");
    if (file == NULL) return NULL;
    if (fread(header, 1, 12, file) != 12 || memcmp(header, "RIFF", 4) != 0 || memcmp(header + 8, "WAVE", 4) != 0) {
        fclose(file);
        return NULL;
    }
    while (samples == NULL && fread(chunk, 1, 8, file) == 8) {
        const unsigned long size = (unsigned long)chunk[4] | (unsigned long)chunk[5] << 8 |
                                   (unsigned long)chunk[6] << 16 | (unsigned long)chunk[7] << 24;
        if (memcmp(chunk, "fmt ", 4) == 0 && size >= 16) {
            if (fread(format, 1, 16, file) != 16 || fseek(file, (long)(size - 16 + (size & 1)), SEEK_CUR) != 0) break;
            has_format = format[0] == 1 && format[1] == 0 && format[14] == 16 && format[15] == 0;
            *out_channel_count = format[2] | format[3] << 8;
            *out_sample_rate_hz = (int)((unsigned long)format[4] | (unsigned long)format[5] << 8 |
                                        (unsigned long)format[6] << 16 | (unsigned long)format[7] << 24);
        } else if (memcmp(chunk, "data", 4) == 0 && has_format && *out_channel_count > 0) {
            const size_t count = size / 2;
            size_t k;
            unsigned char *bytes = malloc(size);
            samples = malloc(count * sizeof *samples);
            if (bytes == NULL || samples == NULL || fread(bytes, 1, size, file) != size) {
                free(bytes);
                free(samples);
                samples = NULL;
                break;
            }
            for (k = 0; k < count; ++k) {
                const int16_t value = (int16_t)(uint16_t)(bytes[2 * k] | bytes[2 * k + 1] << 8);
                samples[k] = (float)value / 32768.0f;
            }
            free(bytes);
            *out_frame_count = count / (size_t)*out_channel_count;
        } else if (fseek(file, (long)(size + (size & 1)), SEEK_CUR) != 0) {
            break;
        }
    }
    fclose(file);
    return samples;
}

/* Every syllable inside the audio, ordered, each ending after it starts and no later than the next
 * one starts; the sentence spans its syllables. */
static int check_well_formed(const tf_timeline *timeline) {
    int failures = 0;
    size_t count = 0;
    size_t k;
    double duration_s = 0.0;
    double sentence_start_s = -1.0;
    double sentence_end_s = -1.0;
    double previous_end_s = 0.0;
    double first_start_s = 0.0;
    double last_end_s = 0.0;
    CHECK_OK(tf_timeline_duration_s(timeline, &duration_s));
    CHECK(duration_s > kClipDurationS - 0.01 && duration_s < kClipDurationS + 0.01);
    CHECK_OK(tf_timeline_sentence_count(timeline, &count));
    CHECK(count == 1);
    CHECK_OK(tf_timeline_sentence(timeline, 0, NULL, &sentence_start_s, &sentence_end_s));
    CHECK_OK(tf_timeline_syllable_count(timeline, &count));
    CHECK(count == kClipSyllables);
    for (k = 0; k < count; ++k) {
        double start_s = -1.0;
        double end_s = -1.0;
        size_t sentence_index = 99;
        CHECK_OK(tf_timeline_syllable_times(timeline, k, &start_s, &end_s, NULL, NULL));
        CHECK_OK(tf_timeline_syllable(timeline, k, NULL, NULL, &sentence_index));
        CHECK(sentence_index == 0);
        CHECK(start_s >= previous_end_s - 1e-9);
        CHECK(end_s > start_s);
        CHECK(end_s <= duration_s);
        if (k == 0) first_start_s = start_s;
        previous_end_s = end_s;
        last_end_s = end_s;
    }
    CHECK(sentence_start_s == first_start_s);
    CHECK(sentence_end_s == last_end_s);
    return failures;
}

/* Whether two timelines give every syllable the same times, bit for bit. */
static int same_syllable_times(const tf_timeline *a, const tf_timeline *b) {
    size_t count_a = 0;
    size_t count_b = 0;
    size_t k;
    if (tf_timeline_syllable_count(a, &count_a) != TF_OK || tf_timeline_syllable_count(b, &count_b) != TF_OK ||
        count_a != count_b) {
        return 0;
    }
    for (k = 0; k < count_a; ++k) {
        double start_a = 0.0, end_a = 0.0, final_a = 0.0, start_b = 0.0, end_b = 0.0, final_b = 0.0;
        int has_final_a = 0, has_final_b = 0;
        tf_timeline_syllable_times(a, k, &start_a, &end_a, &has_final_a, &final_a);
        tf_timeline_syllable_times(b, k, &start_b, &end_b, &has_final_b, &final_b);
        if (start_a != start_b || end_a != end_b || has_final_a != has_final_b || final_a != final_b) return 0;
    }
    return 1;
}

/* What the progress callback saw; cancel_after_calls > 0 makes it cancel on that call. */
typedef struct progress_log {
    int calls;
    int cancel_after_calls;
    int is_decreasing;
    int has_unknown_stage;
    double first_fraction;
    double last_fraction;
} progress_log;

static int log_progress(double fraction, const char *stage, void *user_data) {
    progress_log *log = user_data;
    if (log->calls == 0) log->first_fraction = fraction;
    else if (fraction < log->last_fraction) log->is_decreasing = 1;
    if (strcmp(stage, "reading") != 0 && strcmp(stage, "sentences") != 0 && strcmp(stage, "syllables") != 0) {
        log->has_unknown_stage = 1;
    }
    log->last_fraction = fraction;
    ++log->calls;
    return log->cancel_after_calls > 0 && log->calls >= log->cancel_after_calls;
}

static tf_timeline *clip_transcript(void) {
    tf_timeline *transcript = NULL;
    return tf_load_transcript(kTranscriptPath, &transcript) == TF_OK ? transcript : NULL;
}

static int test_file_and_its_samples_align_alike(void) {
    int failures = 0;
    tf_timeline *transcript = clip_transcript();
    tf_timeline *from_file = NULL;
    tf_timeline *from_samples = NULL;
    size_t frame_count = 0;
    int channel_count = 0;
    int sample_rate_hz = 0;
    float *samples = read_wav_16(kClipPath, &frame_count, &channel_count, &sample_rate_hz);
    CHECK(transcript != NULL);
    CHECK(samples != NULL && channel_count == 1 && sample_rate_hz == 16000);
    CHECK_OK(tf_align_file(kClipPath, transcript, NULL, NULL, NULL, &from_file));
    CHECK(from_file != NULL);
    if (from_file != NULL) failures += check_well_formed(from_file);
    CHECK_OK(tf_align_samples(samples, frame_count, channel_count, sample_rate_hz, transcript, NULL, NULL, NULL,
                              &from_samples));
    CHECK(from_samples != NULL);
    if (from_file != NULL && from_samples != NULL) CHECK(same_syllable_times(from_file, from_samples));
    if (from_file != NULL) {
        /* A clean clip: every syllable is where it should be, and none comes out doubtful. */
        size_t count = 0;
        CHECK_OK(tf_timeline_syllable_count(from_file, &count));
        for (size_t i = 0; i < count; ++i) {
            double confidence = 0.0;
            CHECK_OK(tf_timeline_syllable_confidence(from_file, i, &confidence, NULL));
            CHECK(confidence >= TF_LOW_ALIGNMENT_CONFIDENCE && confidence <= 1.0);
        }
    }
    tf_timeline_destroy(from_samples);
    tf_timeline_destroy(from_file);
    tf_timeline_destroy(transcript);
    free(samples);
    return failures;
}

static int test_progress_rises_and_a_non_zero_return_cancels(void) {
    int failures = 0;
    tf_timeline *transcript = clip_transcript();
    tf_timeline *aligned = NULL;
    tf_timeline *const untouched = (tf_timeline *)&failures; /* never dereferenced */
    progress_log log = {0, 0, 0, 0, -1.0, -1.0};
    progress_log cancelling = {0, 3, 0, 0, -1.0, -1.0};
    CHECK_OK(tf_align_file(kClipPath, transcript, NULL, log_progress, &log, &aligned));
    CHECK(log.calls >= 5);
    CHECK(log.first_fraction == 0.0);
    CHECK(log.last_fraction == 1.0);
    CHECK(log.is_decreasing == 0);
    CHECK(log.has_unknown_stage == 0);
    tf_timeline_destroy(aligned);

    aligned = untouched;
    CHECK_FAILS_WITH(tf_align_file(kClipPath, transcript, NULL, log_progress, &cancelling, &aligned),
                     TF_ERR_CANCELLED, "cancelled");
    CHECK(cancelling.calls == 3);
    CHECK(aligned == untouched);
    tf_timeline_destroy(transcript);
    return failures;
}

static int test_options_are_checked_and_reach_the_aligner(void) {
    int failures = 0;
    tf_align_options *options = NULL;
    tf_timeline *transcript = NULL;
    tf_timeline *aligned = NULL;
    size_t count = 0;
    double start_s = 0.0;
    CHECK_OK(tf_align_options_create(&options));
    CHECK_FAILS_WITH(tf_align_options_set_c1(options, 0.3), TF_ERR_INVALID_ARGUMENT, "c1");
    CHECK_FAILS_WITH(tf_align_options_set_c2(options, 2.0), TF_ERR_INVALID_ARGUMENT, "c2");
    CHECK_FAILS_WITH(tf_align_options_set_first_pause(options, 2.0, 1.0), TF_ERR_INVALID_ARGUMENT, "first_pause");
    CHECK_FAILS_WITH(tf_align_options_set_sentence_cut(options, TF_SENTENCE_CUT_FIRST_PAUSE),
                     TF_ERR_INVALID_ARGUMENT, "first_pause");
    CHECK_FAILS_WITH(tf_align_options_set_sentence_cut(options, (tf_sentence_cut_mode)7), TF_ERR_INVALID_ARGUMENT,
                     "sentence_cut");
    CHECK_OK(tf_align_options_set_c1(options, 0.9));
    CHECK_OK(tf_align_options_set_c2(options, 1.4));
    CHECK_OK(tf_align_options_set_sentence_cut(options, TF_SENTENCE_CUT_AUTOMATIC));

    /* two_sentences: 今天下午有雨。我们明天再去吧。 with the pause between them at 1.69-2.59 s. */
    CHECK_OK(tf_align_options_set_first_pause(options, 1.8, 2.4));
    CHECK_OK(tf_load_transcript(CLIP_DIR "two_sentences.txt", &transcript));
    CHECK_OK(tf_align_file(CLIP_DIR "two_sentences.wav", transcript, options, NULL, NULL, &aligned));
    CHECK_OK(tf_timeline_sentence_count(aligned, &count));
    CHECK(count == 2);
    CHECK_OK(tf_timeline_sentence(aligned, 1, NULL, &start_s, NULL));
    CHECK(start_s > 2.4 && start_s < 2.7);
    tf_timeline_destroy(aligned);
    aligned = NULL;

    /* A pause inside the first sentence makes Algorithm 3.1 cut where no sentence ends. */
    CHECK_OK(tf_align_options_set_first_pause(options, 0.9, 0.92));
    CHECK(tf_align_file(CLIP_DIR "two_sentences.wav", transcript, options, NULL, NULL, &aligned) ==
          TF_ERR_ALIGNMENT);
    CHECK(aligned == NULL);
    CHECK_FAILS_WITH(tf_align_options_set_c1(NULL, 0.9), TF_ERR_INVALID_ARGUMENT, "options");
    CHECK_FAILS_WITH(tf_align_options_create(NULL), TF_ERR_INVALID_ARGUMENT, "out");
    tf_align_options_destroy(options);
    tf_align_options_destroy(NULL);
    tf_timeline_destroy(transcript);
    return failures;
}

static int test_errors_name_the_file_the_sentence_and_the_argument(void) {
    int failures = 0;
    tf_timeline *transcript = clip_transcript();
    tf_timeline *extra = NULL;
    tf_timeline *aligned = NULL;
    const float silence[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    /* 小朋友們在公園裡放風箏。今天下午有雨。: one sentence more than the clip speaks. */
    const char *extra_text = "\xe5\xb0\x8f\xe6\x9c\x8b\xe5\x8f\x8b\xe5\x80\x91\xe5\x9c\xa8\xe5\x85\xac\xe5\x9c\x92"
                             "\xe8\xa3\xa1\xe6\x94\xbe\xe9\xa2\xa8\xe7\xae\x8f\xe3\x80\x82\xe4\xbb\x8a\xe5\xa4\xa9"
                             "\xe4\xb8\x8b\xe5\x8d\x88\xe6\x9c\x89\xe9\x9b\xa8\xe3\x80\x82";
    CHECK_FAILS_WITH(tf_align_file("/no/such/dir/speech.wav", transcript, NULL, NULL, NULL, &aligned), TF_ERR_FILE,
                     "/no/such/dir/speech.wav");
    CHECK(aligned == NULL);

    CHECK_OK(tf_read_transcript(extra_text, strlen(extra_text), "extra.txt", &extra));
    CHECK_FAILS_WITH(tf_align_file(kClipPath, extra, NULL, NULL, NULL, &aligned), TF_ERR_ALIGNMENT, kClipPath);
    CHECK(strstr(tf_last_error_message(), "sentence") != NULL);
    CHECK(aligned == NULL);

    CHECK_FAILS_WITH(tf_align_file(NULL, transcript, NULL, NULL, NULL, &aligned), TF_ERR_INVALID_ARGUMENT,
                     "audio_path");
    CHECK_FAILS_WITH(tf_align_file(kClipPath, NULL, NULL, NULL, NULL, &aligned), TF_ERR_INVALID_ARGUMENT,
                     "transcript");
    CHECK_FAILS_WITH(tf_align_file(kClipPath, transcript, NULL, NULL, NULL, NULL), TF_ERR_INVALID_ARGUMENT, "out");
    CHECK_FAILS_WITH(tf_align_samples(NULL, 4, 1, 16000, transcript, NULL, NULL, NULL, &aligned),
                     TF_ERR_INVALID_ARGUMENT, "samples");
    CHECK_FAILS_WITH(tf_align_samples(silence, 0, 1, 16000, transcript, NULL, NULL, NULL, &aligned),
                     TF_ERR_INVALID_ARGUMENT, "frame_count");
    CHECK_FAILS_WITH(tf_align_samples(silence, 4, 0, 16000, transcript, NULL, NULL, NULL, &aligned),
                     TF_ERR_INVALID_ARGUMENT, "channel_count");
    CHECK_FAILS_WITH(tf_align_samples(silence, 4, 1, 100, transcript, NULL, NULL, NULL, &aligned),
                     TF_ERR_INVALID_ARGUMENT, "sample_rate_hz");
    CHECK_FAILS_WITH(tf_align_samples(silence, 4, 1, 16000, NULL, NULL, NULL, NULL, &aligned),
                     TF_ERR_INVALID_ARGUMENT, "transcript");
    CHECK(aligned == NULL);
    tf_timeline_destroy(extra);
    tf_timeline_destroy(transcript);
    return failures;
}

static int test_the_alignment_plot_is_an_svg_of_the_clip(void) {
    int failures = 0;
    tf_timeline *transcript = clip_transcript();
    tf_timeline *aligned = NULL;
    char *svg = NULL;
    size_t length = 0;
    CHECK_OK(tf_align_file(kClipPath, transcript, NULL, NULL, NULL, &aligned));
    CHECK_OK(tf_alignment_plot_svg(kClipPath, aligned, &svg, &length));
    CHECK(svg != NULL && strncmp(svg, "<svg ", 5) == 0 && strlen(svg) == length);
    CHECK(svg != NULL && strstr(svg, "放 fang4") != NULL);
    tf_free(svg);
    svg = NULL;
    CHECK_FAILS_WITH(tf_alignment_plot_svg("no_such_speech.wav", aligned, &svg, NULL), TF_ERR_FILE,
                     "no_such_speech.wav");
    CHECK(svg == NULL);
    CHECK_FAILS_WITH(tf_write_alignment_plot_svg(NULL, kClipPath, aligned), TF_ERR_INVALID_ARGUMENT, "svg_path");
    tf_timeline_destroy(aligned);
    tf_timeline_destroy(transcript);
    return failures;
}

/* tf_align_options_set_check: a wrong text of as many syllables is refused by default, a warning of
 * the timeline with TF_CHECK_WARN, and nothing at all with TF_CHECK_OFF. */
static int test_check_modes_refuse_warn_or_skip(void) {
    static const char wrong_text[] = "我昨天在超市买了苹果和。";
    int failures = 0;
    tf_timeline *wrong = NULL;
    tf_timeline *aligned = NULL;
    tf_align_options *options = NULL;
    size_t count = 0;
    const char *warning = NULL;
    CHECK_OK(tf_read_transcript(wrong_text, strlen(wrong_text), "wrong.txt", &wrong));
    CHECK_OK(tf_align_options_create(&options));
    CHECK_FAILS_WITH(tf_align_file(kClipPath, wrong, options, NULL, NULL, &aligned), TF_ERR_ALIGNMENT,
                     "is it another sentence, or are two sentences swapped?");
    CHECK(aligned == NULL);

    CHECK_OK(tf_align_options_set_check(options, TF_CHECK_WARN));
    CHECK_OK(tf_align_file(kClipPath, wrong, options, NULL, NULL, &aligned));
    CHECK_OK(tf_timeline_warning_count(aligned, &count));
    CHECK(count >= 1);
    if (count >= 1) {
        CHECK_OK(tf_timeline_warning(aligned, count - 1, &warning));
        CHECK(strstr(warning, "the transcript may not match the audio") == warning);
        CHECK(strstr(warning, "sentence 1 (0.") != NULL);
    }
    tf_timeline_destroy(aligned);
    aligned = NULL;

    CHECK_OK(tf_align_options_set_check(options, TF_CHECK_OFF));
    CHECK_OK(tf_align_file(kClipPath, wrong, options, NULL, NULL, &aligned));
    CHECK_OK(tf_timeline_warning_count(aligned, &count));
    CHECK(count == 0);
    tf_timeline_destroy(aligned);

    CHECK_FAILS_WITH(tf_align_options_set_check(options, (tf_check_mode)9), TF_ERR_INVALID_ARGUMENT, "check");
    CHECK_FAILS_WITH(tf_align_options_set_check(NULL, TF_CHECK_WARN), TF_ERR_INVALID_ARGUMENT, "options");
    tf_align_options_destroy(options);
    tf_timeline_destroy(wrong);
    return failures;
}

/* Lenient alignment (issue #13): the clip says 公园, which the transcript lacks; the stretch is
 * reported with its time and the syllable after it, and a right text has none. */
static int test_lenient_reports_speech_the_transcript_lacks(void) {
    static const char text[] = "小朋友们在里放风筝。";
    int failures = 0;
    tf_timeline *transcript = NULL;
    tf_timeline *aligned = NULL;
    tf_align_options *options = NULL;
    size_t count = 0, first = 0, syllables = 0;
    double start_s = 0.0, end_s = 0.0;
    const char *expected = NULL;
    CHECK_OK(tf_read_transcript(text, strlen(text), "lenient.txt", &transcript));
    CHECK_OK(tf_align_options_create(&options));
    CHECK_OK(tf_align_options_set_lenient(options, 1));
    CHECK_OK(tf_align_file(CLIP_DIR "lenient_espeak.flac", transcript, options, NULL, NULL, &aligned));
    CHECK_OK(tf_timeline_mismatch_count(aligned, &count));
    CHECK(count == 1);
    if (count == 1) {
        CHECK_OK(tf_timeline_mismatch(aligned, 0, &start_s, &end_s, &first, &syllables, &expected));
        CHECK(first == 5 && syllables == 0);
        CHECK(strcmp(expected, "") == 0);
        CHECK(start_s > 1.3 && start_s < 1.5 && end_s > 1.8 && end_s < 2.0);
        CHECK_OK(tf_timeline_mismatch(aligned, 0, NULL, NULL, NULL, NULL, NULL));
        /* Its loudness: a value 0..1 every 20 ms over the stretch, loud somewhere in it. */
        {
            const double *values = NULL;
            size_t value_count = 0, v;
            double step_s = 0.0, loudest = 0.0;
            CHECK_OK(tf_timeline_mismatch_loudness(aligned, 0, &values, &value_count, &step_s));
            CHECK(step_s == 0.02);
            CHECK(values != NULL && value_count >= (size_t)((end_s - start_s) / step_s));
            for (v = 0; values != NULL && v < value_count; ++v) {
                CHECK(values[v] >= 0.0 && values[v] <= 1.0);
                if (values[v] > loudest) loudest = values[v];
            }
            CHECK(loudest > 0.5);
            CHECK_OK(tf_timeline_mismatch_loudness(aligned, 0, NULL, NULL, NULL));
        }
    }
    CHECK_FAILS_WITH(tf_timeline_mismatch(aligned, 1, NULL, NULL, NULL, NULL, NULL), TF_ERR_INVALID_ARGUMENT, "index");
    CHECK_FAILS_WITH(tf_timeline_mismatch_loudness(aligned, 1, NULL, NULL, NULL), TF_ERR_INVALID_ARGUMENT, "index");
    CHECK_FAILS_WITH(tf_timeline_mismatch_loudness(NULL, 0, NULL, NULL, NULL), TF_ERR_INVALID_ARGUMENT, "timeline");
    tf_timeline_destroy(aligned);
    aligned = NULL;
    tf_timeline_destroy(transcript);

    transcript = clip_transcript();
    CHECK_OK(tf_align_file(kClipPath, transcript, options, NULL, NULL, &aligned));
    CHECK_OK(tf_timeline_mismatch_count(aligned, &count));
    CHECK(count == 0);
    tf_timeline_destroy(aligned);
    tf_timeline_destroy(transcript);
    CHECK_FAILS_WITH(tf_align_options_set_lenient(NULL, 1), TF_ERR_INVALID_ARGUMENT, "options");
    CHECK_FAILS_WITH(tf_timeline_mismatch_count(NULL, &count), TF_ERR_INVALID_ARGUMENT, "timeline");
    tf_align_options_destroy(options);
    return failures;
}

/* A subtitle cue pins the aligner (tf_time_transcript, issue #15): a cue narrower than the speech
 * keeps every syllable inside it. */
static int test_a_subtitle_cue_pins_the_syllables(void) {
    int failures = 0;
    tf_timeline *transcript = clip_transcript();
    tf_timeline *timeline = NULL;
    const char *cue_path = TF_TEST_OUTPUT_DIR "/one_sentence_cue.srt";
    FILE *file = fopen(cue_path, "wb");
    size_t count = 0;
    size_t k;
    CHECK(transcript != NULL && file != NULL);
    if (transcript == NULL || file == NULL) return failures;
    /* 小朋友們在公園裡放風箏。, spoken 0.30-2.79 s, cued 0.60-2.50 s. */
    fputs("1\n00:00:00,600 --> 00:00:02,500\n"
          "\xe5\xb0\x8f\xe6\x9c\x8b\xe5\x8f\x8b\xe5\x80\x91\xe5\x9c\xa8\xe5\x85\xac\xe5\x9c\x92\xe8\xa3\xa1"
          "\xe6\x94\xbe\xe9\xa2\xa8\xe7\xae\x8f\xe3\x80\x82\n",
          file);
    fclose(file);
    CHECK_OK(tf_time_transcript(cue_path, kClipPath, transcript, NULL, &timeline));
    CHECK_OK(tf_timeline_syllable_count(timeline, &count));
    CHECK(count == kClipSyllables);
    for (k = 0; k < count; ++k) {
        double start_s = 0.0;
        double end_s = 0.0;
        CHECK_OK(tf_timeline_syllable_times(timeline, k, &start_s, &end_s, NULL, NULL));
        CHECK(start_s >= 0.6 - 1e-9 && end_s <= 2.5 + 1e-9 && start_s < end_s);
    }
    tf_timeline_destroy(timeline);
    tf_timeline_destroy(transcript);
    return failures;
}

/* The cue-pinned aligner takes options (tf_time_transcript_with_options): lenient, a word the cue
 * and transcript lack is reported; a words JSON, which times every syllable, refuses lenient. */
static int test_a_cue_pinned_alignment_takes_lenient_options(void) {
    static const char text[] = "小朋友们在里放风筝。";
    int failures = 0;
    tf_timeline *transcript = NULL;
    tf_timeline *timeline = NULL;
    tf_align_options *options = NULL;
    const char *cue_path = TF_TEST_OUTPUT_DIR "/lenient_cue.srt";
    const char *words_path = TF_TEST_OUTPUT_DIR "/lenient_words.json";
    FILE *file = fopen(cue_path, "wb");
    size_t count = 0;
    CHECK(file != NULL);
    if (file == NULL) return failures;
    fputs("1\n00:00:00,200 --> 00:00:03,100\n小朋友们在里放风筝。\n", file);
    fclose(file);
    file = fopen(words_path, "wb");
    CHECK(file != NULL);
    if (file == NULL) return failures;
    fputs("[{\"text\": \"小朋友们在里放风筝\", \"start\": 0.3, \"end\": 2.9}]", file);
    fclose(file);
    CHECK_OK(tf_read_transcript(text, strlen(text), "lenient.txt", &transcript));
    CHECK_OK(tf_align_options_create(&options));
    CHECK_OK(tf_align_options_set_lenient(options, 1));
    CHECK_OK(tf_time_transcript_with_options(cue_path, CLIP_DIR "lenient_espeak.flac", transcript, NULL, options, NULL,
                                             NULL, &timeline));
    CHECK_OK(tf_timeline_mismatch_count(timeline, &count));
    CHECK(count == 1);
    tf_timeline_destroy(timeline);
    timeline = NULL;
    CHECK_FAILS_WITH(tf_time_transcript_with_options(words_path, CLIP_DIR "lenient_espeak.flac", transcript, NULL,
                                                     options, NULL, NULL, &timeline),
                     TF_ERR_INVALID_ARGUMENT, "times every syllable itself");
    CHECK(timeline == NULL);
    /* NULL options: the defaults, as tf_time_transcript. */
    CHECK_OK(tf_time_transcript_with_options(words_path, CLIP_DIR "lenient_espeak.flac", transcript, NULL, NULL, NULL,
                                             NULL, &timeline));
    tf_timeline_destroy(timeline);
    tf_timeline_destroy(transcript);
    tf_align_options_destroy(options);
    return failures;
}

/* Writes `path` as a copy of `source` with `count` pseudo-random bytes a `share` of the way in (the
 * generator of tests/audio/damaged_audio_test.cpp), or, with `halve_data_size`, with its WAV data
 * size halved; 0 on failure. */
static int write_damaged_copy(const char *source, const char *path, double share, size_t count, int halve_data_size) {
    unsigned char *bytes = NULL;
    long size = 0;
    size_t at;
    size_t k;
    uint32_t seed = 3;
    int written = 0;
    FILE *in = fopen(source, "rb");
    FILE *out = NULL;
    if (in == NULL) return 0;
    if (fseek(in, 0, SEEK_END) == 0 && (size = ftell(in)) > 0 && fseek(in, 0, SEEK_SET) == 0)
        bytes = malloc((size_t)size);
    if (bytes != NULL && fread(bytes, 1, (size_t)size, in) == (size_t)size) {
        at = (size_t)((double)size * share);
        for (k = 0; k < count && at + k < (size_t)size; ++k) {
            seed = seed * 1664525u + 1013904223u;
            bytes[at + k] = (unsigned char)(seed >> 24);
        }
        if (halve_data_size) {
            for (at = 12; at + 8 <= (size_t)size && memcmp(bytes + at, "data", 4) != 0; ++at) continue;
            if (at + 8 <= (size_t)size) {
                uint32_t data_size = (uint32_t)bytes[at + 4] | (uint32_t)bytes[at + 5] << 8 |
                                     (uint32_t)bytes[at + 6] << 16 | (uint32_t)bytes[at + 7] << 24;
                data_size = (data_size / 2) & ~3u;
                for (k = 0; k < 4; ++k) bytes[at + 4 + k] = (unsigned char)(data_size >> (8 * k));
            }
        }
        out = fopen(path, "wb");
        written = out != NULL && fwrite(bytes, 1, (size_t)size, out) == (size_t)size;
        if (out != NULL && fclose(out) != 0) written = 0;
    }
    free(bytes);
    fclose(in);
    return written;
}

/* The count of `timeline`'s warnings that begin with `prefix` and contain `needle`. */
static size_t count_warnings(const tf_timeline *timeline, const char *prefix, const char *needle) {
    size_t count = 0;
    size_t found = 0;
    size_t k;
    const char *warning = NULL;
    if (tf_timeline_warning_count(timeline, &count) != TF_OK) return 0;
    for (k = 0; k < count; ++k)
        if (tf_timeline_warning(timeline, k, &warning) == TF_OK && strncmp(warning, prefix, strlen(prefix)) == 0 &&
            strstr(warning, needle) != NULL)
            ++found;
    return found;
}

/* Aligns `path` (a damaged copy that still aligns) and says whether it gave all `kClipSyllables` with one
 * warning "<path>: the file is damaged: ..." that contains `needle`. */
static int aligns_with_one_damage_warning(const char *path, const tf_timeline *transcript, const char *needle) {
    char prefix[512];
    tf_timeline *aligned = NULL;
    size_t count = 0;
    int ok;
    snprintf(prefix, sizeof prefix, "%s: the file is damaged: ", path);
    if (tf_align_file(path, transcript, NULL, NULL, NULL, &aligned) != TF_OK) {
        fprintf(stderr, "%s: %s\n", path, tf_last_error_message());
        return 0;
    }
    ok = tf_timeline_syllable_count(aligned, &count) == TF_OK && count == kClipSyllables &&
         count_warnings(aligned, prefix, needle) == 1;
    tf_timeline_destroy(aligned);
    return ok;
}

/* Bad input (issue #13): a damaged file aligns with a warning naming where its sound was lost, or is
 * refused saying so before what the aligner found; a stale WAV header is read whole and said. */
static int test_damage_and_a_stale_header_are_said(void) {
    static const char scratched_m4a[] = TF_TEST_OUTPUT_DIR "/scratched_phone.m4a";
    static const char scratched_mp4[] = TF_TEST_OUTPUT_DIR "/scratched_clip.mp4";
    static const char scratched_webm[] = TF_TEST_OUTPUT_DIR "/scratched_clip.webm";
    static const char scratched_opus[] = TF_TEST_OUTPUT_DIR "/scratched_voice.opus";
    static const char scratched_index_mp4[] = TF_TEST_OUTPUT_DIR "/scratched_index_clip.mp4";
    static const char stale_wav[] = TF_TEST_OUTPUT_DIR "/stale_header.wav";
    int failures = 0;
    tf_timeline *transcript = NULL;
    tf_timeline *aligned = NULL;
    size_t count = 0;
    CHECK_OK(tf_load_transcript(kTranscriptPath, &transcript));

    /* The scratch costs the AAC decoder 0.64 s of packets: read as silence, the rest keeps its time. */
    CHECK(write_damaged_copy(AUDIO_DIR "phone.m4a", scratched_m4a, 1.0 / 3.0, 2000, 0));
    CHECK(aligns_with_one_damage_warning(scratched_m4a, transcript, "s of its sound could not be decoded, at 1."));

    /* 0.7 s of 3.1 lost from a video's sound track: refused, the damage named before the text. */
    CHECK(write_damaged_copy(AUDIO_DIR "clip.mp4", scratched_mp4, 1.0 / 3.0, 2000, 0));
    CHECK_FAILS_WITH(tf_align_file(scratched_mp4, transcript, NULL, NULL, NULL, &aligned), TF_ERR_ALIGNMENT,
                     "scratched_clip.mp4: the file is damaged: 0.");
    CHECK(strstr(tf_last_error_message(), "s of its sound could not be decoded, at 0.") != NULL);
    CHECK(aligned == NULL);

    /* A WebM of one cluster scratched half way in: the demuxer skips the rest of the cluster, and the
     * sound up to the track's stated 3.098 s is named as lost. */
    CHECK(write_damaged_copy(AUDIO_DIR "clip.webm", scratched_webm, 0.5, 2000, 0));
    CHECK(aligns_with_one_damage_warning(scratched_webm, transcript,
                                         "s of its sound could not be decoded, at 1.373-3.098 s"));

    /* A scratch in an Ogg page's header (its segment table, 40 bytes into the page at byte 1920): the
     * page claims more bytes than the file holds; it was called cut. Its second is named as lost. */
    CHECK(write_damaged_copy(AUDIO_DIR "voice.opus", scratched_opus, 1960.5 / 5869.0, 2000, 0));
    CHECK_FAILS_WITH(tf_align_file(scratched_opus, transcript, NULL, NULL, NULL, &aligned), TF_ERR_ALIGNMENT,
                     "scratched_voice.opus: the file is damaged: 1 s of its sound could not be decoded, at 1.014-2.014 s");
    CHECK(aligned == NULL);

    /* 100 bytes scratched inside a video's index (moov, at the end of this file) hide its sound
     * track: called damaged there, not "a video without a sound track". */
    CHECK(write_damaged_copy(AUDIO_DIR "clip.mp4", scratched_index_mp4, 0.95, 100, 0));
    CHECK_FAILS_WITH(tf_align_file(scratched_index_mp4, transcript, NULL, NULL, NULL, &aligned), TF_ERR_PARSE,
                     "scratched_index_clip.mp4: the file is damaged: its index (the moov box, bytes 10710-12464, "
                     "which says where its sound and picture lie) breaks at byte 11834, and no sound track");
    CHECK(aligned == NULL);

    /* A recorder that stopped without bringing its header up to date: the data size states half. */
    CHECK(write_damaged_copy(kClipPath, stale_wav, 0.0, 0, 1));
    CHECK_OK(tf_align_file(stale_wav, transcript, NULL, NULL, NULL, &aligned));
    CHECK_OK(tf_timeline_syllable_count(aligned, &count));
    CHECK(count == kClipSyllables);
    CHECK(count_warnings(aligned, TF_TEST_OUTPUT_DIR "/stale_header.wav: its header states 1.5 s of sound, "
                                  "the file holds 3.1 s", "read to the end of the file") == 1);
    tf_timeline_destroy(aligned);
    tf_timeline_destroy(transcript);
    return failures;
}

int main(void) {
    int failures = 0;
    failures += test_a_subtitle_cue_pins_the_syllables();
    failures += test_a_cue_pinned_alignment_takes_lenient_options();
    failures += test_check_modes_refuse_warn_or_skip();
    failures += test_lenient_reports_speech_the_transcript_lacks();
    failures += test_the_alignment_plot_is_an_svg_of_the_clip();
    failures += test_file_and_its_samples_align_alike();
    failures += test_progress_rises_and_a_non_zero_return_cancels();
    failures += test_options_are_checked_and_reach_the_aligner();
    failures += test_errors_name_the_file_the_sentence_and_the_argument();
    failures += test_damage_and_a_stale_header_are_said();
    if (failures != 0) fprintf(stderr, "%d check(s) failed\n", failures);
    return failures == 0 ? 0 : 1;
}

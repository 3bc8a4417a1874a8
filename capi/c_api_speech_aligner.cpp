// tf_align_options, tf_align_file, tf_align_samples and the alignment plot: the C face of
// speech_aligner.hpp and alignment_plot.hpp.
#include <string>

#include "c_api_guard.hpp"
#include "c_api_handles.hpp"
#include "talkface/alignment_plot.hpp"
#include "talkface/speech_aligner.hpp"

// The C header spells the C++ threshold out as a number: they must not part.
static_assert(TF_LOW_ALIGNMENT_CONFIDENCE == talkface::kLowAlignmentConfidence, "TF_LOW_ALIGNMENT_CONFIDENCE");

using talkface::AlignOptions;
using talkface::CheckMode;
using talkface::InvalidArgument;
using talkface::SentenceCutMode;
using talkface::SpeechAligner;
using talkface::TextMismatch;
using talkface::capi::enum_value;
using talkface::capi::guard;
using talkface::capi::progress_for;
using talkface::capi::require_non_null;

namespace {

// Applies `change` to a copy of the options and keeps it only if SpeechAligner's constructor
// accepts it (else its InvalidArgument, naming the option, propagates): the ranges live in one
// place, and a tf_align_options never holds a value the aligner would refuse later.
template <typename Change>
void update(tf_align_options* options, Change&& change) {
    require_non_null(options, "options");
    AlignOptions candidate = options->options;
    change(candidate);
    static_cast<void>(SpeechAligner(candidate));
    options->options = candidate;
}

const TextMismatch& mismatch_at(const talkface::Timeline& timeline, size_t index) {
    if (index >= timeline.mismatches.size())
        throw InvalidArgument("index", "mismatch " + std::to_string(index) + " of " +
                                           std::to_string(timeline.mismatches.size()));
    return timeline.mismatches[index];
}

SpeechAligner aligner_for(const tf_align_options* options) {
    return SpeechAligner(options != nullptr ? options->options : AlignOptions{});
}


}  // namespace

extern "C" {

tf_status tf_align_options_create(tf_align_options** out) {
    return guard([&] {
        require_non_null(out, "out");
        *out = new tf_align_options{};
    });
}

void tf_align_options_destroy(tf_align_options* options) {
    delete options;
}

tf_status tf_align_options_set_sentence_cut(tf_align_options* options, tf_sentence_cut_mode mode) {
    return guard([&] {
        require_non_null(options, "options");
        const int value = enum_value(mode);
        if (value != TF_SENTENCE_CUT_AUTOMATIC && value != TF_SENTENCE_CUT_FIRST_PAUSE) {
            throw InvalidArgument("sentence_cut", "expected a tf_sentence_cut_mode (0..1), got " +
                                                      std::to_string(value));
        }
        update(options, [&](AlignOptions& o) { o.sentence_cut = static_cast<SentenceCutMode>(value); });
    });
}

tf_status tf_align_options_set_first_pause(tf_align_options* options, double start_s, double end_s) {
    return guard([&] {
        update(options, [&](AlignOptions& o) {
            o.sentence_cut = SentenceCutMode::first_pause;
            o.first_pause_start_s = start_s;
            o.first_pause_end_s = end_s;
        });
    });
}

tf_status tf_align_options_set_c1(tf_align_options* options, double c1) {
    return guard([&] { update(options, [&](AlignOptions& o) { o.c1 = c1; }); });
}

tf_status tf_align_options_set_c2(tf_align_options* options, double c2) {
    return guard([&] { update(options, [&](AlignOptions& o) { o.c2 = c2; }); });
}

tf_status tf_align_options_set_check(tf_align_options* options, tf_check_mode mode) {
    return guard([&] {
        require_non_null(options, "options");
        const int value = enum_value(mode);
        if (value != TF_CHECK_REFUSE && value != TF_CHECK_WARN && value != TF_CHECK_OFF)
            throw InvalidArgument("check", "expected a tf_check_mode (0..2), got " + std::to_string(value));
        update(options, [&](AlignOptions& o) { o.check = static_cast<CheckMode>(value); });
    });
}

tf_status tf_align_options_set_lenient(tf_align_options* options, int lenient) {
    return guard([&] {
        require_non_null(options, "options");
        update(options, [&](AlignOptions& o) { o.lenient = lenient != 0; });
    });
}

tf_status tf_timeline_mismatch_count(const tf_timeline* timeline, size_t* out_count) {
    return guard([&] {
        require_non_null(timeline, "timeline");
        require_non_null(out_count, "out_count");
        *out_count = timeline->timeline.mismatches.size();
    });
}

tf_status tf_timeline_mismatch(const tf_timeline* timeline, size_t index, double* out_start_s, double* out_end_s,
                               size_t* out_first_syllable, size_t* out_syllable_count, const char** out_expected_text) {
    return guard([&] {
        require_non_null(timeline, "timeline");
        const TextMismatch& mismatch = mismatch_at(timeline->timeline, index);
        if (out_start_s != nullptr) *out_start_s = mismatch.start_s;
        if (out_end_s != nullptr) *out_end_s = mismatch.end_s;
        if (out_first_syllable != nullptr) *out_first_syllable = mismatch.first_syllable;
        if (out_syllable_count != nullptr) *out_syllable_count = mismatch.syllable_count;
        if (out_expected_text != nullptr) *out_expected_text = mismatch.expected_text.c_str();
    });
}

tf_status tf_timeline_mismatch_loudness(const tf_timeline* timeline, size_t index, const double** out_values,
                                        size_t* out_count, double* out_step_s) {
    return guard([&] {
        require_non_null(timeline, "timeline");
        const TextMismatch& mismatch = mismatch_at(timeline->timeline, index);
        if (out_values != nullptr) *out_values = mismatch.loudness.empty() ? nullptr : mismatch.loudness.data();
        if (out_count != nullptr) *out_count = mismatch.loudness.size();
        if (out_step_s != nullptr) *out_step_s = talkface::kMismatchLoudnessStepS;
    });
}

tf_status tf_align_file(const char* audio_path, const tf_timeline* transcript, const tf_align_options* options,
                        tf_progress_fn progress, void* user_data, tf_timeline** out) {
    return guard([&] {
        require_non_null(audio_path, "audio_path");
        require_non_null(transcript, "transcript");
        require_non_null(out, "out");
        talkface::Timeline aligned =
            aligner_for(options).align_file(audio_path, transcript->timeline, progress_for(progress, user_data));
        *out = new tf_timeline{std::move(aligned)};
    });
}

tf_status tf_align_samples(const float* samples, size_t frame_count, int channel_count, int sample_rate_hz,
                           const tf_timeline* transcript, const tf_align_options* options, tf_progress_fn progress,
                           void* user_data, tf_timeline** out) {
    return guard([&] {
        require_non_null(samples, "samples");
        require_non_null(transcript, "transcript");
        require_non_null(out, "out");
        talkface::AudioView audio;
        audio.samples = samples;
        audio.frame_count = frame_count;
        audio.channel_count = channel_count;
        audio.sample_rate_hz = sample_rate_hz;
        talkface::Timeline aligned =
            aligner_for(options).align(audio, transcript->timeline, progress_for(progress, user_data));
        *out = new tf_timeline{std::move(aligned)};
    });
}

tf_status tf_alignment_plot_svg(const char* audio_path, const tf_timeline* timeline, char** out_svg, size_t* out_len) {
    return guard([&] {
        require_non_null(audio_path, "audio_path");
        require_non_null(timeline, "timeline");
        require_non_null(out_svg, "out_svg");
        talkface::capi::give_document(talkface::alignment_plot_svg(audio_path, timeline->timeline), out_svg, out_len);
    });
}

tf_status tf_write_alignment_plot_svg(const char* svg_path, const char* audio_path, const tf_timeline* timeline) {
    return guard([&] {
        require_non_null(svg_path, "svg_path");
        require_non_null(audio_path, "audio_path");
        require_non_null(timeline, "timeline");
        talkface::write_alignment_plot_svg(svg_path, audio_path, timeline->timeline);
    });
}

}  // extern "C"

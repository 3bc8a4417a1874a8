// tf_timeline, transcripts and syllable shapes: the C face of transcript.hpp, timeline.hpp,
// timeline_json.hpp and syllable_mouth_shapes() in lip_sync.hpp.
#include <charconv>
#include <string>
#include <string_view>

#include "c_api_guard.hpp"
#include "c_api_handles.hpp"
#include "talkface/lip_sync.hpp"
#include "talkface/timeline_json.hpp"
#include "talkface/transcript.hpp"

using talkface::InvalidArgument;
using talkface::Sentence;
using talkface::Syllable;
using talkface::Timeline;
using talkface::capi::guard;
using talkface::capi::require_non_null;

struct tf_transcript_options {
    talkface::TranscriptOptions options;
};

struct tf_timeline_json_options {
    talkface::TimelineJsonOptions options;
};

namespace {

const talkface::TranscriptOptions& options_or_defaults(const tf_transcript_options* options) {
    static const talkface::TranscriptOptions defaults;
    return options != nullptr ? options->options : defaults;
}

std::string source_or_default(const char* source_name) {
    return source_name != nullptr ? source_name : "<transcript>";
}

// items[index], const or not as `items` is.
template <typename Items>
auto& item_at(Items& items, size_t index, const char* what) {
    if (index >= items.size()) {
        throw InvalidArgument("index", std::string("expected a ") + what + " index below " +
                                           std::to_string(items.size()) + ", got " + std::to_string(index));
    }
    return items[index];
}

Syllable& syllable_at(tf_timeline* timeline, size_t index) {
    return item_at(timeline->timeline.syllables, index, "syllable");
}

// For messages: the shortest text that reads back as the same double, whatever the C locale.
std::string number_text(double value) {
    char buffer[32];
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
    return std::string(buffer, result.ptr);
}

}  // namespace

extern "C" {

tf_status tf_read_transcript(const char* text, size_t length, const char* source_name, tf_timeline** out) {
    return tf_read_transcript_with_options(text, length, source_name, nullptr, out);
}

tf_status tf_read_transcript_with_options(const char* text, size_t length, const char* source_name,
                                          const tf_transcript_options* options, tf_timeline** out) {
    return guard([&] {
        require_non_null(text, "text");
        require_non_null(out, "out");
        *out = new tf_timeline{talkface::read_transcript(
            std::string_view(text, length), options_or_defaults(options), source_or_default(source_name))};
    });
}

tf_status tf_load_transcript(const char* path, tf_timeline** out) {
    return tf_load_transcript_with_options(path, nullptr, out);
}

tf_status tf_load_transcript_with(const char* path, const char* encoding, int keep_directions,
                                  tf_timeline** out) {
    return guard([&] {
        require_non_null(path, "path");
        require_non_null(out, "out");
        talkface::TranscriptOptions options;
        options.encoding = encoding != nullptr ? encoding : "";
        options.keep_directions = keep_directions != 0;
        *out = new tf_timeline{talkface::load_transcript(path, options)};
    });
}

tf_status tf_load_transcript_with_options(const char* path, const tf_transcript_options* options,
                                          tf_timeline** out) {
    return guard([&] {
        require_non_null(path, "path");
        require_non_null(out, "out");
        *out = new tf_timeline{talkface::load_transcript(path, options_or_defaults(options))};
    });
}

tf_status tf_transcript_options_create(tf_transcript_options** out) {
    return guard([&] {
        require_non_null(out, "out");
        *out = new tf_transcript_options{};
    });
}

void tf_transcript_options_destroy(tf_transcript_options* options) {
    delete options;
}

tf_status tf_transcript_options_set_read_pinyin(tf_transcript_options* options, int read_pinyin) {
    return guard([&] {
        require_non_null(options, "options");
        options->options.read_pinyin = read_pinyin != 0;
    });
}

tf_status tf_transcript_options_set_keep_directions(tf_transcript_options* options, int keep_directions) {
    return guard([&] {
        require_non_null(options, "options");
        options->options.keep_directions = keep_directions != 0;
    });
}

tf_status tf_transcript_options_set_encoding(tf_transcript_options* options, const char* encoding) {
    return guard([&] {
        require_non_null(options, "options");
        options->options.encoding = encoding != nullptr ? encoding : "";
    });
}

tf_status tf_timeline_create(tf_timeline** out) {
    return guard([&] {
        require_non_null(out, "out");
        *out = new tf_timeline{};
    });
}

void tf_timeline_destroy(tf_timeline* timeline) {
    delete timeline;
}

tf_status tf_timeline_add_sentence(tf_timeline* timeline, const char* text, double start_s, double end_s) {
    return guard([&] {
        require_non_null(timeline, "timeline");
        require_non_null(text, "text");
        timeline->timeline.sentences.push_back(Sentence{text, start_s, end_s});
    });
}

tf_status tf_timeline_add_syllable(tf_timeline* timeline, const char* text, const char* pinyin,
                                   size_t sentence_index, double start_s, double end_s) {
    return guard([&] {
        require_non_null(timeline, "timeline");
        require_non_null(text, "text");
        require_non_null(pinyin, "pinyin");
        const size_t sentence_count = timeline->timeline.sentences.size();
        if (sentence_index >= sentence_count) {
            throw InvalidArgument("sentence_index", "expected an index below " + std::to_string(sentence_count) +
                                                        " (the sentences added so far), got " +
                                                        std::to_string(sentence_index));
        }
        Syllable syllable;
        syllable.text = text;
        syllable.pinyin = pinyin;
        syllable.sentence = sentence_index;
        syllable.start_s = start_s;
        syllable.end_s = end_s;
        timeline->timeline.syllables.push_back(std::move(syllable));
    });
}

tf_status tf_timeline_set_syllable_final_start_s(tf_timeline* timeline, size_t index, double final_start_s) {
    return guard([&] {
        require_non_null(timeline, "timeline");
        syllable_at(timeline, index).final_start_s = final_start_s;
    });
}

tf_status tf_timeline_set_syllable_confidence(tf_timeline* timeline, size_t index, double confidence) {
    return guard([&] {
        require_non_null(timeline, "timeline");
        Syllable& syllable = syllable_at(timeline, index);
        if (!(confidence >= 0.0 && confidence <= 1.0)) {
            throw InvalidArgument("confidence", "expected 0..1, got " + number_text(confidence));
        }
        syllable.confidence = confidence;
    });
}

tf_status tf_timeline_set_syllable_pause_after(tf_timeline* timeline, size_t index, int pause_after) {
    return guard([&] {
        require_non_null(timeline, "timeline");
        syllable_at(timeline, index).pause_after = pause_after != 0;
    });
}

tf_status tf_timeline_set_sentence_starts_paragraph(tf_timeline* timeline, size_t index, int starts_paragraph) {
    return guard([&] {
        require_non_null(timeline, "timeline");
        item_at(timeline->timeline.sentences, index, "sentence").starts_paragraph = starts_paragraph != 0;
    });
}

tf_status tf_timeline_sentence_starts_paragraph(const tf_timeline* timeline, size_t index, int* out_starts_paragraph) {
    return guard([&] {
        require_non_null(timeline, "timeline");
        require_non_null(out_starts_paragraph, "out_starts_paragraph");
        *out_starts_paragraph = item_at(timeline->timeline.sentences, index, "sentence").starts_paragraph ? 1 : 0;
    });
}

tf_status tf_timeline_set_syllable_generic_speech(tf_timeline* timeline, size_t index, int generic_speech) {
    return guard([&] {
        require_non_null(timeline, "timeline");
        syllable_at(timeline, index).generic_speech = generic_speech != 0;
    });
}

tf_status tf_timeline_syllable_generic_speech(const tf_timeline* timeline, size_t index, int* out_generic_speech) {
    return guard([&] {
        require_non_null(timeline, "timeline");
        require_non_null(out_generic_speech, "out_generic_speech");
        *out_generic_speech = item_at(timeline->timeline.syllables, index, "syllable").generic_speech ? 1 : 0;
    });
}

tf_status tf_timeline_set_duration_s(tf_timeline* timeline, double duration_s) {
    return guard([&] {
        require_non_null(timeline, "timeline");
        timeline->timeline.duration_s = duration_s;
    });
}

tf_status tf_timeline_duration_s(const tf_timeline* timeline, double* out_duration_s) {
    return guard([&] {
        require_non_null(timeline, "timeline");
        require_non_null(out_duration_s, "out_duration_s");
        *out_duration_s = timeline->timeline.duration_s;
    });
}

tf_status tf_timeline_sentence_count(const tf_timeline* timeline, size_t* out_count) {
    return guard([&] {
        require_non_null(timeline, "timeline");
        require_non_null(out_count, "out_count");
        *out_count = timeline->timeline.sentences.size();
    });
}

tf_status tf_timeline_sentence(const tf_timeline* timeline, size_t index, const char** out_text,
                               double* out_start_s, double* out_end_s) {
    return guard([&] {
        require_non_null(timeline, "timeline");
        const Sentence& sentence = item_at(timeline->timeline.sentences, index, "sentence");
        if (out_text != nullptr) *out_text = sentence.text.c_str();
        if (out_start_s != nullptr) *out_start_s = sentence.start_s;
        if (out_end_s != nullptr) *out_end_s = sentence.end_s;
    });
}

tf_status tf_timeline_syllable_count(const tf_timeline* timeline, size_t* out_count) {
    return guard([&] {
        require_non_null(timeline, "timeline");
        require_non_null(out_count, "out_count");
        *out_count = timeline->timeline.syllables.size();
    });
}

tf_status tf_timeline_syllable(const tf_timeline* timeline, size_t index, const char** out_text,
                               const char** out_pinyin, size_t* out_sentence_index) {
    return guard([&] {
        require_non_null(timeline, "timeline");
        const Syllable& syllable = item_at(timeline->timeline.syllables, index, "syllable");
        if (out_text != nullptr) *out_text = syllable.text.c_str();
        if (out_pinyin != nullptr) *out_pinyin = syllable.pinyin.c_str();
        if (out_sentence_index != nullptr) *out_sentence_index = syllable.sentence;
    });
}

tf_status tf_timeline_syllable_times(const tf_timeline* timeline, size_t index, double* out_start_s,
                                     double* out_end_s, int* out_has_final_start, double* out_final_start_s) {
    return guard([&] {
        require_non_null(timeline, "timeline");
        const Syllable& syllable = item_at(timeline->timeline.syllables, index, "syllable");
        if (out_start_s != nullptr) *out_start_s = syllable.start_s;
        if (out_end_s != nullptr) *out_end_s = syllable.end_s;
        if (out_has_final_start != nullptr) *out_has_final_start = syllable.final_start_s ? 1 : 0;
        if (out_final_start_s != nullptr && syllable.final_start_s) *out_final_start_s = *syllable.final_start_s;
    });
}

tf_status tf_timeline_syllable_confidence(const tf_timeline* timeline, size_t index, double* out_confidence,
                                          int* out_pause_after) {
    return guard([&] {
        require_non_null(timeline, "timeline");
        const Syllable& syllable = item_at(timeline->timeline.syllables, index, "syllable");
        if (out_confidence != nullptr) *out_confidence = syllable.confidence;
        if (out_pause_after != nullptr) *out_pause_after = syllable.pause_after ? 1 : 0;
    });
}

tf_status tf_timeline_warning_count(const tf_timeline* timeline, size_t* out_count) {
    return guard([&] {
        require_non_null(timeline, "timeline");
        require_non_null(out_count, "out_count");
        *out_count = timeline->timeline.warnings.size();
    });
}

tf_status tf_timeline_warning(const tf_timeline* timeline, size_t index, const char** out_warning) {
    return guard([&] {
        require_non_null(timeline, "timeline");
        require_non_null(out_warning, "out_warning");
        *out_warning = item_at(timeline->timeline.warnings, index, "warning").c_str();
    });
}

tf_status tf_timeline_written_form_count(const tf_timeline* timeline, size_t* out_count) {
    return guard([&] {
        require_non_null(timeline, "timeline");
        require_non_null(out_count, "out_count");
        *out_count = timeline->timeline.written_forms.size();
    });
}

tf_status tf_timeline_written_form(const tf_timeline* timeline, size_t index, const char** out_text,
                                   size_t* out_first_syllable, size_t* out_syllable_count) {
    return guard([&] {
        require_non_null(timeline, "timeline");
        const auto& form = item_at(timeline->timeline.written_forms, index, "written form");
        if (out_text != nullptr) *out_text = form.text.c_str();
        if (out_first_syllable != nullptr) *out_first_syllable = form.first_syllable;
        if (out_syllable_count != nullptr) *out_syllable_count = form.syllable_count;
    });
}

tf_status tf_timeline_add_written_form(tf_timeline* timeline, const char* text, size_t first_syllable,
                                       size_t syllable_count) {
    return guard([&] {
        require_non_null(timeline, "timeline");
        require_non_null(text, "text");
        auto& timeline_value = timeline->timeline;
        if (*text == '\0') throw InvalidArgument("text", "expected the form as written, got an empty string");
        if (syllable_count == 0) throw InvalidArgument("syllable_count", "expected at least 1, got 0");
        const size_t syllables = timeline_value.syllables.size();
        if (first_syllable >= syllables || syllable_count > syllables - first_syllable) {
            throw InvalidArgument("first_syllable", "syllables " + std::to_string(first_syllable) + ".." +
                                                        std::to_string(first_syllable + syllable_count - 1) +
                                                        " are not all among the " + std::to_string(syllables) +
                                                        " syllables added so far");
        }
        if (!timeline_value.written_forms.empty()) {
            const auto& previous = timeline_value.written_forms.back();
            const size_t previous_end = previous.first_syllable + previous.syllable_count;
            if (first_syllable < previous_end) {
                throw InvalidArgument("first_syllable", "expected " + std::to_string(previous_end) +
                                                            " or more (forms come in order, apart), got " +
                                                            std::to_string(first_syllable));
            }
        }
        timeline_value.written_forms.push_back({text, first_syllable, syllable_count});
    });
}

tf_status tf_timeline_to_json(const tf_timeline* timeline, char** out_json, size_t* out_len) {
    return tf_timeline_to_json_with_options(timeline, nullptr, out_json, out_len);
}

tf_status tf_timeline_json_options_create(tf_timeline_json_options** out) {
    return guard([&] {
        require_non_null(out, "out");
        *out = new tf_timeline_json_options{};
    });
}

void tf_timeline_json_options_destroy(tf_timeline_json_options* options) {
    delete options;
}

tf_status tf_timeline_json_options_set_with_times(tf_timeline_json_options* options, int with_times) {
    return guard([&] {
        require_non_null(options, "options");
        options->options.with_times = with_times != 0;
    });
}

tf_status tf_timeline_to_json_with_options(const tf_timeline* timeline,
                                           const tf_timeline_json_options* options, char** out_json,
                                           size_t* out_len) {
    return guard([&] {
        require_non_null(timeline, "timeline");
        require_non_null(out_json, "out_json");
        static const talkface::TimelineJsonOptions defaults;
        talkface::capi::give_document(
            talkface::timeline_to_json(timeline->timeline, options != nullptr ? options->options : defaults),
            out_json, out_len);
    });
}

tf_status tf_timeline_from_json(const char* json, size_t length, const char* source_name, tf_timeline** out) {
    return guard([&] {
        require_non_null(json, "json");
        require_non_null(out, "out");
        *out = new tf_timeline{talkface::timeline_from_json(std::string_view(json, length),
                                                            source_name != nullptr ? source_name : "<timeline>")};
    });
}

tf_status tf_timeline_load_json(const char* path, tf_timeline** out) {
    return guard([&] {
        require_non_null(path, "path");
        require_non_null(out, "out");
        *out = new tf_timeline{talkface::load_timeline_json(path)};
    });
}

int tf_is_valid_pinyin(const char* syllable) {
    return syllable != nullptr && talkface::is_valid_pinyin(syllable) ? 1 : 0;
}

tf_status tf_syllable_mouth_shapes(const char* pinyin, tf_mouth_shape* out, size_t capacity,
                                   size_t* out_count) {
    return guard([&] {
        require_non_null(pinyin, "pinyin");
        require_non_null(out_count, "out_count");
        const std::vector<talkface::MouthShape> shapes = talkface::syllable_mouth_shapes(pinyin);
        if (out == nullptr && capacity == 0) {
            *out_count = shapes.size();
            return;
        }
        require_non_null(out, "out");
        if (capacity < shapes.size()) {
            throw InvalidArgument("capacity", "\"" + std::string(pinyin) + "\" has " +
                                                  std::to_string(shapes.size()) + " shapes, capacity is " +
                                                  std::to_string(capacity));
        }
        for (size_t k = 0; k < shapes.size(); ++k) out[k] = static_cast<tf_mouth_shape>(shapes[k]);
        *out_count = shapes.size();
    });
}

}  // extern "C"

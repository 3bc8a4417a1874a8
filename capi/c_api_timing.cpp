// Timing exports and imports in C: the C face of timing_formats.hpp.
#include <string>
#include <string_view>

#include "c_api_guard.hpp"
#include "c_api_handles.hpp"
#include "talkface/timing_formats.hpp"

using talkface::capi::guard;
using talkface::capi::require_non_null;

namespace {

talkface::ExportInput export_input(const tf_timeline* timeline, const tf_animation* animation, const char* audio_path) {
    require_non_null(timeline, "timeline");
    require_non_null(animation, "animation");
    talkface::ExportInput input;
    input.timeline = timeline->timeline;
    input.mouth_key_frames = animation->animation.mouth_key_frames;
    input.fps = animation->animation.fps;
    input.frames = animation->animation.frames;
    input.audio_path = audio_path != nullptr ? audio_path : "";
    return input;
}

std::string text_or(const char* text, const char* fallback) { return text != nullptr ? text : fallback; }

}  // namespace

extern "C" {

tf_status tf_export_to_string(const tf_timeline* timeline, const tf_animation* animation, const char* format,
                              const char* audio_path, char** out_document, size_t* out_len) {
    return guard([&] {
        require_non_null(format, "format");
        require_non_null(out_document, "out_document");
        talkface::capi::give_document(talkface::export_to_string(export_input(timeline, animation, audio_path), format),
                                      out_document, out_len);
    });
}

tf_status tf_export_to_file(const char* path, const tf_timeline* timeline, const tf_animation* animation,
                            const char* format, const char* audio_path) {
    return guard([&] {
        require_non_null(path, "path");
        talkface::export_to_file(path, export_input(timeline, animation, audio_path), text_or(format, ""));
    });
}

tf_status tf_read_timing_string(const char* text, size_t length, const char* format, const tf_timeline* transcript,
                                double duration_s, const char* source_name, tf_timeline** out) {
    return guard([&] {
        require_non_null(text, "text");
        require_non_null(format, "format");
        require_non_null(transcript, "transcript");
        require_non_null(out, "out");
        *out = new tf_timeline{talkface::read_timing_string(std::string_view(text, length), format,
                                                            transcript->timeline, duration_s,
                                                            text_or(source_name, "<timing>"))};
    });
}

tf_status tf_read_timing_file(const char* path, const tf_timeline* transcript, double duration_s, const char* format,
                              tf_timeline** out) {
    return guard([&] {
        require_non_null(path, "path");
        require_non_null(transcript, "transcript");
        require_non_null(out, "out");
        *out = new tf_timeline{talkface::read_timing_file(path, transcript->timeline, duration_s, text_or(format, ""))};
    });
}

tf_status tf_write_timing_string(const tf_timeline* timeline, const char* format, char** out_document,
                                 size_t* out_len) {
    return guard([&] {
        require_non_null(timeline, "timeline");
        require_non_null(format, "format");
        require_non_null(out_document, "out_document");
        talkface::capi::give_document(talkface::write_timing_string(timeline->timeline, format), out_document,
                                      out_len);
    });
}

tf_status tf_time_transcript(const char* timing_path, const char* audio_path, const tf_timeline* transcript,
                             const char* format, tf_timeline** out) {
    return guard([&] {
        require_non_null(timing_path, "timing_path");
        require_non_null(audio_path, "audio_path");
        require_non_null(transcript, "transcript");
        require_non_null(out, "out");
        *out = new tf_timeline{
            talkface::time_transcript(timing_path, audio_path, transcript->timeline, text_or(format, ""))};
    });
}

tf_status tf_time_transcript_with_options(const char* timing_path, const char* audio_path,
                                          const tf_timeline* transcript, const char* format,
                                          const tf_align_options* options, tf_progress_fn progress, void* user_data,
                                          tf_timeline** out) {
    return guard([&] {
        require_non_null(timing_path, "timing_path");
        require_non_null(audio_path, "audio_path");
        require_non_null(transcript, "transcript");
        require_non_null(out, "out");
        *out = new tf_timeline{talkface::time_transcript(
            timing_path, audio_path, transcript->timeline, options != nullptr ? options->options : talkface::AlignOptions{},
            text_or(format, ""), talkface::capi::progress_for(progress, user_data))};
    });
}

}  // extern "C"

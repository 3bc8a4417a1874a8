// tf_video_options and tf_video_writer: the C face of talkface::VideoWriter.

#include "c_api_guard.hpp"
#include "c_api_handles.hpp"
#include "talkface/face_video.hpp"
#include "talkface/video_writer.hpp"

using talkface::VideoOptions;
using talkface::VideoWriter;
using talkface::capi::enum_value;
using talkface::capi::guard;
using talkface::capi::progress_for;
using talkface::capi::require_non_null;

struct tf_video_options {
    VideoOptions options;
};

struct tf_video_writer {
    VideoWriter writer;
};

struct tf_video_look {
    talkface::FaceVideoOptions options;  // its `video` part is ignored: tf_video_options carries it
};

extern "C" {

tf_status tf_video_format_from_path(const char* path, tf_video_format* out_format) {
    return guard([&] {
        require_non_null(path, "path");
        require_non_null(out_format, "out_format");
        *out_format = static_cast<tf_video_format>(talkface::video_format_from_path(path));
    });
}

tf_status tf_video_options_create(tf_video_options** out) {
    return guard([&] {
        require_non_null(out, "out");
        *out = new tf_video_options{};
    });
}

void tf_video_options_destroy(tf_video_options* options) { delete options; }

tf_status tf_video_options_set_size(tf_video_options* options, int width_px, int height_px) {
    return guard([&] {
        require_non_null(options, "options");
        options->options.width_px = width_px;
        options->options.height_px = height_px;
    });
}

tf_status tf_video_options_set_fps(tf_video_options* options, double fps) {
    return guard([&] {
        require_non_null(options, "options");
        options->options.fps = fps;
    });
}

tf_status tf_video_options_set_crf(tf_video_options* options, int crf) {
    return guard([&] {
        require_non_null(options, "options");
        options->options.crf = crf;
    });
}

tf_status tf_video_options_set_transparent(tf_video_options* options, int transparent) {
    return guard([&] {
        require_non_null(options, "options");
        options->options.transparent = transparent != 0;
    });
}

tf_status tf_check_video_options(const char* path, const tf_video_options* options) {
    return guard([&] {
        require_non_null(path, "path");
        talkface::check_video_options(path, options != nullptr ? options->options : VideoOptions{});
    });
}

tf_status tf_video_writer_open(const char* path, const tf_video_options* options, tf_video_writer** out) {
    return guard([&] {
        require_non_null(path, "path");
        require_non_null(out, "out");
        *out = new tf_video_writer{VideoWriter(path, options != nullptr ? options->options : VideoOptions{})};
    });
}

void tf_video_writer_destroy(tf_video_writer* writer) { delete writer; }

tf_status tf_video_writer_add_audio(tf_video_writer* writer, const float* samples, size_t frame_count,
                                    int channel_count, int sample_rate_hz) {
    return guard([&] {
        require_non_null(writer, "writer");
        require_non_null(samples, "samples");
        writer->writer.add_audio({samples, frame_count, channel_count, sample_rate_hz});
    });
}

tf_status tf_video_writer_add_audio_file(tf_video_writer* writer, const char* audio_path) {
    return guard([&] {
        require_non_null(writer, "writer");
        require_non_null(audio_path, "audio_path");
        writer->writer.add_audio_file(audio_path);
    });
}

tf_status tf_video_writer_write_frame(tf_video_writer* writer, const uint8_t* rgba, size_t stride_bytes) {
    return guard([&] {
        require_non_null(writer, "writer");
        writer->writer.write_frame(rgba, stride_bytes);
    });
}

tf_status tf_video_writer_frame_count(const tf_video_writer* writer, size_t* out_count) {
    return guard([&] {
        require_non_null(writer, "writer");
        require_non_null(out_count, "out_count");
        *out_count = writer->writer.frame_count();
    });
}

tf_status tf_video_writer_finish(tf_video_writer* writer) {
    return guard([&] {
        require_non_null(writer, "writer");
        writer->writer.finish();
    });
}

tf_status tf_video_look_create(tf_video_look** out) {
    return guard([&] {
        require_non_null(out, "out");
        *out = new tf_video_look{};
    });
}

void tf_video_look_destroy(tf_video_look* look) { delete look; }

tf_status tf_video_look_set_layout(tf_video_look* look, tf_frame_layout layout) {
    return guard([&] {
        require_non_null(look, "look");
        const int value = enum_value(layout);
        if (value != TF_FRAME_LAYOUT_ANNOUNCER && value != TF_FRAME_LAYOUT_FACE) {
            throw talkface::InvalidArgument("layout", "expected TF_FRAME_LAYOUT_ANNOUNCER (0) or TF_FRAME_LAYOUT_FACE "
                                                      "(1), found " + std::to_string(value));
        }
        look->options.frame.layout = static_cast<talkface::FrameLayout>(value);
    });
}

tf_status tf_video_look_set_face_look(tf_video_look* look, tf_face_look face_look) {
    return guard([&] {
        require_non_null(look, "look");
        const int value = enum_value(face_look);
        if (value != TF_FACE_LOOK_OUTLINED && value != TF_FACE_LOOK_FLAT) {
            throw talkface::InvalidArgument("face_look", "expected TF_FACE_LOOK_OUTLINED (0) or TF_FACE_LOOK_FLAT (1), "
                                                         "found " + std::to_string(value));
        }
        look->options.frame.look = static_cast<talkface::FaceLook>(value);
    });
}

tf_status tf_video_look_set_clothes(tf_video_look* look, int draw_clothes, tf_rgb colour) {
    return guard([&] {
        require_non_null(look, "look");
        look->options.frame.draw_clothes = draw_clothes != 0;
        look->options.frame.clothes = talkface::capi::to_rgb(colour);
    });
}

tf_status tf_video_look_set_stroke_width_in_d(tf_video_look* look, double stroke_width_in_d) {
    return guard([&] {
        require_non_null(look, "look");
        look->options.frame.stroke_width_in_d = stroke_width_in_d;
    });
}

tf_status tf_video_look_set_background(tf_video_look* look, const tf_rgb* colour, const char* image_path) {
    return guard([&] {
        require_non_null(look, "look");
        look->options.frame.background = talkface::capi::to_optional_rgb(colour);
        look->options.background_image_path = image_path != nullptr ? image_path : "";
    });
}

tf_status tf_video_look_set_face_placement(tf_video_look* look, const double origin_xy[2], double d_px) {
    return guard([&] {
        require_non_null(look, "look");
        talkface::capi::set_face_placement(look->options.frame, origin_xy, d_px);
    });
}

tf_status tf_render_video(const char* path, const tf_face_model* face, const tf_animation* animation,
                          const char* audio_path, const tf_video_options* video, const tf_video_look* look,
                          tf_progress_fn progress, void* user_data) {
    return guard([&] {
        require_non_null(path, "path");
        require_non_null(face, "face");
        require_non_null(animation, "animation");
        talkface::FaceVideoOptions options = look != nullptr ? look->options : talkface::FaceVideoOptions{};
        options.video = video != nullptr ? video->options : VideoOptions{};
        talkface::render_video(path, face->model, animation->animation, audio_path != nullptr ? audio_path : "",
                               options, progress_for(progress, user_data));
    });
}

}  // extern "C"

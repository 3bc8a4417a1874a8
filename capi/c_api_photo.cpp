// tf_photo_*: the C face of talkface/face_from_photo.hpp (SPEC step 1, thesis 2.2).
#include <string>

#include "c_api_guard.hpp"
#include "c_api_handles.hpp"
#include "talkface/face_from_photo.hpp"
#include "talkface/talkface_photo.h"

using talkface::InvalidArgument;
using talkface::capi::guard;
using talkface::capi::new_face;
using talkface::capi::require_non_null;

struct tf_photo_options {
    talkface::PhotoOptions options;
};

struct tf_photo_result {
    talkface::PhotoFaceResult result;
};

namespace {

talkface::PhotoOptions options_or_default(const tf_photo_options* options) {
    return options != nullptr ? options->options : talkface::PhotoOptions{};
}

talkface::ImageView view_of(const uint8_t* pixels, int width, int height, int stride_bytes, const tf_pixel_format& format) {
    const int value = talkface::capi::enum_value(format);
    if (value < TF_PIXEL_FORMAT_GRAY8 || value > TF_PIXEL_FORMAT_RGBA8) {
        throw InvalidArgument("format", "expected a tf_pixel_format (0..3), got " + std::to_string(value));
    }
    require_non_null(pixels, "pixels");
    return talkface::ImageView{pixels, width, height, stride_bytes, static_cast<talkface::PixelFormat>(value)};
}

}  // namespace

extern "C" {

int tf_has_dlib_locator(void) {
    return talkface::has_dlib_locator() ? 1 : 0;
}

tf_status tf_photo_options_create(tf_photo_options** out) {
    return guard([&] {
        require_non_null(out, "out");
        *out = new tf_photo_options{};
    });
}

void tf_photo_options_destroy(tf_photo_options* options) {
    delete options;
}

tf_status tf_photo_options_set_locator(tf_photo_options* options, tf_photo_locator locator) {
    return guard([&] {
        require_non_null(options, "options");
        const int value = talkface::capi::enum_value(locator);
        if (value < TF_PHOTO_LOCATOR_THESIS || value > TF_PHOTO_LOCATOR_AUTOMATIC) {
            throw InvalidArgument("locator", "expected a tf_photo_locator (0..2), got " + std::to_string(value));
        }
        options->options.locator = static_cast<talkface::PhotoLocator>(value);
    });
}

tf_status tf_photo_options_set_face_index(tf_photo_options* options, int face_index) {
    return guard([&] {
        require_non_null(options, "options");
        if (face_index < -1) {
            throw InvalidArgument("face_index", "expected -1 or a face's index, got " + std::to_string(face_index));
        }
        options->options.face_index = face_index;
    });
}

tf_status tf_photo_options_set_cascade_dir(tf_photo_options* options, const char* folder) {
    return guard([&] {
        require_non_null(options, "options");
        require_non_null(folder, "folder");
        options->options.cascade_dir = folder;
    });
}

tf_status tf_photo_options_set_dlib_model_path(tf_photo_options* options, const char* path) {
    return guard([&] {
        require_non_null(options, "options");
        require_non_null(path, "path");
        options->options.dlib_model_path = path;
    });
}

tf_status tf_photo_options_set_min_face_width_px(tf_photo_options* options, int min_face_width_px) {
    return guard([&] {
        require_non_null(options, "options");
        options->options.min_face_width_px = min_face_width_px;
    });
}

tf_status tf_photo_result_from_file(const char* path, const tf_photo_options* options, tf_photo_result** out) {
    return guard([&] {
        require_non_null(path, "path");
        require_non_null(out, "out");
        *out = new tf_photo_result{talkface::face_from_photo_file(path, options_or_default(options))};
    });
}

tf_status tf_photo_result_from_pixels(const uint8_t* pixels, int width, int height, int stride_bytes,
                                      tf_pixel_format format, const tf_photo_options* options, tf_photo_result** out) {
    return guard([&] {
        require_non_null(out, "out");
        const talkface::ImageView view = view_of(pixels, width, height, stride_bytes, format);
        *out = new tf_photo_result{talkface::face_from_photo(view, options_or_default(options))};
    });
}

void tf_photo_result_destroy(tf_photo_result* result) {
    delete result;
}

tf_status tf_photo_result_face(const tf_photo_result* result, tf_face_model** out) {
    return guard([&] {
        require_non_null(result, "result");
        require_non_null(out, "out");
        *out = new_face(result->result.face);
    });
}

tf_status tf_photo_result_feature_count(const tf_photo_result* result, size_t* out_count) {
    return guard([&] {
        require_non_null(result, "result");
        require_non_null(out_count, "out_count");
        *out_count = result->result.features.size();
    });
}

tf_status tf_photo_result_feature(const tf_photo_result* result, size_t index, const char** out_name,
                                  double* out_confidence, int* out_from_prior) {
    return guard([&] {
        require_non_null(result, "result");
        const auto& features = result->result.features;
        if (index >= features.size()) {
            throw InvalidArgument("index", "expected 0.." + std::to_string(features.size() - 1) + ", got " +
                                               std::to_string(index));
        }
        const talkface::PhotoFeature& feature = features[index];
        if (out_name != nullptr) *out_name = feature.name.c_str();
        if (out_confidence != nullptr) *out_confidence = feature.confidence;
        if (out_from_prior != nullptr) *out_from_prior = feature.from_prior ? 1 : 0;
    });
}

tf_status tf_photo_result_confidence(const tf_photo_result* result, const char* feature_name, double* out_confidence) {
    return guard([&] {
        require_non_null(result, "result");
        require_non_null(feature_name, "feature_name");
        require_non_null(out_confidence, "out_confidence");
        *out_confidence = result->result.confidence(feature_name);
    });
}

tf_status tf_photo_result_locator(const tf_photo_result* result, tf_photo_locator* out_locator) {
    return guard([&] {
        require_non_null(result, "result");
        require_non_null(out_locator, "out_locator");
        *out_locator = static_cast<tf_photo_locator>(static_cast<int>(result->result.locator_used));
    });
}

tf_status tf_photo_result_write_overlay(const tf_photo_result* result, const char* photo_path,
                                        const char* output_png_path) {
    return guard([&] {
        require_non_null(result, "result");
        require_non_null(photo_path, "photo_path");
        require_non_null(output_png_path, "output_png_path");
        talkface::write_photo_overlay(std::string(photo_path), result->result, output_png_path);
    });
}

tf_status tf_face_model_from_photo_file(const char* path, const tf_photo_options* options, tf_face_model** out) {
    return guard([&] {
        require_non_null(path, "path");
        require_non_null(out, "out");
        *out = new_face(talkface::face_from_photo_file(path, options_or_default(options)).face);
    });
}

tf_status tf_face_model_from_photo_pixels(const uint8_t* pixels, int width, int height, int stride_bytes,
                                          tf_pixel_format format, const tf_photo_options* options, tf_face_model** out) {
    return guard([&] {
        require_non_null(out, "out");
        const talkface::ImageView view = view_of(pixels, width, height, stride_bytes, format);
        *out = new_face(talkface::face_from_photo(view, options_or_default(options)).face);
    });
}

}  // extern "C"

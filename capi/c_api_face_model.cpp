// tf_face_model and colours: the C face of talkface::FaceModel.
#include <cstdio>
#include <string>
#include <string_view>

#include "c_api_guard.hpp"
#include "c_api_handles.hpp"
#include "talkface/types.hpp"

using talkface::FaceColors;
using talkface::FaceModel;
using talkface::InvalidArgument;
using talkface::Point2;
using talkface::capi::guard;
using talkface::capi::new_face;
using talkface::capi::require_non_null;

namespace {

talkface::Rgb to_rgb(tf_rgb colour) {
    return talkface::Rgb{colour.r, colour.g, colour.b};
}
tf_rgb from_rgb(talkface::Rgb colour) {
    return tf_rgb{colour.r, colour.g, colour.b};
}

// The member of FaceColors that `which` names.
talkface::Rgb& color_member(FaceColors& colors, const tf_face_color& which) {
    switch (talkface::capi::enum_value(which)) {
        case TF_FACE_COLOR_SKIN:
            return colors.skin;
        case TF_FACE_COLOR_HAIR:
            return colors.hair;
        case TF_FACE_COLOR_BROWS:
            return colors.brows;
        case TF_FACE_COLOR_EYE_WHITE:
            return colors.eye_white;
        case TF_FACE_COLOR_IRIS:
            return colors.iris;
        case TF_FACE_COLOR_LIPS:
            return colors.lips;
        case TF_FACE_COLOR_MOUTH_INSIDE:
            return colors.mouth_inside;
        case TF_FACE_COLOR_OUTLINE:
            return colors.outline;
        default:
            throw InvalidArgument("which", "expected a tf_face_color (0..7), got " +
                                               std::to_string(talkface::capi::enum_value(which)));
    }
}


}  // namespace

extern "C" {

tf_status tf_rgb_from_hex(const char* text, tf_rgb* out) {
    return guard([&] {
        require_non_null(text, "text");
        require_non_null(out, "out");
        *out = from_rgb(talkface::rgb_from_hex(text, "text"));
    });
}

tf_status tf_rgb_to_hex(tf_rgb colour, char out_hex[8]) {
    return guard([&] {
        require_non_null(out_hex, "out_hex");
        const std::string hex = talkface::to_hex(to_rgb(colour));
        std::snprintf(out_hex, 8, "%s", hex.c_str());
    });
}

size_t tf_face_point_count(void) {
    return FaceModel::kPointCount;
}

const char* tf_face_point_id(size_t index) {
    const auto& ids = FaceModel::point_ids();
    return index < ids.size() ? ids[index].c_str() : nullptr;
}

size_t tf_face_fapu_count(void) {
    return FaceModel::kFapuCount;
}

const char* tf_face_fapu_name(size_t index) {
    const auto& names = FaceModel::fapu_names();
    return index < names.size() ? names[index].c_str() : nullptr;
}

tf_status tf_face_model_default(tf_face_model** out) {
    return guard([&] {
        require_non_null(out, "out");
        *out = new_face(FaceModel::default_face());
    });
}

tf_status tf_face_model_load(const char* path, tf_face_model** out) {
    return guard([&] {
        require_non_null(path, "path");
        require_non_null(out, "out");
        *out = new_face(FaceModel::load(path));
    });
}

tf_status tf_face_model_from_xml(const char* text, size_t length, const char* source_name,
                                 tf_face_model** out) {
    return guard([&] {
        require_non_null(text, "text");
        require_non_null(out, "out");
        *out = new_face(FaceModel::from_xml(std::string_view(text, length),
                                            source_name != nullptr ? source_name : "<string>"));
    });
}

tf_status tf_face_model_save(const tf_face_model* face, const char* path) {
    return guard([&] {
        require_non_null(face, "face");
        require_non_null(path, "path");
        face->model.save(path);
    });
}

tf_status tf_face_model_to_xml(const tf_face_model* face, char** out_xml, size_t* out_len) {
    return guard([&] {
        require_non_null(face, "face");
        require_non_null(out_xml, "out_xml");
        talkface::capi::give_document(face->model.to_xml(), out_xml, out_len);
    });
}

tf_status tf_face_model_clone(const tf_face_model* face, tf_face_model** out) {
    return guard([&] {
        require_non_null(face, "face");
        require_non_null(out, "out");
        *out = new_face(face->model);
    });
}

void tf_face_model_destroy(tf_face_model* face) {
    delete face;
}

tf_status tf_face_model_equal(const tf_face_model* a, const tf_face_model* b, int* out_equal) {
    return guard([&] {
        require_non_null(a, "a");
        require_non_null(b, "b");
        require_non_null(out_equal, "out_equal");
        *out_equal = a->model == b->model ? 1 : 0;
    });
}

tf_status tf_face_model_point(const tf_face_model* face, const char* id, double* out_x, double* out_y) {
    return guard([&] {
        require_non_null(face, "face");
        require_non_null(id, "id");
        require_non_null(out_x, "out_x");
        require_non_null(out_y, "out_y");
        const Point2 point = face->model.point(id);
        *out_x = point.x;
        *out_y = point.y;
    });
}

tf_status tf_face_model_set_point(tf_face_model* face, const char* id, double x, double y) {
    return guard([&] {
        require_non_null(face, "face");
        require_non_null(id, "id");
        face->model.set_point(id, Point2{x, y});
    });
}

tf_status tf_face_model_fapu(const tf_face_model* face, const char* name, double* out_value_px) {
    return guard([&] {
        require_non_null(face, "face");
        require_non_null(name, "name");
        require_non_null(out_value_px, "out_value_px");
        *out_value_px = face->model.fapu(name);
    });
}

tf_status tf_face_model_set_fapu(tf_face_model* face, const char* name, double value_px) {
    return guard([&] {
        require_non_null(face, "face");
        require_non_null(name, "name");
        face->model.set_fapu(name, value_px);
    });
}

tf_status tf_face_model_name(const tf_face_model* face, const char** out_name) {
    return guard([&] {
        require_non_null(face, "face");
        require_non_null(out_name, "out_name");
        *out_name = face->model.name().c_str();
    });
}

tf_status tf_face_model_set_name(tf_face_model* face, const char* name) {
    return guard([&] {
        require_non_null(face, "face");
        require_non_null(name, "name");
        face->model.set_name(name);
    });
}

tf_status tf_face_model_color(const tf_face_model* face, tf_face_color which, tf_rgb* out) {
    return guard([&] {
        require_non_null(face, "face");
        require_non_null(out, "out");
        FaceColors colors = face->model.colors();
        *out = from_rgb(color_member(colors, which));
    });
}

tf_status tf_face_model_set_color(tf_face_model* face, tf_face_color which, tf_rgb colour) {
    return guard([&] {
        require_non_null(face, "face");
        FaceColors colors = face->model.colors();
        color_member(colors, which) = to_rgb(colour);
        face->model.set_colors(colors);
    });
}

}  // extern "C"

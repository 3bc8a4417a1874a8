// tf_expression_style: the C face of ExpressionStyle, its fields by name (expression_simulator.hpp).
#include <cstddef>
#include <string>
#include <string_view>
#include <utility>

#include "c_api_guard.hpp"
#include "c_api_handles.hpp"

using talkface::ExpressionStyle;
using talkface::capi::enum_value;
using talkface::capi::guard;
using talkface::capi::require_non_null;

namespace {

using talkface::InvalidArgument;
using talkface::UniformRange;

// The fields by name, for C only: C++ and Python use the members themselves. Every name is the
// member's, as in the style JSON; a test sets every key of tf_expression_style_to_json() by name.
template <typename Value>
struct Field {
    const char* name;
    Value ExpressionStyle::*member;
};

using S = ExpressionStyle;
const Field<double> kNumberFields[] = {{"blink_interval_scale_s", &S::blink_interval_scale_s},
                                       {"nod_min_pause_s", &S::nod_min_pause_s}};
const Field<int> kIntegerFields[] = {{"blink_interval_shape", &S::blink_interval_shape}};
const Field<UniformRange> kRangeFields[] = {{"blink_duration_s", &S::blink_duration_s},
                                            {"brows_interval_s", &S::brows_interval_s},
                                            {"brows_duration_s", &S::brows_duration_s},
                                            {"brows_amount", &S::brows_amount},
                                            {"tilt_interval_s", &S::tilt_interval_s},
                                            {"tilt_duration_s", &S::tilt_duration_s},
                                            {"tilt_angle_deg", &S::tilt_angle_deg},
                                            {"turn_interval_s", &S::turn_interval_s},
                                            {"turn_duration_s", &S::turn_duration_s},
                                            {"turn_angle_deg", &S::turn_angle_deg},
                                            {"nod_lead_s", &S::nod_lead_s},
                                            {"nod_down_s", &S::nod_down_s},
                                            {"nod_up_s", &S::nod_up_s},
                                            {"nod_angle_deg", &S::nod_angle_deg}};
const Field<bool> kFlagFields[] = {{"is_blink_simulated", &S::is_blink_simulated},
                                   {"is_brows_simulated", &S::is_brows_simulated},
                                   {"is_tilt_simulated", &S::is_tilt_simulated},
                                   {"is_turn_simulated", &S::is_turn_simulated},
                                   {"is_nod_simulated", &S::is_nod_simulated}};

template <typename Value, std::size_t N>
bool is_in(const Field<Value> (&fields)[N], std::string_view name) {
    for (const Field<Value>& field : fields) {
        if (name == field.name) return true;
    }
    return false;
}

// The member named `name` in `fields` (of type `type_name`). Throws InvalidArgument for a field of
// another type, saying which, and for an unknown name, listing the fields of this type.
template <typename Value, std::size_t N>
Value ExpressionStyle::*find(const Field<Value> (&fields)[N], const char* type_name, const char* name) {
    std::string names;
    for (const Field<Value>& field : fields) {
        if (std::string_view(name) == field.name) return field.member;
        names += (names.empty() ? "" : ", ") + std::string(field.name);
    }
    const char* other = is_in(kNumberFields, name)    ? "number"
                        : is_in(kIntegerFields, name) ? "integer"
                        : is_in(kRangeFields, name)   ? "range"
                        : is_in(kFlagFields, name)    ? "flag"
                                                      : nullptr;
    if (other != nullptr) {
        throw InvalidArgument("ExpressionStyle::" + std::string(name),
                              std::string("is a ") + other + " field, not a " + type_name + " field");
    }
    throw InvalidArgument("ExpressionStyle field \"" + std::string(name) + "\"",
                          std::string("unknown; the ") + type_name + " fields are " + names);
}

// *out = read(field's value), once style, field and out (called out_name) are known not to be NULL.
template <typename Value, std::size_t N, typename Out, typename Read>
tf_status read_field(const tf_expression_style* style, const char* field, const Field<Value> (&fields)[N],
                     const char* type_name, Out* out, const char* out_name, Read read) {
    return guard([&] {
        require_non_null(style, "style");
        require_non_null(field, "field");
        require_non_null(out, out_name);
        *out = read(style->style.*find(fields, type_name, field));
    });
}

// Sets the field on a copy and validates it: a refused value leaves the style as it was, and the
// style was valid before, so the field named in the error is this one.
template <typename Value, std::size_t N>
tf_status write_field(tf_expression_style* style, const char* field, const Field<Value> (&fields)[N],
                      const char* type_name, Value value) {
    return guard([&] {
        require_non_null(style, "style");
        require_non_null(field, "field");
        ExpressionStyle changed = style->style;
        changed.*find(fields, type_name, field) = value;
        changed.validate();
        style->style = std::move(changed);
    });
}

}  // namespace

extern "C" {

tf_status tf_expression_style_create(const char* base_name, tf_expression_style** out) {
    return guard([&] {
        require_non_null(out, "out");
        *out =
            new tf_expression_style{ExpressionStyle::from_name(base_name != nullptr ? base_name : "normal")};
    });
}

tf_status tf_expression_style_load(const char* path, tf_expression_style** out) {
    return guard([&] {
        require_non_null(path, "path");
        require_non_null(out, "out");
        *out = new tf_expression_style{ExpressionStyle::load(path)};
    });
}

tf_status tf_expression_style_from_json(const char* json, const char* source_name,
                                        tf_expression_style** out) {
    return guard([&] {
        require_non_null(json, "json");
        require_non_null(out, "out");
        *out = new tf_expression_style{
            ExpressionStyle::from_json(json, source_name != nullptr ? source_name : "<string>")};
    });
}

tf_status tf_expression_style_to_json(const tf_expression_style* style, char** out_json, size_t* out_len) {
    return guard([&] {
        require_non_null(style, "style");
        require_non_null(out_json, "out_json");
        talkface::capi::give_document(style->style.to_json(), out_json, out_len);
    });
}

void tf_expression_style_destroy(tf_expression_style* style) {
    delete style;
}

tf_status tf_expression_style_name(const tf_expression_style* style, const char** out_name) {
    return guard([&] {
        require_non_null(style, "style");
        require_non_null(out_name, "out_name");
        *out_name = style->style.name.c_str();
    });
}

tf_status tf_expression_style_get_number(const tf_expression_style* style, const char* field,
                                         double* out_value) {
    return read_field(style, field, kNumberFields, "number", out_value, "out_value",
                      [](double value) { return value; });
}

tf_status tf_expression_style_set_number(tf_expression_style* style, const char* field, double value) {
    return write_field(style, field, kNumberFields, "number", value);
}

tf_status tf_expression_style_get_integer(const tf_expression_style* style, const char* field,
                                          int* out_value) {
    return read_field(style, field, kIntegerFields, "integer", out_value, "out_value",
                      [](int value) { return value; });
}

tf_status tf_expression_style_set_integer(tf_expression_style* style, const char* field, int value) {
    return write_field(style, field, kIntegerFields, "integer", value);
}

tf_status tf_expression_style_get_range(const tf_expression_style* style, const char* field, double* out_min,
                                        double* out_max) {
    return read_field(style, field, kRangeFields, "range", out_min, "out_min",
                      [&](const UniformRange& range) {
                          require_non_null(out_max, "out_max");
                          *out_max = range.max;
                          return range.min;
                      });
}

tf_status tf_expression_style_set_range(tf_expression_style* style, const char* field, double min,
                                        double max) {
    return write_field(style, field, kRangeFields, "range", UniformRange{min, max});
}

tf_status tf_expression_style_get_flag(const tf_expression_style* style, const char* field, int* out_value) {
    return read_field(style, field, kFlagFields, "flag", out_value, "out_value",
                      [](bool value) { return value ? 1 : 0; });
}

tf_status tf_expression_style_set_flag(tf_expression_style* style, const char* field, int value) {
    return write_field(style, field, kFlagFields, "flag", value != 0);
}

tf_status tf_expression_style_set_simulated(tf_expression_style* style, tf_expression_event_kind kind,
                                            int is_simulated) {
    return guard([&] {
        require_non_null(style, "style");
        style->style.set_simulated(static_cast<talkface::ExpressionEventKind>(enum_value(kind)),
                                   is_simulated != 0);
    });
}

tf_status tf_expression_simulator_create_with_style(const tf_timeline* timeline, uint64_t seed,
                                                    const tf_expression_style* style,
                                                    tf_expression_simulator** out) {
    return guard([&] {
        require_non_null(timeline, "timeline");
        require_non_null(style, "style");
        require_non_null(out, "out");
        *out = new tf_expression_simulator{
            talkface::ExpressionSimulator(timeline->timeline, seed, style->style)};
    });
}

tf_status tf_expression_simulator_style(const tf_expression_simulator* simulator, tf_expression_style** out) {
    return guard([&] {
        require_non_null(simulator, "simulator");
        require_non_null(out, "out");
        *out = new tf_expression_style{simulator->simulator.style()};
    });
}

}  // extern "C"

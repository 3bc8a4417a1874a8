// tf_expression_style: the C face of ExpressionStyle, its fields by name (expression_simulator.hpp).
#include "c_api_guard.hpp"
#include "c_api_handles.hpp"

using talkface::ExpressionStyle;
using talkface::capi::enum_value;
using talkface::capi::guard;
using talkface::capi::require_non_null;

namespace {

// *out = read(style, field), once style, field and out (called out_name) are known not to be NULL.
template <typename Value, typename Read>
tf_status read_field(const tf_expression_style* style, const char* field, Value* out, const char* out_name,
                     Read read) {
    return guard([&] {
        require_non_null(style, "style");
        require_non_null(field, "field");
        require_non_null(out, out_name);
        *out = read(style->style, field);
    });
}

template <typename Write>
tf_status write_field(tf_expression_style* style, const char* field, Write write) {
    return guard([&] {
        require_non_null(style, "style");
        require_non_null(field, "field");
        write(style->style, field);
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
    return read_field(style, field, out_value, "out_value",
                      [](const ExpressionStyle& s, const char* f) { return s.number(f); });
}

tf_status tf_expression_style_set_number(tf_expression_style* style, const char* field, double value) {
    return write_field(style, field, [&](ExpressionStyle& s, const char* f) { s.set_number(f, value); });
}

tf_status tf_expression_style_get_integer(const tf_expression_style* style, const char* field,
                                          int* out_value) {
    return read_field(style, field, out_value, "out_value",
                      [](const ExpressionStyle& s, const char* f) { return s.integer(f); });
}

tf_status tf_expression_style_set_integer(tf_expression_style* style, const char* field, int value) {
    return write_field(style, field, [&](ExpressionStyle& s, const char* f) { s.set_integer(f, value); });
}

tf_status tf_expression_style_get_range(const tf_expression_style* style, const char* field, double* out_min,
                                        double* out_max) {
    return read_field(style, field, out_min, "out_min", [&](const ExpressionStyle& s, const char* f) {
        require_non_null(out_max, "out_max");
        const talkface::UniformRange range = s.range(f);
        *out_max = range.max;
        return range.min;
    });
}

tf_status tf_expression_style_set_range(tf_expression_style* style, const char* field, double min,
                                        double max) {
    return write_field(style, field, [&](ExpressionStyle& s, const char* f) { s.set_range(f, {min, max}); });
}

tf_status tf_expression_style_get_flag(const tf_expression_style* style, const char* field, int* out_value) {
    return read_field(style, field, out_value, "out_value",
                      [](const ExpressionStyle& s, const char* f) { return s.flag(f) ? 1 : 0; });
}

tf_status tf_expression_style_set_flag(tf_expression_style* style, const char* field, int value) {
    return write_field(style, field, [&](ExpressionStyle& s, const char* f) { s.set_flag(f, value != 0); });
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

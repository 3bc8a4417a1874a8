// ExpressionStyle's fields by name, with the limits each one is checked against: shared by the
// by-name accessors, the simulator's check of a whole style and the style JSON reader.
#ifndef TALKFACE_EXPRESSION_STYLE_FIELDS_HPP
#define TALKFACE_EXPRESSION_STYLE_FIELDS_HPP

#include <string>
#include <string_view>
#include <vector>

#include "talkface/expression_simulator.hpp"

namespace talkface::detail {

// One field: exactly one member pointer is set, the one of `type`.
struct StyleFieldSpec {
    StyleField field;
    double ExpressionStyle::*number = nullptr;
    int ExpressionStyle::*integer = nullptr;
    UniformRange ExpressionStyle::*range = nullptr;
    bool ExpressionStyle::*flag = nullptr;
    double lowest = 0.0;   // smallest value (for a range: smallest min)
    double highest = 0.0;  // largest value (for a range: largest max)
    // The value (a range's min) must be above `lowest`, not just at or above it: a zero duration
    // or scale could stall the simulation loop with zero intervals.
    bool is_above_lowest = false;
};

const std::vector<StyleFieldSpec>& style_field_specs();

// The field named `name` of type `type`. Throws InvalidArgument naming it if there is none: for
// an unknown name listing the fields of that type, for one of another type saying which it is.
const StyleFieldSpec& find_style_field(std::string_view name, StyleFieldType type);

// "" if the field's value in `style` is within its limits, else what is wrong ("expected ...,
// got ...").
std::string style_field_problem(const StyleFieldSpec& spec, const ExpressionStyle& style);

// Throws InvalidArgument naming the first field ("ExpressionStyle::tilt_angle_deg") out of range.
void check_style(const ExpressionStyle& style);

// "number", "integer", "range", "flag".
const char* style_field_type_name(StyleFieldType type);

}  // namespace talkface::detail

#endif

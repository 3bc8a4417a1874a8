// ExpressionStyle's fields by name, with the limits each one is checked against: shared by
// ExpressionStyle::validate() (which the simulator calls) and the style JSON reader and writer.
#ifndef TALKFACE_EXPRESSION_STYLE_FIELDS_HPP
#define TALKFACE_EXPRESSION_STYLE_FIELDS_HPP

#include <string>
#include <string_view>
#include <vector>

#include "talkface/expression_simulator.hpp"

namespace talkface::detail {

// What a field holds.
enum class StyleFieldType : int {
    number,   // a double: seconds
    integer,  // an int: blink_interval_shape
    range,    // a UniformRange: seconds, 0..1 or degrees
    flag,     // a bool: is_<kind>_simulated
};

// A field as the style JSON names it: the C++ member's name.
struct StyleField {
    const char* name;
    StyleFieldType type;
};

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

// "" if the field's value in `style` is within its limits, else what is wrong ("expected ...,
// got ...").
std::string style_field_problem(const StyleFieldSpec& spec, const ExpressionStyle& style);

}  // namespace talkface::detail

#endif

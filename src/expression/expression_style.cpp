// ExpressionStyle: the thesis's named styles (chapter 4), its fields by name and their limits.
#include <array>
#include <cmath>
#include <string>

#include "common/number_format.hpp"
#include "expression/style_fields.hpp"
#include "talkface/errors.hpp"
#include "talkface/expression_simulator.hpp"

namespace talkface::detail {

namespace {

// Longer than any speech talkface animates, short enough that a typo (3600000) shows.
constexpr double kLongestSeconds = 3600.0;

StyleFieldSpec number_field(const char* name, double ExpressionStyle::*member, bool is_above_lowest) {
    StyleFieldSpec spec{{name, StyleFieldType::number}};
    spec.number = member;
    spec.highest = kLongestSeconds;
    spec.is_above_lowest = is_above_lowest;
    return spec;
}

StyleFieldSpec range_field(const char* name, UniformRange ExpressionStyle::*member, double highest,
                           bool is_duration) {
    StyleFieldSpec spec{{name, StyleFieldType::range}};
    spec.range = member;
    spec.highest = highest;
    spec.is_above_lowest = is_duration;
    return spec;
}

StyleFieldSpec flag_field(const char* name, bool ExpressionStyle::*member) {
    StyleFieldSpec spec{{name, StyleFieldType::flag}};
    spec.flag = member;
    return spec;
}

// Indexed by ExpressionEventKind.
constexpr std::array<bool ExpressionStyle::*, 5> kSimulatedFlags{
    &ExpressionStyle::is_blink_simulated, &ExpressionStyle::is_brows_simulated,
    &ExpressionStyle::is_tilt_simulated, &ExpressionStyle::is_turn_simulated,
    &ExpressionStyle::is_nod_simulated};

std::vector<StyleFieldSpec> make_specs() {
    using S = ExpressionStyle;
    StyleFieldSpec shape{{"blink_interval_shape", StyleFieldType::integer}};
    shape.integer = &S::blink_interval_shape;
    // Gamma variates are products of `shape` uniforms (random.hpp): 16 keeps them above 2^-900.
    shape.lowest = 1;
    shape.highest = 16;
    const bool duration = true;
    const bool interval = false;
    return {shape,
            number_field("blink_interval_scale_s", &S::blink_interval_scale_s, true),
            range_field("blink_duration_s", &S::blink_duration_s, kLongestSeconds, duration),
            range_field("brows_interval_s", &S::brows_interval_s, kLongestSeconds, interval),
            range_field("brows_duration_s", &S::brows_duration_s, kLongestSeconds, duration),
            range_field("brows_amount", &S::brows_amount, 1.0, interval),
            range_field("tilt_interval_s", &S::tilt_interval_s, kLongestSeconds, interval),
            range_field("tilt_duration_s", &S::tilt_duration_s, kLongestSeconds, duration),
            range_field("tilt_angle_deg", &S::tilt_angle_deg, kMaxPoseAngleDeg, interval),
            range_field("turn_interval_s", &S::turn_interval_s, kLongestSeconds, interval),
            range_field("turn_duration_s", &S::turn_duration_s, kLongestSeconds, duration),
            range_field("turn_angle_deg", &S::turn_angle_deg, kMaxPoseAngleDeg, interval),
            range_field("nod_lead_s", &S::nod_lead_s, kLongestSeconds, interval),
            range_field("nod_down_s", &S::nod_down_s, kLongestSeconds, duration),
            range_field("nod_up_s", &S::nod_up_s, kLongestSeconds, duration),
            range_field("nod_angle_deg", &S::nod_angle_deg, kMaxPoseAngleDeg, interval),
            number_field("nod_min_pause_s", &S::nod_min_pause_s, false),
            flag_field("is_blink_simulated", &S::is_blink_simulated),
            flag_field("is_brows_simulated", &S::is_brows_simulated),
            flag_field("is_tilt_simulated", &S::is_tilt_simulated),
            flag_field("is_turn_simulated", &S::is_turn_simulated),
            flag_field("is_nod_simulated", &S::is_nod_simulated)};
}

std::string lower_bound_text(const StyleFieldSpec& spec, const char* what) {
    return format_shortest(spec.lowest) + (spec.is_above_lowest ? " < " : " <= ") + what;
}

bool is_below_lowest(const StyleFieldSpec& spec, double value) {
    return spec.is_above_lowest ? value <= spec.lowest : value < spec.lowest;
}

}  // namespace

const std::vector<StyleFieldSpec>& style_field_specs() {
    static const std::vector<StyleFieldSpec> specs = make_specs();
    return specs;
}

std::string style_field_problem(const StyleFieldSpec& spec, const ExpressionStyle& style) {
    switch (spec.field.type) {
        case StyleFieldType::number: {
            const double value = style.*spec.number;
            if (std::isfinite(value) && !is_below_lowest(spec, value) && value <= spec.highest) return "";
            return "expected seconds with " + lower_bound_text(spec, "value") +
                   " <= " + format_shortest(spec.highest) + ", got " + format_shortest(value);
        }
        case StyleFieldType::integer: {
            const int value = style.*spec.integer;
            if (value >= spec.lowest && value <= spec.highest) return "";
            return "expected an integer from " + format_shortest(spec.lowest) + " to " +
                   format_shortest(spec.highest) + ", got " + std::to_string(value);
        }
        case StyleFieldType::range: {
            const UniformRange range = style.*spec.range;
            if (std::isfinite(range.min) && std::isfinite(range.max) && range.min <= range.max &&
                !is_below_lowest(spec, range.min) && range.max <= spec.highest) {
                return "";
            }
            return "expected a range with " + lower_bound_text(spec, "min") +
                   " <= max <= " + format_shortest(spec.highest) + ", got [" + format_shortest(range.min) +
                   ", " + format_shortest(range.max) + "]";
        }
        case StyleFieldType::flag:
            return "";
    }
    return "unknown field type";
}

}  // namespace talkface::detail

namespace talkface {
inline namespace v0 {

namespace {

std::size_t checked_kind_index(ExpressionEventKind kind) {
    const auto index = static_cast<std::size_t>(kind);
    if (index >= detail::kSimulatedFlags.size()) {
        throw InvalidArgument("kind", "expected an ExpressionEventKind, got " + std::to_string(index));
    }
    return index;
}

}  // namespace

ExpressionStyle ExpressionStyle::normal() {
    return ExpressionStyle{};
}

ExpressionStyle ExpressionStyle::announcer() {
    ExpressionStyle style;
    style.name = "announcer";
    style.tilt_interval_s = {0.0, 3.32};   // thesis 4.5.1: mean 1.60 +- sd 1.72
    style.tilt_duration_s = {0.2, 0.5};    // thesis 4.5.1: mean 0.35 +- sd 0.15
    style.turn_interval_s = {0.04, 3.96};  // thesis Table 4.7
    style.turn_duration_s = {0.2, 0.46};   // thesis Table 4.7
    style.nod_down_s = {0.17, 0.47};       // thesis Table 4.12
    style.nod_up_s = {0.17, 0.35};         // thesis Table 4.12
    return style;
}

ExpressionStyle ExpressionStyle::from_name(std::string_view name) {
    if (name == "normal") return normal();
    if (name == "announcer") return announcer();
    throw InvalidArgument("expression style \"" + std::string(name) + "\"",
                          "expected \"normal\" or \"announcer\"");
}

void ExpressionStyle::validate() const {
    for (const detail::StyleFieldSpec& spec : detail::style_field_specs()) {
        const std::string problem = detail::style_field_problem(spec, *this);
        if (!problem.empty())
            throw InvalidArgument("ExpressionStyle::" + std::string(spec.field.name), problem);
    }
}

bool ExpressionStyle::is_simulated(ExpressionEventKind kind) const {
    return this->*detail::kSimulatedFlags[checked_kind_index(kind)];
}

void ExpressionStyle::set_simulated(ExpressionEventKind kind, bool is_simulated) {
    this->*detail::kSimulatedFlags[checked_kind_index(kind)] = is_simulated;
}

bool operator==(const ExpressionStyle& a, const ExpressionStyle& b) {
    if (a.name != b.name) return false;
    for (const detail::StyleFieldSpec& spec : detail::style_field_specs()) {
        const bool is_equal = spec.number    ? a.*spec.number == b.*spec.number
                              : spec.integer ? a.*spec.integer == b.*spec.integer
                              : spec.range   ? a.*spec.range == b.*spec.range
                                             : a.*spec.flag == b.*spec.flag;
        if (!is_equal) return false;
    }
    return true;
}

bool operator!=(const ExpressionStyle& a, const ExpressionStyle& b) {
    return !(a == b);
}

}  // namespace v0
}  // namespace talkface

// The style JSON (docs/style-format.md): an ExpressionStyle read from and written to a flat JSON
// object, through the library's small JSON reader (common/json.hpp).
#include <cmath>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "common/atomic_file.hpp"
#include "common/json.hpp"
#include "common/number_format.hpp"
#include "expression/style_fields.hpp"
#include "talkface/errors.hpp"
#include "talkface/expression_simulator.hpp"

namespace talkface {
inline namespace v0 {

namespace {

using detail::JsonReader;
using detail::JsonValue;
using detail::StyleFieldType;

std::string all_keys() {
    std::string keys = "base, name";
    for (const detail::StyleFieldSpec& spec : detail::style_field_specs())
        keys += std::string(", ") + spec.field.name;
    return keys;
}

// Sets one field from its JSON value, or says what is wrong with the value's type.
void set_field(const detail::StyleFieldSpec& spec, const JsonValue& value, ExpressionStyle& style,
               const JsonReader& reader, const std::string& item) {
    const auto wrong_type = [&](const char* expected) {
        reader.fail(value.offset, item, std::string("expected ") + expected + ", found " + detail::json_found(value));
    };
    switch (spec.field.type) {
        case StyleFieldType::number:
            if (value.type != JsonValue::Type::number) wrong_type("a number");
            style.*spec.number = value.number;
            break;
        case StyleFieldType::integer:
            if (value.type != JsonValue::Type::number || value.number != std::floor(value.number) ||
                std::abs(value.number) > 1e9) {
                wrong_type("a whole number");
            }
            style.*spec.integer = static_cast<int>(value.number);
            break;
        case StyleFieldType::range:
            if (value.type != JsonValue::Type::array || value.items.size() != 2 ||
                value.items[0].type != JsonValue::Type::number ||
                value.items[1].type != JsonValue::Type::number) {
                wrong_type("[min, max], a list of two numbers");
            }
            style.*spec.range = UniformRange{value.items[0].number, value.items[1].number};
            break;
        case StyleFieldType::flag:
            if (value.type != JsonValue::Type::boolean) wrong_type("true or false");
            style.*spec.flag = value.boolean;
            break;
    }
}

}  // namespace

ExpressionStyle ExpressionStyle::from_json(std::string_view text, const std::string& source) {
    JsonReader reader(text, source);
    const JsonValue document = reader.read_document();
    if (document.type != JsonValue::Type::object) {
        reader.fail(
            document.offset, "",
            std::string("expected a style object {\"key\": value, ...}, found ") + detail::json_found(document));
    }
    // "base" first, wherever it stands: the other keys change the style it names.
    ExpressionStyle style;
    for (std::size_t k = 0; k < document.members.size(); ++k) {
        const auto& [key, value] = document.members[k];
        if (key != "base") continue;
        if (value.type != JsonValue::Type::string) {
            reader.fail(value.offset, "key \"base\"",
                        std::string("expected \"normal\" or \"announcer\", found ") + detail::json_found(value));
        }
        try {
            style = from_name(value.text);
        } catch (const InvalidArgument& error) {
            reader.fail(value.offset, "key \"base\"", error.what());
        }
    }
    style.name = "custom";
    for (std::size_t k = 0; k < document.members.size(); ++k) {
        const auto& [key, value] = document.members[k];
        const std::string item = "key \"" + key + "\"";
        if (key == "base") continue;
        if (key == "name") {
            if (value.type != JsonValue::Type::string) {
                reader.fail(value.offset, item, std::string("expected a string, found ") + detail::json_found(value));
            }
            style.name = value.text;
            continue;
        }
        const detail::StyleFieldSpec* spec = nullptr;
        for (const detail::StyleFieldSpec& candidate : detail::style_field_specs()) {
            if (key == candidate.field.name) spec = &candidate;
        }
        if (spec == nullptr)
            reader.fail(document.key_offsets[k], item, "unknown key; the keys are " + all_keys());
        set_field(*spec, value, style, reader, item);
        const std::string problem = detail::style_field_problem(*spec, style);
        if (!problem.empty()) reader.fail(value.offset, item, problem);
    }
    return style;
}

ExpressionStyle ExpressionStyle::load(const std::string& path) {
    return from_json(detail::read_file(path), path);
}

std::string ExpressionStyle::to_json() const {
    std::string json = "{\n  \"name\": " + detail::json_quoted(name);
    for (const detail::StyleFieldSpec& spec : detail::style_field_specs()) {
        json += ",\n  " + detail::json_quoted(spec.field.name) + ": ";
        switch (spec.field.type) {
            case StyleFieldType::number:
                json += detail::format_shortest(this->*spec.number);
                break;
            case StyleFieldType::integer:
                json += std::to_string(this->*spec.integer);
                break;
            case StyleFieldType::range:
                json += "[" + detail::format_shortest((this->*spec.range).min) + ", " +
                        detail::format_shortest((this->*spec.range).max) + "]";
                break;
            case StyleFieldType::flag:
                json += this->*spec.flag ? "true" : "false";
                break;
        }
    }
    return json + "\n}\n";
}

}  // namespace v0
}  // namespace talkface

// The style JSON (docs/style-format.md): an ExpressionStyle read from and written to a flat JSON
// object. The library has no JSON dependency, and this format needs only a small reader.
#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "common/atomic_file.hpp"
#include "common/number_format.hpp"
#include "common/text_location.hpp"
#include "expression/style_fields.hpp"
#include "talkface/errors.hpp"
#include "talkface/expression_simulator.hpp"

namespace talkface {
inline namespace v0 {

namespace {

struct JsonValue {
    enum class Type { null, boolean, number, string, array, object };
    Type type = Type::null;
    std::size_t offset = 0;  // where the value starts in the text, for line:column
    bool boolean = false;
    double number = 0.0;
    std::string text;
    std::vector<JsonValue> items;
    std::vector<std::pair<std::string, JsonValue>> members;  // in the order of the text
    std::vector<std::size_t> key_offsets;                    // one per member
};

// A strict RFC 8259 reader: no comments, no trailing commas.
class JsonReader {
public:
    JsonReader(std::string_view text, const std::string& source) : text_(text), source_(source) {}

    JsonValue read_document() {
        JsonValue value = read_value(0);
        skip_space();
        if (position_ < text_.size()) fail(position_, "", "unexpected text after the JSON value");
        return value;
    }

    [[noreturn]] void fail(std::size_t offset, const std::string& item, const std::string& problem) const {
        const detail::TextLocation where = detail::locate_offset(text_, static_cast<std::ptrdiff_t>(offset));
        throw ParseError(source_, where.line, where.column, item, problem);
    }

private:
    // Deep enough for any style; a bound keeps hostile input from exhausting the stack.
    static constexpr int kMaxDepth = 64;

    void skip_space() {
        while (position_ < text_.size() && (text_[position_] == ' ' || text_[position_] == '\t' ||
                                            text_[position_] == '\n' || text_[position_] == '\r')) {
            ++position_;
        }
    }

    bool consume(std::string_view word) {
        if (text_.substr(position_, word.size()) != word) return false;
        position_ += word.size();
        return true;
    }

    void expect(char c, const char* context) {
        skip_space();
        if (position_ >= text_.size() || text_[position_] != c) {
            fail(position_, "", std::string("expected '") + c + "' " + context);
        }
        ++position_;
    }

    JsonValue read_value(int depth) {
        skip_space();
        if (depth > kMaxDepth) fail(position_, "", "nested too deeply");
        JsonValue value;
        value.offset = position_;
        if (position_ >= text_.size())
            fail(position_, "", "not JSON: the text ends where a value should start");
        const char c = text_[position_];
        if (c == '{') {
            read_object(value, depth);
        } else if (c == '[') {
            read_array(value, depth);
        } else if (c == '"') {
            value.type = JsonValue::Type::string;
            value.text = read_string();
        } else if (consume("true") || consume("false")) {
            value.type = JsonValue::Type::boolean;
            value.boolean = c == 't';
        } else if (consume("null")) {
            value.type = JsonValue::Type::null;
        } else {
            value.type = JsonValue::Type::number;
            value.number = read_number();
        }
        return value;
    }

    void read_object(JsonValue& value, int depth) {
        value.type = JsonValue::Type::object;
        ++position_;
        skip_space();
        if (consume("}")) return;
        for (;;) {
            skip_space();
            const std::size_t key_offset = position_;
            if (position_ >= text_.size() || text_[position_] != '"')
                fail(position_, "", "expected a key in quotes");
            std::string key = read_string();
            for (const auto& member : value.members) {
                if (member.first == key) fail(key_offset, "key \"" + key + "\"", "given twice");
            }
            expect(':', "after a key");
            value.members.emplace_back(std::move(key), read_value(depth + 1));
            value.key_offsets.push_back(key_offset);
            skip_space();
            if (consume("}")) return;
            expect(',', "or '}' after a value in an object");
        }
    }

    void read_array(JsonValue& value, int depth) {
        value.type = JsonValue::Type::array;
        ++position_;
        skip_space();
        if (consume("]")) return;
        for (;;) {
            value.items.push_back(read_value(depth + 1));
            skip_space();
            if (consume("]")) return;
            expect(',', "or ']' after a value in a list");
        }
    }

    double read_number() {
        const std::size_t start = position_;
        const auto is_digit = [&](std::size_t k) {
            return k < text_.size() && text_[k] >= '0' && text_[k] <= '9';
        };
        std::size_t end = start;
        if (end < text_.size() && text_[end] == '-') ++end;
        if (!is_digit(end))
            fail(start, "",
                 "not JSON: expected a value (a number, string, list, object, true, false or null)");
        if (text_[end] == '0') {
            ++end;
        } else {
            while (is_digit(end)) ++end;
        }
        if (end < text_.size() && text_[end] == '.') {
            ++end;
            if (!is_digit(end)) fail(end, "", "not JSON: expected a digit after the decimal point");
            while (is_digit(end)) ++end;
        }
        if (end < text_.size() && (text_[end] == 'e' || text_[end] == 'E')) {
            ++end;
            if (end < text_.size() && (text_[end] == '+' || text_[end] == '-')) ++end;
            if (!is_digit(end)) fail(end, "", "not JSON: expected a digit in the exponent");
            while (is_digit(end)) ++end;
        }
        const std::optional<double> number = detail::parse_double(text_.substr(start, end - start));
        if (!number || !std::isfinite(*number)) fail(start, "", "number out of range");
        position_ = end;
        return *number;
    }

    unsigned read_hex4() {
        if (position_ + 4 > text_.size()) fail(position_, "", "not JSON: expected 4 hex digits after \\u");
        unsigned code = 0;
        for (int k = 0; k < 4; ++k) {
            const char c = text_[position_++];
            code <<= 4;
            if (c >= '0' && c <= '9')
                code |= static_cast<unsigned>(c - '0');
            else if (c >= 'a' && c <= 'f')
                code |= static_cast<unsigned>(c - 'a' + 10);
            else if (c >= 'A' && c <= 'F')
                code |= static_cast<unsigned>(c - 'A' + 10);
            else
                fail(position_ - 1, "", "not JSON: expected 4 hex digits after \\u");
        }
        return code;
    }

    static void append_utf8(std::string& out, std::uint32_t code) {
        if (code < 0x80) {
            out += static_cast<char>(code);
        } else if (code < 0x800) {
            out += static_cast<char>(0xC0 | (code >> 6));
            out += static_cast<char>(0x80 | (code & 0x3F));
        } else if (code < 0x10000) {
            out += static_cast<char>(0xE0 | (code >> 12));
            out += static_cast<char>(0x80 | ((code >> 6) & 0x3F));
            out += static_cast<char>(0x80 | (code & 0x3F));
        } else {
            out += static_cast<char>(0xF0 | (code >> 18));
            out += static_cast<char>(0x80 | ((code >> 12) & 0x3F));
            out += static_cast<char>(0x80 | ((code >> 6) & 0x3F));
            out += static_cast<char>(0x80 | (code & 0x3F));
        }
    }

    // At the opening quote; returns the string's UTF-8 with escapes resolved.
    std::string read_string() {
        const std::size_t start = position_++;
        std::string result;
        for (;;) {
            if (position_ >= text_.size()) fail(start, "", "not JSON: a string is not closed");
            const char c = text_[position_++];
            if (c == '"') return result;
            if (static_cast<unsigned char>(c) < 0x20)
                fail(position_ - 1, "", "not JSON: a control character in a string");
            if (c != '\\') {
                result += c;
                continue;
            }
            if (position_ >= text_.size()) fail(start, "", "not JSON: a string is not closed");
            const char escape = text_[position_++];
            switch (escape) {
                case '"':
                    result += '"';
                    break;
                case '\\':
                    result += '\\';
                    break;
                case '/':
                    result += '/';
                    break;
                case 'b':
                    result += '\b';
                    break;
                case 'f':
                    result += '\f';
                    break;
                case 'n':
                    result += '\n';
                    break;
                case 'r':
                    result += '\r';
                    break;
                case 't':
                    result += '\t';
                    break;
                case 'u': {
                    std::uint32_t code = read_hex4();
                    if (code >= 0xD800 && code < 0xDC00 && consume("\\u")) {
                        const std::uint32_t low = read_hex4();
                        if (low >= 0xDC00 && low < 0xE000)
                            code = 0x10000 + ((code - 0xD800) << 10) + (low - 0xDC00);
                    }
                    append_utf8(result, code);
                    break;
                }
                default:
                    fail(position_ - 2, "", std::string("not JSON: unknown escape \\") + escape);
            }
        }
    }

    std::string_view text_;
    std::string source_;
    std::size_t position_ = 0;
};

// What a message says was found: the value itself where it is short, else its type.
std::string found(const JsonValue& value) {
    switch (value.type) {
        case JsonValue::Type::null: return "null";
        case JsonValue::Type::boolean: return value.boolean ? "true" : "false";
        case JsonValue::Type::number: return detail::format_shortest(value.number);
        case JsonValue::Type::string:
            return value.text.size() > 40 ? "a string" : "\"" + value.text + "\"";
        case JsonValue::Type::array: return "a list of " + std::to_string(value.items.size());
        case JsonValue::Type::object: return "an object";
    }
    return "a value";
}

std::string all_keys() {
    std::string keys = "base, name";
    for (const StyleField& field : ExpressionStyle::fields()) keys += std::string(", ") + field.name;
    return keys;
}

std::string quoted_json(std::string_view text) {
    std::string result = "\"";
    for (const char c : text) {
        if (c == '"' || c == '\\') {
            result += '\\';
            result += c;
        } else if (static_cast<unsigned char>(c) < 0x20) {
            static const char kHex[] = "0123456789abcdef";
            result += "\\u00";
            result += kHex[(c >> 4) & 0xF];
            result += kHex[c & 0xF];
        } else {
            result += c;
        }
    }
    return result + "\"";
}

// Sets one field from its JSON value, or says what is wrong with the value's type.
void set_field(const detail::StyleFieldSpec& spec, const JsonValue& value, ExpressionStyle& style,
               const JsonReader& reader, const std::string& item) {
    const auto wrong_type = [&](const char* expected) {
        reader.fail(value.offset, item, std::string("expected ") + expected + ", found " + found(value));
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
            std::string("expected a style object {\"key\": value, ...}, found ") + found(document));
    }
    // "base" first, wherever it stands: the other keys change the style it names.
    ExpressionStyle style;
    for (std::size_t k = 0; k < document.members.size(); ++k) {
        const auto& [key, value] = document.members[k];
        if (key != "base") continue;
        if (value.type != JsonValue::Type::string) {
            reader.fail(value.offset, "key \"base\"",
                        std::string("expected \"normal\" or \"announcer\", found ") + found(value));
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
                reader.fail(value.offset, item, std::string("expected a string, found ") + found(value));
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
    std::string json = "{\n  \"name\": " + quoted_json(name);
    for (const detail::StyleFieldSpec& spec : detail::style_field_specs()) {
        json += ",\n  " + quoted_json(spec.field.name) + ": ";
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

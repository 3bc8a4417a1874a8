#include "common/json.hpp"

#include <cmath>
#include <cstdint>
#include <optional>

#include "common/number_format.hpp"
#include "common/text_location.hpp"
#include "talkface/errors.hpp"

namespace talkface::detail {

namespace {

// Deep enough for any document talkface reads; a bound keeps hostile input from exhausting the stack.
constexpr int kMaxDepth = 64;

void append_utf8(std::string& out, std::uint32_t code) {
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

}  // namespace

const JsonValue* JsonValue::find(std::string_view key) const {
    for (const auto& member : members) {
        if (member.first == key) return &member.second;
    }
    return nullptr;
}

JsonReader::JsonReader(std::string_view text, std::string source) : text_(text), source_(std::move(source)) {}

JsonValue JsonReader::read_document() {
    JsonValue value = read_value(0);
    skip_space();
    if (position_ < text_.size()) fail(position_, "", "unexpected text after the JSON value");
    return value;
}

void JsonReader::fail(std::size_t offset, const std::string& item, const std::string& problem) const {
    const TextLocation where = locate_offset(text_, static_cast<std::ptrdiff_t>(offset));
    throw ParseError(source_, where.line, where.column, item, problem);
}

void JsonReader::skip_space() {
    while (position_ < text_.size() && (text_[position_] == ' ' || text_[position_] == '\t' ||
                                        text_[position_] == '\n' || text_[position_] == '\r')) {
        ++position_;
    }
}

bool JsonReader::consume(std::string_view word) {
    if (text_.substr(position_, word.size()) != word) return false;
    position_ += word.size();
    return true;
}

void JsonReader::expect(char c, const char* context) {
    skip_space();
    if (position_ >= text_.size() || text_[position_] != c) {
        fail(position_, "", std::string("expected '") + c + "' " + context);
    }
    ++position_;
}

JsonValue JsonReader::read_value(int depth) {
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

void JsonReader::read_object(JsonValue& value, int depth) {
    value.type = JsonValue::Type::object;
    ++position_;
    skip_space();
    if (consume("}")) return;
    for (;;) {
        skip_space();
        const std::size_t key_offset = position_;
        if (position_ >= text_.size() || text_[position_] != '"') fail(position_, "", "expected a key in quotes");
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

void JsonReader::read_array(JsonValue& value, int depth) {
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

double JsonReader::read_number() {
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
    const std::optional<double> number = parse_double(text_.substr(start, end - start));
    if (!number || !std::isfinite(*number)) fail(start, "", "number out of range");
    position_ = end;
    return *number;
}

unsigned JsonReader::read_hex4() {
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

// At the opening quote; returns the string's UTF-8 with escapes resolved.
std::string JsonReader::read_string() {
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
                // A character outside the BMP is a surrogate pair; half of one is no character.
                const std::size_t escape_start = position_ - 2;
                std::uint32_t code = read_hex4();
                if (code >= 0xDC00 && code < 0xE000) fail(escape_start, "", "not JSON: a lone low surrogate");
                if (code >= 0xD800 && code < 0xDC00) {
                    if (!consume("\\u")) fail(escape_start, "", "not JSON: a high surrogate without its low half");
                    const std::uint32_t low = read_hex4();
                    if (low < 0xDC00 || low >= 0xE000)
                        fail(escape_start, "", "not JSON: a high surrogate without its low half");
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

std::string json_found(const JsonValue& value) {
    switch (value.type) {
        case JsonValue::Type::null: return "null";
        case JsonValue::Type::boolean: return value.boolean ? "true" : "false";
        case JsonValue::Type::number: return format_shortest(value.number);
        case JsonValue::Type::string:
            return value.text.size() > 40 ? "a string" : "\"" + value.text + "\"";
        case JsonValue::Type::array: return "a list of " + std::to_string(value.items.size());
        case JsonValue::Type::object: return "an object";
    }
    return "a value";
}

std::string json_quoted(std::string_view text) {
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

std::string json_number(double value) { return format_shortest(value); }

}  // namespace talkface::detail

#include "text/code_points.hpp"

#include <cstdio>

#include "talkface/errors.hpp"

namespace talkface::detail {

namespace {

// Appends `text`'s code points to `code_points` when given, up to the first fault, which it returns.
std::optional<Utf8Fault> decode_into(std::string_view text, std::vector<CodePoint>* code_points) {
    int line = 1;
    int column = 1;
    std::size_t offset = text.substr(0, 3) == "\xEF\xBB\xBF" ? 3 : 0;
    while (offset < text.size()) {
        const auto lead = static_cast<unsigned char>(text[offset]);
        std::size_t length = 1;
        char32_t value = lead;
        char32_t minimum = 0;
        if (lead >= 0xF0 && lead <= 0xF4) {
            length = 4;
            value = lead & 0x07U;
            minimum = 0x10000;
        } else if (lead >= 0xE0 && lead <= 0xEF) {
            length = 3;
            value = lead & 0x0FU;
            minimum = 0x800;
        } else if (lead >= 0xC2 && lead <= 0xDF) {
            length = 2;
            value = lead & 0x1FU;
            minimum = 0x80;
        } else if (lead >= 0x80) {
            length = 0;  // a continuation byte, or C0 C1 F5..FF, which never start a character
        }
        for (std::size_t i = 1; length > 0 && i < length; ++i) {
            const auto next = offset + i < text.size() ? static_cast<unsigned char>(text[offset + i]) : 0U;
            if ((next & 0xC0U) != 0x80U) {
                length = 0;
            } else {
                value = (value << 6) | (next & 0x3FU);
            }
        }
        // Overlong forms, UTF-16 surrogates and values past U+10FFFF are not characters.
        if (length == 0 || value < minimum || (value >= 0xD800 && value <= 0xDFFF) || value > 0x10FFFF) {
            return Utf8Fault{offset, line, column};
        }
        if (code_points != nullptr) {
            code_points->push_back({value, text.substr(offset, length), line, column});
        }
        offset += length;
        if (value == '\n') {
            ++line;
            column = 1;
        } else {
            ++column;
        }
    }
    return std::nullopt;
}

}  // namespace

std::vector<CodePoint> decode_utf8(std::string_view text, const std::string& source_name) {
    std::vector<CodePoint> code_points;
    code_points.reserve(text.size());
    if (const auto fault = decode_into(text, &code_points)) {
        char byte_text[8];
        std::snprintf(byte_text, sizeof byte_text, "0x%02X",
                      static_cast<unsigned>(text[fault->offset]) & 0xFFU);
        throw ParseError(source_name, fault->line, fault->column,
                         "byte offset " + std::to_string(fault->offset),
                         std::string("invalid UTF-8: the sequence starting with byte ") + byte_text +
                             " is not a character; save the transcript as UTF-8");
    }
    return code_points;
}

std::optional<Utf8Fault> find_utf8_fault(std::string_view text) {
    return decode_into(text, nullptr);
}

}  // namespace talkface::detail

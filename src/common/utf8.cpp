#include "common/utf8.hpp"

#include <string>

#include "talkface/errors.hpp"

namespace talkface::detail {

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

namespace {

// The byte order marks: U+FEFF in each Unicode encoding.
constexpr std::string_view kUtf16LeMark("\xFF\xFE", 2);
constexpr std::string_view kUtf16BeMark("\xFE\xFF", 2);
constexpr std::string_view kUtf32LeMark("\xFF\xFE\0\0", 4);
constexpr std::string_view kUtf32BeMark("\0\0\xFE\xFF", 4);

bool starts_with_mark(std::string_view text, std::string_view mark) {
    return text.substr(0, mark.size()) == mark;
}

// UTF-32 with its byte order mark (FF FE 00 00 or 00 00 FE FF): 4-byte units, each a code point.
std::string utf8_from_utf32(std::string_view text, bool is_big_endian, const std::string& source) {
    if (text.size() % 4 != 0) {
        throw ParseError(
            source, 0, 0, "",
            "not UTF-32: " + std::to_string(text.size()) +
                " bytes (the byte order mark's 4 included) is not a whole number of 32-bit units; "
                "was the file cut short?");
    }
    std::string out;
    for (std::size_t k = 4; k + 3 < text.size(); k += 4) {
        std::uint32_t code = 0;
        for (std::size_t b = 0; b < 4; ++b) {
            const auto byte = static_cast<unsigned char>(text[k + (is_big_endian ? b : 3 - b)]);
            code = code << 8 | byte;
        }
        if (code > 0x10FFFF || (code >= 0xD800 && code < 0xE000)) {
            throw ParseError(source, 0, 0, "byte offset " + std::to_string(k),
                             "not UTF-32: " + std::to_string(code) + " is not a Unicode character");
        }
        append_utf8(out, code);
    }
    return out;
}

}  // namespace

bool has_byte_order_mark(std::string_view text) {
    for (const std::string_view mark : {kUtf8Mark, kUtf16LeMark, kUtf16BeMark, kUtf32LeMark, kUtf32BeMark}) {
        if (starts_with_mark(text, mark)) return true;
    }
    return false;
}

std::string utf8_from_marked_text(std::string_view text, const std::string& source) {
    if (starts_with_mark(text, kUtf8Mark)) return std::string(text.substr(kUtf8Mark.size()));
    // UTF-32 LE's mark starts as UTF-16 LE's does: it is told first.
    if (starts_with_mark(text, kUtf32LeMark)) return utf8_from_utf32(text, false, source);
    if (starts_with_mark(text, kUtf32BeMark)) return utf8_from_utf32(text, true, source);
    const bool is_big_endian = starts_with_mark(text, kUtf16BeMark);
    const bool is_little_endian = starts_with_mark(text, kUtf16LeMark);
    if (!is_big_endian && !is_little_endian) return std::string(text);
    // UTF-16 is 2-byte units: an odd last byte is half of one, a file cut short or not UTF-16 at all.
    // Refused rather than dropped, so that nothing the user wrote goes missing without a word.
    if (text.size() % 2 != 0) {
        throw ParseError(source, 0, 0, "",
                         "not UTF-16: an odd number of bytes (" + std::to_string(text.size()) +
                             ", the byte order mark's 2 included), so the last byte is half a 16-bit unit; "
                             "was the file cut short?");
    }
    std::string out;
    const auto unit = [&](std::size_t k) -> std::uint32_t {
        const auto a = static_cast<unsigned char>(text[k]);
        const auto b = static_cast<unsigned char>(text[k + 1]);
        return is_big_endian ? (a << 8 | b) : (b << 8 | a);
    };
    for (std::size_t k = 2; k + 1 < text.size(); k += 2) {
        std::uint32_t code = unit(k);
        if (code >= 0xD800 && code < 0xDC00 && k + 3 < text.size()) {
            const std::uint32_t low = unit(k + 2);
            if (low >= 0xDC00 && low < 0xE000) {
                code = 0x10000 + ((code - 0xD800) << 10) + (low - 0xDC00);
                k += 2;
            }
        }
        if (code >= 0xD800 && code < 0xE000) throw ParseError(source, 0, 0, "", "not UTF-16: half a surrogate pair");
        append_utf8(out, code);
    }
    return out;
}

}  // namespace talkface::detail

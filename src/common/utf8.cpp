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

std::string utf8_from_marked_text(std::string_view text, const std::string& source) {
    if (text.size() >= 3 && text.substr(0, 3) == "\xEF\xBB\xBF") return std::string(text.substr(3));
    const bool is_big_endian = text.size() >= 2 && text[0] == '\xFE' && text[1] == '\xFF';
    const bool is_little_endian = text.size() >= 2 && text[0] == '\xFF' && text[1] == '\xFE';
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

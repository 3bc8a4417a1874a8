// A transcript as code points, each with its UTF-8 bytes and where it stands (line, column), the
// unit every reader of the text stage works on.
#ifndef TALKFACE_TEXT_CODE_POINTS_HPP
#define TALKFACE_TEXT_CODE_POINTS_HPP

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace talkface::detail {

struct CodePoint {
    char32_t value = 0;
    std::string_view text;  // its UTF-8 bytes in the transcript
    int line = 1;
    int column = 1;  // in characters
};

// Where a text stops being UTF-8: the first byte that does not start a character.
struct Utf8Fault {
    std::size_t offset = 0;  // in bytes, from the text's start
    int line = 1;
    int column = 1;  // in characters
};

// Decodes UTF-8 (a leading byte order mark skipped); views point into `text`.
// \throws talkface::ParseError naming `source_name`, the line, column and byte offset of the
//         first byte that does not start a character.
std::vector<CodePoint> decode_utf8(std::string_view text, const std::string& source_name);

// The first fault decode_utf8 would throw for, or none: for a caller that words the error itself
// (a transcript's reader names the legacy encodings the bytes could be).
std::optional<Utf8Fault> find_utf8_fault(std::string_view text);

// Full-width ASCII forms (！？，Ａ１％) behave as their ASCII counterparts, and so does the ratio sign
// ∶ (U+2236), which GB/T 15834 and news write for a colon between numbers (1∶0击败, 比例尺1∶50000).
// Subscript digits are digits: a chemical formula's (CO₂ H₂O, read as CO2 H2O are, C O 二) and a
// lesson's indices (x₁ x 一), as teachers read them (session 14; they were skipped with a warning).
inline char32_t ascii_form(char32_t c) {
    if (c == 0x2236) return ':';
    if (c >= 0x2080 && c <= 0x2089) return c - 0x2080 + '0';
    return c >= 0xFF01 && c <= 0xFF5E ? c - 0xFEE0 : c;
}

inline bool is_ascii_digit(char32_t c) {
    return c >= '0' && c <= '9';
}

// Whether c, folded to its digit by ascii_form, was written as a subscript digit (₀ ... ₉: log₂8's base,
// KMnO₄'s count, x₁'s index): UTF-8's E2 82 80 to E2 82 89.
inline bool is_subscript_digit(const CodePoint& c) {
    return c.text.size() == 3 && c.text[0] == '\xE2' && c.text[1] == '\x82' && is_ascii_digit(c.value);
}

inline bool is_ascii_capital(char32_t c) {
    return c >= 'A' && c <= 'Z';
}

inline bool is_ascii_letter(char32_t c) {
    return is_ascii_capital(c) || (c >= 'a' && c <= 'z');
}

// `word` with its ASCII capitals in small letters (the tables of words, domains and suffixes are
// kept so; every other byte, UTF-8 included, as it is).
inline std::string ascii_lower_case(std::string_view word) {
    std::string lower(word);
    for (char& letter : lower)
        if (is_ascii_capital(static_cast<unsigned char>(letter)))
            letter = static_cast<char>(letter - 'A' + 'a');
    return lower;
}

}  // namespace talkface::detail

#endif

#include "text/typed_names.hpp"

#include <algorithm>
#include <string>

#include "text/written_number_scan.hpp"

namespace talkface::detail {

namespace {

char32_t typed_at(const std::vector<CodePoint>& text, std::size_t i) {
    return i < text.size() ? text[i].value : 0;
}

bool is_alphanumeric(char32_t c) {
    return is_ascii_letter(c) || is_ascii_digit(c);
}

bool is_hex_digit(char32_t c) {
    return is_ascii_digit(c) || (c >= 'a' && c <= 'f') || (c >= 'A' && c <= 'F');
}

// Past a name inside a path or joined by underscores: letters, digits, and a dot, a hyphen or an
// underscore with a letter or a digit after it (setup.exe, my-file); a space ends it.
std::size_t name_end(const std::vector<CodePoint>& text, std::size_t i, bool takes_underscore) {
    while (is_alphanumeric(typed_at(text, i)) || ((typed_at(text, i) == '.' || typed_at(text, i) == '-' ||
                                                   (takes_underscore && typed_at(text, i) == '_')) &&
                                                  is_alphanumeric(typed_at(text, i + 1)))) {
        ++i;
    }
    return i;
}

// The names of a path after its first separator at text[i], each after a separator; returns the end.
std::size_t append_path(std::vector<AddressPart>& parts, const std::vector<CodePoint>& text, std::size_t i,
                        char32_t separator, const char* said_separator) {
    while (typed_at(text, i) == separator && is_alphanumeric(typed_at(text, i + 1))) {
        parts.push_back({AddressPart::Kind::words, said_separator});
        const auto end = name_end(text, i + 1, true);
        append_address_parts(parts, text, i + 1, end);
        i = end;
    }
    return i;
}

std::optional<WebAddress> read_windows_path(const std::vector<CodePoint>& text, std::size_t start) {
    if (!is_ascii_letter(typed_at(text, start)) || typed_at(text, start + 1) != ':' ||
        typed_at(text, start + 2) != '\\')
        return std::nullopt;
    WebAddress path;
    path.parts.push_back({AddressPart::Kind::letters, std::string(1, static_cast<char>(text[start].value))});
    path.parts.push_back({AddressPart::Kind::words, "冒号"});
    if (!is_alphanumeric(typed_at(text, start + 3))) {
        path.parts.push_back({AddressPart::Kind::words, "反斜杠"});
        path.end = start + 3;
        return path;
    }
    path.end = append_path(path.parts, text, start + 2, '\\', "反斜杠");
    return path;
}

std::optional<WebAddress> read_unix_path(const std::vector<CodePoint>& text, std::size_t start) {
    if (typed_at(text, start) != '/' || !is_ascii_letter(typed_at(text, start + 1))) return std::nullopt;
    WebAddress path;
    path.end = append_path(path.parts, text, start, '/', "斜杠");
    constexpr std::size_t kFewestNames = 2;
    const auto names = static_cast<std::size_t>(std::count_if(
        path.parts.begin(), path.parts.end(), [](const AddressPart& part) { return part.text == "斜杠"; }));
    if (names < kFewestNames) return std::nullopt;
    return path;
}

std::optional<WebAddress> read_underscored_name(const std::vector<CodePoint>& text, std::size_t start) {
    if (!is_ascii_letter(typed_at(text, start))) return std::nullopt;
    const auto first_end = name_end(text, start, false);
    constexpr std::size_t kShortestFirstPart = 2;
    if (first_end - start < kShortestFirstPart || typed_at(text, first_end) != '_' ||
        !is_alphanumeric(typed_at(text, first_end + 1)))
        return std::nullopt;
    WebAddress name;
    name.end = name_end(text, start, true);
    // A function's argument after it (log_3 9, log_2(8), log_2 n: a number or a variable of one letter)
    // makes it a formula's base, no typed name.
    const auto next = typed_at(text, name.end);
    const auto argument = typed_at(text, name.end + 1);
    const bool is_variable = is_ascii_letter(argument) && !is_alphanumeric(typed_at(text, name.end + 2));
    if (next == '(' || (next == ' ' && (is_ascii_digit(argument) || is_variable))) return std::nullopt;
    append_address_parts(name.parts, text, start, name.end);
    return name;
}

// 0x and hexadecimal digits, each digit and letter said alone: a code's, not a number's or a word's.
std::optional<WebAddress> read_hex_number(const std::vector<CodePoint>& text, std::size_t start) {
    if (typed_at(text, start) != '0' || !is_one_of(typed_at(text, start + 1), U"xX") ||
        !is_hex_digit(typed_at(text, start + 2)))
        return std::nullopt;
    auto end = start + 2;
    while (is_hex_digit(typed_at(text, end))) ++end;
    if (is_alphanumeric(typed_at(text, end))) return std::nullopt;
    WebAddress code;
    code.end = end;
    code.parts.push_back({AddressPart::Kind::digits, "0"});
    for (auto i = start + 1; i < end; ++i) {
        const bool letter = is_ascii_letter(text[i].value);
        const auto c = static_cast<char>(text[i].value);
        if (!letter && code.parts.back().kind == AddressPart::Kind::digits) {
            code.parts.back().text += c;
            continue;
        }
        code.parts.push_back(
            {letter ? AddressPart::Kind::letters : AddressPart::Kind::digits, std::string(1, c)});
    }
    return code;
}

}  // namespace

std::optional<WebAddress> read_typed_name(const std::vector<CodePoint>& text, std::size_t start) {
    const auto previous = start == 0 ? 0 : text[start - 1].value;
    if (is_alphanumeric(previous) || is_one_of(previous, U"./\\:_-")) return std::nullopt;
    if (auto path = read_windows_path(text, start)) return path;
    if (auto path = read_unix_path(text, start)) return path;
    if (auto name = read_underscored_name(text, start)) return name;
    return read_hex_number(text, start);
}

}  // namespace talkface::detail

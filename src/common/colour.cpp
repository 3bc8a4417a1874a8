#include <cctype>
#include <cstdio>

#include "talkface/errors.hpp"
#include "talkface/types.hpp"

namespace talkface {
inline namespace v0 {

std::string to_hex(Rgb colour) {
    char text[8];
    std::snprintf(text, sizeof text, "#%02x%02x%02x", colour.r, colour.g, colour.b);
    return text;
}

Rgb rgb_from_hex(std::string_view text, const std::string& parameter) {
    auto fail = [&] {
        throw InvalidArgument(parameter, "expected a colour as #rrggbb or #rgb, found \"" +
                                             std::string(text) + "\"");
    };
    if (text.size() != 7 && text.size() != 4) fail();
    if (text[0] != '#') fail();
    auto nibble = [&](char c) -> int {
        if (!std::isxdigit(static_cast<unsigned char>(c))) fail();
        return std::isdigit(static_cast<unsigned char>(c)) ? c - '0' : (std::tolower(c) - 'a' + 10);
    };
    auto channel = [&](std::size_t index) -> std::uint8_t {
        if (text.size() == 4) return static_cast<std::uint8_t>(nibble(text[index + 1]) * 17);
        return static_cast<std::uint8_t>(nibble(text[2 * index + 1]) * 16 + nibble(text[2 * index + 2]));
    };
    return Rgb{channel(0), channel(1), channel(2)};
}

}  // namespace v0
}  // namespace talkface

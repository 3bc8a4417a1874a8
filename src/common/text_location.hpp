// Turns a byte offset into a 1-based line:column, for every parser's error messages
// (pugixml reports offsets only).
#ifndef TALKFACE_COMMON_TEXT_LOCATION_HPP
#define TALKFACE_COMMON_TEXT_LOCATION_HPP

#include <cstddef>
#include <string_view>

namespace talkface::detail {

struct TextLocation {
    int line = 0;    // 1-based
    int column = 0;  // 1-based, in bytes
};

// The line and column of `offset` in `text`; an offset past the end gives the end's location.
TextLocation locate_offset(std::string_view text, std::ptrdiff_t offset);

}  // namespace talkface::detail

#endif

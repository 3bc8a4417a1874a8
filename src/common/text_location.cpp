#include "common/text_location.hpp"

#include <algorithm>

namespace talkface::detail {

TextLocation locate_offset(std::string_view text, std::ptrdiff_t offset) {
    const auto end = static_cast<std::size_t>(std::clamp<std::ptrdiff_t>(
        offset, 0, static_cast<std::ptrdiff_t>(text.size())));
    TextLocation location{1, 1};
    for (std::size_t i = 0; i < end; ++i) {
        if (text[i] == '\n') {
            ++location.line;
            location.column = 1;
        } else {
            ++location.column;
        }
    }
    return location;
}

}  // namespace talkface::detail

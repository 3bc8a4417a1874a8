// Whether a text starts or ends with another (C++20's string_view members, which C++17 lacks): a
// file name's suffix, a file's first line, the words before or after a number in its clause.
#ifndef TALKFACE_COMMON_STRING_ENDS_HPP
#define TALKFACE_COMMON_STRING_ENDS_HPP

#include <string_view>

namespace talkface::detail {

inline bool starts_with(std::string_view text, std::string_view start) {
    return text.substr(0, start.size()) == start;
}

inline bool ends_with(std::string_view text, std::string_view end) {
    return text.size() >= end.size() && text.substr(text.size() - end.size()) == end;
}

}  // namespace talkface::detail

#endif

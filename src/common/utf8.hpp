// UTF-8 out: a code point appended as its bytes (the JSON reader's \u escapes, Praat's UTF-16 files).
#ifndef TALKFACE_COMMON_UTF8_HPP
#define TALKFACE_COMMON_UTF8_HPP

#include <cstdint>
#include <string>

namespace talkface::detail {

// Appends `code` (at most U+10FFFF, not a surrogate) to `out` as UTF-8.
void append_utf8(std::string& out, std::uint32_t code);

}  // namespace talkface::detail

#endif

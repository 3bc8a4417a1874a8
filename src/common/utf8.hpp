// UTF-8 out: a code point appended as its bytes (the JSON reader's \u escapes), and a text file's
// bytes as UTF-8 whichever Unicode encoding its byte order mark names (Praat's and Windows' UTF-16,
// UTF-32).
#ifndef TALKFACE_COMMON_UTF8_HPP
#define TALKFACE_COMMON_UTF8_HPP

#include <cstdint>
#include <string>
#include <string_view>

namespace talkface::detail {

// Appends `code` (at most U+10FFFF, not a surrogate) to `out` as UTF-8.
void append_utf8(std::string& out, std::uint32_t code);

// UTF-8's byte order mark (U+FEFF), which Windows' Notepad writes before UTF-8 text.
inline constexpr std::string_view kUtf8Mark("\xEF\xBB\xBF", 3);

// Whether `text` starts with a byte order mark (UTF-8, UTF-16 or UTF-32, either byte order), which
// names its encoding.
bool has_byte_order_mark(std::string_view text);

// A text file's bytes as UTF-8: a UTF-8 byte order mark dropped; UTF-16 or UTF-32 with its byte
// order mark (little or big endian: what Praat writes for a text that is not ASCII, Windows
// Notepad's "Unicode" and "Unicode big endian") converted; anything else as it is.
// \throws talkface::ParseError naming `source` for UTF-16 with half a surrogate pair or an odd
// number of bytes (its last byte half a unit: once dropped without a word, refused since session 14),
// and for UTF-32 not in whole units or with a unit that is no character.
std::string utf8_from_marked_text(std::string_view text, const std::string& source);

}  // namespace talkface::detail

#endif

// A transcript file's bytes as UTF-8, whatever its writer saved it in: a byte order mark's Unicode
// encoding, an encoding the user names (a Chinese Windows' GB18030, a Taiwanese one's Big5), else
// UTF-8. Bytes that are not UTF-8 are never guessed into text silently: the error says which
// encodings read them, with the start of the text each gives, so the user can choose.
#ifndef TALKFACE_TEXT_TRANSCRIPT_ENCODING_HPP
#define TALKFACE_TEXT_TRANSCRIPT_ENCODING_HPP

#include <string>
#include <string_view>

namespace talkface::detail {

// `bytes` as UTF-8. A byte order mark (UTF-8, UTF-16 or UTF-32, either byte order) names the
// encoding, whatever `encoding` says; otherwise `encoding` does: any name glibc's iconv knows
// ("gb18030", "gbk", "big5", "big5-hkscs", "utf-16le", ...), case aside; "" means UTF-8.
// \throws talkface::InvalidArgument naming "encoding" for a name iconv does not know;
//         talkface::ParseError naming `source`, the line and column (of the text read so far) and
//         the byte offset where the bytes stop being text in that encoding. Bytes that are not
//         UTF-8 when no encoding is named: the message names the encodings that read them as
//         Chinese text (GB18030, Big5, UTF-16 without its mark), likeliest first, each with the
//         start of what it reads.
std::string transcript_utf8(std::string_view bytes, const std::string& encoding, const std::string& source);

}  // namespace talkface::detail

#endif

// Text helpers for the web page: escaping, base64 data: URIs, URLs a page may link to.
#ifndef TALKFACE_RENDER_HTML_TEXT_HPP
#define TALKFACE_RENDER_HTML_TEXT_HPP

#include <string>
#include <string_view>

namespace talkface {
inline namespace v0 {

// `text` with & < > " ' replaced by character references, safe inside HTML or XML text and quoted
// attribute values.
std::string escape_html(std::string_view text);

}  // namespace v0

namespace detail {

// RFC 4648 base64 of `bytes`, padded, on one line.
std::string base64(std::string_view bytes);

// "data:<mime>;base64,<...>" for the bytes.
std::string data_uri(const std::string& mime_type, std::string_view bytes);

// The MIME type of an audio or image file, told by its extension (case ignored); empty if unknown.
std::string audio_mime_type(const std::string& path);
std::string image_mime_type(const std::string& path);

// `url` with every byte outside RFC 3986's unreserved and reserved characters percent-encoded
// (spaces, non-ASCII, quotes), so it can stand in an attribute as one URL.
std::string percent_encode_url(std::string_view url);

// Throws talkface::InvalidArgument naming `parameter` unless `url` is relative or uses http:,
// https: or mailto: (javascript:, data: and the like could run script), and has no control
// characters (which browsers drop, so "java\tscript:" would still be a scheme).
void require_safe_link(std::string_view url, const std::string& parameter);

}  // namespace detail
}  // namespace talkface

#endif

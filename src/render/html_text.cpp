#include "render/html_text.hpp"

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <string>

#include "common/markup_escape.hpp"
#include "talkface/errors.hpp"
#include "talkface/web_page.hpp"

namespace talkface {
inline namespace v0 {

std::string escape_html(std::string_view text) { return detail::escape_markup(text, detail::QuoteEscape::html); }

}  // namespace v0
}  // namespace talkface

namespace talkface::detail {

namespace {

std::string lower_extension(const std::string& path) {
    const std::size_t slash = path.find_last_of("/\\");
    const std::size_t dot = path.rfind('.');
    if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return {};
    std::string extension = path.substr(dot + 1);
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return extension;
}

}  // namespace

std::string base64(std::string_view bytes) {
    static constexpr char kAlphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string text;
    text.reserve((bytes.size() + 2) / 3 * 4);
    std::size_t i = 0;
    for (; i + 2 < bytes.size(); i += 3) {
        const std::uint32_t n = static_cast<std::uint32_t>(static_cast<unsigned char>(bytes[i])) << 16 |
                                static_cast<std::uint32_t>(static_cast<unsigned char>(bytes[i + 1])) << 8 |
                                static_cast<unsigned char>(bytes[i + 2]);
        text += kAlphabet[n >> 18 & 63];
        text += kAlphabet[n >> 12 & 63];
        text += kAlphabet[n >> 6 & 63];
        text += kAlphabet[n & 63];
    }
    if (i < bytes.size()) {
        std::uint32_t n = static_cast<std::uint32_t>(static_cast<unsigned char>(bytes[i])) << 16;
        if (i + 1 < bytes.size()) n |= static_cast<std::uint32_t>(static_cast<unsigned char>(bytes[i + 1])) << 8;
        text += kAlphabet[n >> 18 & 63];
        text += kAlphabet[n >> 12 & 63];
        text += i + 1 < bytes.size() ? kAlphabet[n >> 6 & 63] : '=';
        text += '=';
    }
    return text;
}

std::string data_uri(const std::string& mime_type, std::string_view bytes) {
    return "data:" + mime_type + ";base64," + base64(bytes);
}

std::string audio_mime_type(const std::string& path) {
    const std::string extension = lower_extension(path);
    if (extension == "ogg" || extension == "oga" || extension == "opus") return "audio/ogg";
    if (extension == "wav") return "audio/wav";
    if (extension == "flac") return "audio/flac";
    if (extension == "mp3") return "audio/mpeg";
    if (extension == "m4a") return "audio/mp4";
    return {};
}

std::string image_mime_type(const std::string& path) {
    const std::string extension = lower_extension(path);
    if (extension == "png") return "image/png";
    if (extension == "jpg" || extension == "jpeg") return "image/jpeg";
    if (extension == "gif") return "image/gif";
    if (extension == "webp") return "image/webp";
    if (extension == "svg") return "image/svg+xml";
    return {};
}

std::string percent_encode_url(std::string_view url) {
    static constexpr char kHex[] = "0123456789ABCDEF";
    std::string encoded;
    for (const char c : url) {
        const auto byte = static_cast<unsigned char>(c);
        const bool keep = std::isalnum(byte) != 0 ||
                          std::string_view("-._~:/?#[]@!$&()*+,;=%").find(c) != std::string_view::npos;
        if (keep && byte < 0x80) {
            encoded += c;
        } else {
            encoded += '%';
            encoded += kHex[byte >> 4];
            encoded += kHex[byte & 15];
        }
    }
    return encoded;
}

void require_safe_link(std::string_view url, const std::string& parameter) {
    for (const char c : url) {
        const auto byte = static_cast<unsigned char>(c);
        if (byte < 0x20 || byte == 0x7f) {
            throw InvalidArgument(parameter, "the URL holds a control character; write it percent-encoded");
        }
    }
    const std::size_t colon = url.find(':');
    const std::size_t path_start = url.find_first_of("/?#");
    if (colon == std::string_view::npos || (path_start != std::string_view::npos && path_start < colon)) return;
    std::string scheme(url.substr(0, colon));
    std::transform(scheme.begin(), scheme.end(), scheme.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (scheme != "http" && scheme != "https" && scheme != "mailto") {
        throw InvalidArgument(parameter, "expected an http:, https:, mailto: or relative URL, found the scheme \"" +
                                             std::string(url.substr(0, colon)) + ":\"");
    }
}

}  // namespace talkface::detail

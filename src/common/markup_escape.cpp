#include "common/markup_escape.hpp"

namespace talkface::detail {

std::string escape_markup(std::string_view text, QuoteEscape quotes) {
    std::string escaped;
    escaped.reserve(text.size() + text.size() / 8);
    for (const char c : text) {
        switch (c) {
            case '&': escaped += "&amp;"; continue;
            case '<': escaped += "&lt;"; continue;
            case '>': escaped += "&gt;"; continue;
            case '"':
                if (quotes != QuoteEscape::none) {
                    escaped += "&quot;";
                    continue;
                }
                break;
            case '\'':
                if (quotes != QuoteEscape::none) {
                    escaped += quotes == QuoteEscape::html ? "&#39;" : "&apos;";
                    continue;
                }
                break;
            default: break;
        }
        escaped += c;
    }
    return escaped;
}

}  // namespace talkface::detail

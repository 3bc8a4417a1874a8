#include "text/phonetic_spelling.hpp"

namespace talkface::detail {

namespace {

// A sign IPA writes and an alphabet does not: IPA's extensions and its modifier letters (ə ɪ ʃ ʒ ŋ ˈ ˌ ː),
// and the letters it shares with other scripts (æ ð ŋ θ).
bool is_phonetic_sign(char32_t c) {
    return (c >= 0x250 && c <= 0x2FF) || c == 0xE6 || c == 0xF0 || c == 0x14B || c == 0x3B8;
}

}  // namespace

std::optional<std::size_t> past_phonetic_spelling(const std::vector<CodePoint>& text, std::size_t start) {
    if (start >= text.size()) return std::nullopt;
    const auto open = text[start].value;
    if (open != '[' && open != '/') return std::nullopt;
    const char32_t close = open == '[' ? ']' : '/';
    constexpr std::size_t kLongest = 40;  // code points: a phrase's spelling
    bool has_phonetic_sign = false;
    for (auto k = start + 1; k < text.size() && k <= start + kLongest; ++k) {
        const auto c = text[k].value;
        if (c == close) return has_phonetic_sign ? std::optional<std::size_t>(k + 1) : std::nullopt;
        const bool is_letter = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z');
        if (is_phonetic_sign(c)) {
            has_phonetic_sign = true;
        } else if (!is_letter && c != ' ' && c != '.' && c != ':' && c != '(' && c != ')') {
            return std::nullopt;
        }
    }
    return std::nullopt;
}

}  // namespace talkface::detail

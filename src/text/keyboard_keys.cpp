#include "text/keyboard_keys.hpp"

#include <string>

#include "text/written_number_scan.hpp"

namespace talkface::detail {

namespace {

std::string lower_letters(const std::vector<CodePoint>& text, std::size_t first, std::size_t end) {
    std::string word;
    for (auto i = first; i < end; ++i) word += static_cast<char>(text[i].value);
    return ascii_lower_case(word);
}

// Whether the letters right before text[end] are a modifier key's name.
bool ends_with_modifier(const std::vector<CodePoint>& text, std::size_t end) {
    auto first = end;
    while (first > 0 && is_ascii_letter(text[first - 1].value)) --first;
    if (first == end || (first > 0 && is_ascii_digit(text[first - 1].value))) return false;
    const auto word = lower_letters(text, first, end);
    for (const std::string_view modifier :
         {"ctrl", "control", "shift", "alt", "cmd", "command", "win", "fn", "option"})
        if (word == modifier) return true;
    return false;
}

}  // namespace

std::string_view key_sign_word(char32_t c) {
    switch (c) {
        case 0x2318:
            return "command";  // ⌘
        case 0x2325:
            return "option";  // ⌥
        case 0x21E7:
            return "shift";  // ⇧
        case 0x2303:
            return "control";  // ⌃
        default:
            return {};
    }
}

std::optional<std::string_view> key_name_word(const std::vector<CodePoint>& text, std::size_t start,
                                              std::size_t end) {
    const auto word = lower_letters(text, start, end);
    if (word == "ctrl") return "control";
    const bool in_shortcut = value_at(text, end) == '+' || (start > 0 && text[start - 1].value == '+') ||
                             value_at(text, end) == U'键' || value_at(text, end) == U'鍵';
    if (word == "cmd" && in_shortcut) return "command";
    return std::nullopt;
}

bool joins_shortcut_keys(const std::vector<CodePoint>& text, std::size_t i) {
    if (value_at(text, i) != '+' || i == 0) return false;
    const auto left = text[i - 1].value;
    const auto right = value_at(text, i + 1);
    const bool key_right =
        is_ascii_letter(right) || is_ascii_digit(right) || is_han(right) || !key_sign_word(right).empty();
    if (!key_sign_word(left).empty()) return key_right;
    if (!key_sign_word(right).empty()) return is_ascii_letter(left) || is_ascii_digit(left);
    return ends_with_modifier(text, i) && key_right;
}

}  // namespace talkface::detail

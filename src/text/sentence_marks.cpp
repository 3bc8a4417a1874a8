#include "text/sentence_marks.hpp"

#include <string_view>

#include "text/written_number_scan.hpp"

namespace talkface::detail {

bool is_space(char32_t c) {
    return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' || c == '\f' || c == 0xA0 ||
           c == 0x3000 || c == 0xFEFF;
}

bool has_blank_line(std::string_view space) {
    const std::size_t first = space.find('\n');
    if (first == std::string_view::npos) return false;
    return space.find('\n', first + 1) != std::string_view::npos;
}

bool ends_sentence(char32_t c) {
    const auto a = ascii_form(c);
    return a == '.' || a == '!' || a == '?' || a == ';' || c == 0x3002 /*。*/ || c == 0xFF61 /*｡*/ ||
           c == 0x2026 /*…*/ || c == 0x22EF /*⋯*/;
}

bool marks_pause(char32_t c) {
    const auto a = ascii_form(c);
    return a == ',' || a == ':' || c == 0x3001 /*、*/ || c == 0xFF64 /*､*/ || c == 0xFE50 || c == 0xFE51 ||
           c == 0xFE55;
}

bool closes_quote(char32_t c) {
    const auto a = ascii_form(c);
    return a == '"' || a == '\'' || a == ')' || a == ']' || a == '}' || c == 0x300D /*」*/ ||
           c == 0x300F /*』*/ || c == 0x201D /*”*/ || c == 0x2019 /*’*/ || c == 0x300B /*》*/ ||
           c == 0x3009 /*〉*/ || c == 0x3011 /*】*/ || c == 0x3015 /*〕*/ || c == 0x3017 /*〗*/ ||
           c == 0xFE42 || c == 0xFE44;
}

bool is_silent_punctuation(char32_t c) {
    const auto a = ascii_form(c);
    if (a < 0x80) {
        // A set's ASCII braces (opens_set: a fix's are read before); a full-width one is text, reported.
        if (c == '{' || c == '}') return true;
        return a == '"' || a == '\'' || a == '(' || a == ')' || a == '[' || a == ']' || a == '<' ||
               a == '>' || a == '-' || a == '_' || a == '/' || a == '\\' || a == '`' || a == '|' || a == '~';
    }
    return c == 0xB7 /*·*/ || c == 0x30FB /*・*/ || (c >= 0x2010 && c <= 0x2027) ||
           (c >= 0x2032 && c <= 0x205E) || (c >= 0x3000 && c <= 0x303F) || (c >= 0xFE10 && c <= 0xFE1F) ||
           (c >= 0xFE30 && c <= 0xFE6B) || (c >= 0xFF5F && c <= 0xFF65);
}

bool marks_choice(const std::vector<CodePoint>& text, std::size_t i) {
    if (ascii_form(text[i].value) != '.' || i == 0 || i + 1 >= text.size()) return false;
    const auto letter = ascii_form(text[i - 1].value);
    if (letter < 'A' || letter > 'H') return false;
    if (i >= 2) {
        const auto before = ascii_form(text[i - 2].value);
        if ((before >= 'A' && before <= 'Z') || (before >= 'a' && before <= 'z') ||
            (before >= '0' && before <= '9'))
            return false;
    }
    const auto next = text[i + 1].value;
    return next >= 0x3400 && next <= 0x9FFF;
}

bool marks_list_item(const std::vector<CodePoint>& text, std::size_t i) {
    constexpr std::size_t kMostDigits = 2;
    if (ascii_form(text[i].value) != '.' || i == 0 || i + 1 >= text.size()) return false;
    auto k = i;
    while (k > 0 && i - k < kMostDigits + 1 && ascii_form(text[k - 1].value) >= '0' &&
           ascii_form(text[k - 1].value) <= '9')
        --k;
    if (k == i || i - k > kMostDigits) return false;
    if (k > 0) {
        const auto before = ascii_form(text[k - 1].value);
        if (!(before == '\n' || before == ' ' || before == ':' || before == 0x3000)) return false;
    }
    const auto next = text[i + 1].value;
    return next >= 0x3400 && next <= 0x9FFF;
}

bool marks_lineage_dot(const std::vector<CodePoint>& text, std::size_t i) {
    if (ascii_form(text[i].value) != '.' || !detail::is_digit_at(text, i + 1)) return false;
    auto k = i;
    while (k > 0 && is_ascii_capital(text[k - 1].value)) --k;
    return i - k >= 2 && (k == 0 || !is_ascii_letter(text[k - 1].value));
}

bool marks_initialism_dot(const std::vector<CodePoint>& text, std::size_t i) {
    const auto is_dot = [&](std::size_t k) { return k < text.size() && ascii_form(text[k].value) == '.'; };
    // A letter alone before the dot at k: no letter or digit right before it.
    const auto initial_before = [&](std::size_t k) {
        if (k == 0 || !is_ascii_letter(text[k - 1].value)) return false;
        return k == 1 || !(is_ascii_letter(text[k - 2].value) || detail::is_digit_at(text, k - 2));
    };
    if (!is_dot(i) || !initial_before(i)) return false;
    const bool another_after =
        i + 2 < text.size() && is_ascii_letter(text[i + 1].value) && is_dot(i + 2) && initial_before(i + 2);
    const bool another_before = i >= 2 && is_dot(i - 2) && initial_before(i - 2);
    return another_after || another_before;
}

bool marks_topic(const std::vector<CodePoint>& text, std::size_t i) {
    constexpr std::size_t kLongestTopic = 30;  // code points between the two marks
    const auto is_mark = [&](std::size_t k) { return ascii_form(text[k].value) == '#'; };
    const auto breaks_topic = [&](std::size_t k) {
        const auto c = text[k].value;
        return c == '\n' || c == ' ' || c == 0x3000 || ends_sentence(c);
    };
    for (std::size_t k = i + 1; k < text.size() && k <= i + kLongestTopic + 1 && !breaks_topic(k); ++k)
        if (is_mark(k)) return k > i + 1;
    for (std::size_t k = i; k-- > 0 && k + kLongestTopic + 1 >= i && !breaks_topic(k);)
        if (is_mark(k)) return k + 1 < i;
    return false;
}

bool marks_ticker(const std::vector<CodePoint>& text, std::size_t i) {
    constexpr std::size_t kLongestTicker = 5;
    const auto is_word_character = [&](std::size_t k) {
        const auto c = ascii_form(text[k].value);
        return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9');
    };
    if (ascii_form(text[i].value) != '$' || (i > 0 && is_word_character(i - 1))) return false;
    auto k = i + 1;
    while (k < text.size() && ascii_form(text[k].value) >= 'A' && ascii_form(text[k].value) <= 'Z') ++k;
    return k > i + 1 && k - i - 1 <= kLongestTicker && (k == text.size() || !is_word_character(k));
}

bool marks_screen_mode(const std::vector<CodePoint>& text, std::size_t i) {
    if (ascii_form(text[i].value) != '@' || i < 2 || !detail::is_digit_at(text, i + 1)) return false;
    return detail::is_one_of(ascii_form(text[i - 1].value), U"KkPp") && detail::is_digit_at(text, i - 2);
}

bool marks_bullet(const std::vector<CodePoint>& text, std::size_t i) {
    constexpr char32_t kFirstShape = 0x25A0;
    constexpr char32_t kLastShape = 0x25FF;
    constexpr char32_t kTriangle = 0x25B3;
    const auto c = text[i].value;
    if (c < kFirstShape || c > kLastShape || c == kTriangle) return false;
    for (auto k = i; k-- > 0;) {
        if (text[k].value == '\n') return true;
        if (!is_space(text[k].value)) return false;
    }
    return true;
}

bool opens_set(const std::vector<CodePoint>& text, std::size_t i) {
    if (i >= text.size() || text[i].value != '{') return false;
    constexpr std::size_t kLongest = 40;
    bool lists = false;
    for (auto k = i + 1; k < text.size() && k <= i + kLongest; ++k) {
        const auto c = ascii_form(text[k].value);
        if (c == '}') return lists;
        const bool alphanumeric = (c >= '0' && c <= '9') || (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z');
        if (c == ',' || c == '|') {
            lists = true;
        } else if (!alphanumeric && c != ' ' &&
                   std::u32string_view(U".+-<>=").find(c) == std::u32string_view::npos) {
            return false;
        }
    }
    return false;
}

}  // namespace talkface::detail

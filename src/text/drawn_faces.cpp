#include "text/drawn_faces.hpp"

#include <algorithm>

namespace talkface::detail {

namespace {

// A pictograph; the stars ★ ☆ are a rating's (★★★★☆ 四星) and the dingbats' circled digits ❶ ➀ a list's
// numbers, both read.
bool is_emoji(char32_t c) {
    constexpr char32_t kBlackStar = 0x2605;
    constexpr char32_t kWhiteStar = 0x2606;
    const bool is_circled_digit = c >= 0x2776 && c <= 0x2793;
    return (c >= 0x1F000 && c <= 0x1FAFF) ||
           (c >= 0x2600 && c <= 0x27BF && c != kBlackStar && c != kWhiteStar && !is_circled_digit) ||
           c == 0x2B50 /*⭐*/ || c == 0x2B55 /*⭕*/;
}

// What joins an emoji to the next or changes it: the variation selectors (☀️), the zero-width joiner
// (👨‍👩‍👧), a keycap's mark and the tags of a flag.
bool joins_emoji(char32_t c) {
    return c == 0xFE0F || c == 0xFE0E || c == 0x200D || c == 0x20E3 || (c >= 0xE0020 && c <= 0xE007F);
}

bool is_han(char32_t c) {
    return (c >= 0x4E00 && c <= 0x9FFF) || (c >= 0x3400 && c <= 0x4DBF) || (c >= 0x20000 && c <= 0x2FFFF);
}

bool is_letter_or_digit(char32_t c) {
    return (c >= '0' && c <= '9') || (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z');
}

// Marks that end or pause a sentence, or quote: text's punctuation, which a face's neighbours never are.
bool is_text_punctuation(char32_t c) {
    constexpr std::u32string_view kMarks =
        U".,!?:;\"'\u3002\u3001\u2026\u201C\u201D\u2018\u2019\u300C\u300D~\u301C";
    return kMarks.find(c) != std::u32string_view::npos;
}

bool is_space(char32_t c) {
    return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == 0x3000;
}

// A sign a face may be drawn with beside its bracket: not a word's (a Chinese character, a Latin letter,
// a digit), not text's punctuation, not a space.
bool is_face_sign(char32_t c) {
    return c != 0 && !is_space(c) && !is_han(c) && !is_letter_or_digit(c) && !is_text_punctuation(c) &&
           c != '(' && c != ')';
}

// A sign that may touch a face outside its bracket (Σ before it, ﾉ♡ ╯︵ after it, the table ┻━┻): a face sign
// that is not ASCII and none of the signs a written form reads (² ° ± × ½ of Latin-1, superscripts and
// currencies, ℃, Roman numerals and fractions, arrows, maths, circled numbers), so x²(^_^) keeps its 平方.
bool is_touching_sign(char32_t c) {
    const bool is_read_sign = c < 0x100 || (c >= 0x2070 && c <= 0x22FF) || (c >= 0x2460 && c <= 0x24FF);
    return is_face_sign(c) && !is_read_sign;
}

char32_t value_at(const std::vector<CodePoint>& text, std::size_t i) {
    return i < text.size() ? text[i].value : 0;
}

// The end of a face whose bracket opens at text[open], or open where none does.
std::size_t face_bracket_end(const std::vector<CodePoint>& text, std::size_t open) {
    // A face is a few signs; a longer bracket is an aside.
    constexpr std::size_t kLongestFace = 16;
    constexpr std::size_t kFewestSigns = 2;
    if (value_at(text, open) != '(') return open;
    std::size_t signs = 0;
    bool draws = false;
    for (auto k = open + 1; k < text.size() && k <= open + kLongestFace + 1; ++k) {
        const auto c = text[k].value;
        if (c == ')') return signs >= kFewestSigns && draws ? k + 1 : open;
        if (c == '\n' || c == '(' || is_han(c) || is_letter_or_digit(c)) return open;
        if (is_space(c)) continue;
        ++signs;
        draws = draws || !is_text_punctuation(c);
    }
    return open;
}

}  // namespace

std::vector<std::size_t> find_drawing_ends(const std::vector<CodePoint>& text) {
    std::vector<std::size_t> ends(text.size());
    for (std::size_t k = 0; k < text.size(); ++k) ends[k] = k;
    std::size_t last_end = 0;  // the end of the last drawing found
    for (std::size_t i = 0; i < text.size();) {
        if (is_emoji(text[i].value)) {
            auto end = i + 1;
            while (end < text.size() && (is_emoji(text[end].value) || joins_emoji(text[end].value))) ++end;
            ends[i] = last_end = end;
            i = end;
            continue;
        }
        const auto bracket_end = face_bracket_end(text, i);
        if (bracket_end == i) {
            ++i;
            continue;
        }
        // The signs touching the face before it, back to the end of an earlier drawing (an emoji).
        auto begin = i;
        while (begin > last_end && is_touching_sign(text[begin - 1].value)) --begin;
        auto end = bracket_end;
        while (is_touching_sign(value_at(text, end))) ++end;
        if (value_at(text, end) == ' ' && is_touching_sign(value_at(text, end + 1))) {
            auto thrown = end + 1;
            while (is_touching_sign(value_at(text, thrown))) ++thrown;
            const auto next = value_at(text, thrown);
            if (next == 0 || is_space(next) || is_han(next) || is_text_punctuation(next)) end = thrown;
        }
        ends[begin] = last_end = end;
        i = end;
    }
    return ends;
}

}  // namespace talkface::detail

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

bool is_lone_letter(const std::vector<CodePoint>& text, std::size_t i) {
    const auto is_ascii_letter = [](char32_t c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z'); };
    return is_ascii_letter(value_at(text, i)) && !(i > 0 && is_letter_or_digit(text[i - 1].value)) &&
           !is_letter_or_digit(value_at(text, i + 1));
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

// Whether a face typed in ASCII signs may stand next to c, the code point before or after it (0 where none
// is): a space, a Chinese character or punctuation sets it apart from a word, a formula or a time (x-x=0,
// 3:30, 选项:D), which touch letters, digits and signs.
bool sets_off_face(char32_t c) {
    return c == 0 || is_space(c) || is_han(c) || (c >= 0x80 && !is_letter_or_digit(c)) ||
           std::u32string_view(U".,!?\"~").find(c) != std::u32string_view::npos;
}

// The end of a face typed in ASCII signs outside a bracket that begins at text[i], or i where none does:
// two eyes alike about a mouth (^_^, T_T, -_-, =_=, >_< with its eyes mirrored, ^o^), or ^^ alone, the
// sweat of a ; after it allowed (^_^;), the mouth no eye (--- and === are lines); letters are eyes only
// about an underscore (T_T, o_o, x_x), which a formula's letters never are. And a face on its side, a colon's
// or a semicolon's eyes, a nose and a mouth of a letter (:D, :-P, ;o), after a space or at the line's start
// (選項:D is a choice's letter): the other sideways faces, :-) ;( and the like, are punctuation already,
// unsaid and unwarned.
std::size_t ascii_face_end(const std::vector<CodePoint>& text, std::size_t i) {
    constexpr std::u32string_view kSignEyes = U"^-=><;*@~";
    constexpr std::u32string_view kLetterEyes = U"TQoOxXuU";
    constexpr std::u32string_view kMouths = U"_.-ovw";
    constexpr std::u32string_view kLetterMouths = U"DPpOo3";
    if (!sets_off_face(i > 0 ? text[i - 1].value : 0)) return i;
    const auto eye = value_at(text, i);
    const auto mouth = value_at(text, i + 1);
    const auto mirrored = eye == '>' ? U'<' : eye;
    const bool is_sign_eye = kSignEyes.find(eye) != std::u32string_view::npos;
    const bool is_letter_eye = kLetterEyes.find(eye) != std::u32string_view::npos;
    auto end = i;
    if (eye == '^' && mouth == '^') {
        end = i + 2;
    } else if ((is_sign_eye || is_letter_eye) && value_at(text, i + 2) == mirrored && mouth != eye &&
               kMouths.find(mouth) != std::u32string_view::npos && (is_sign_eye || mouth == '_')) {
        end = i + 3;
    } else if ((eye == 'X' || eye == 'x') && mouth == 'D') {
        // A laugh on its side, its eyes squeezed shut (XD, XDDD, xD; session 39: spelled, ai ke si di), as
        // chats in Taiwan and Hong Kong close a joke; not before a Chinese character unless its mouth is
        // drawn wide (xD卡 is a memory card), nor before a model's number or a word (XD 2000).
        auto wide = i + 2;
        while (value_at(text, wide) == 'D') ++wide;
        auto next = wide;
        while (is_space(value_at(text, next))) ++next;
        if ((wide > i + 2 || !is_han(value_at(text, wide))) && !is_letter_or_digit(value_at(text, next)))
            end = wide;
    } else if ((eye == ':' || eye == ';') && (i == 0 || is_space(text[i - 1].value))) {
        const auto side_mouth = value_at(text, i + 1) == '-' ? i + 2 : i + 1;
        if (kLetterMouths.find(value_at(text, side_mouth)) != std::u32string_view::npos) end = side_mouth + 1;
    }
    if (end == i) return i;
    if (value_at(text, end) == ';') ++end;
    return sets_off_face(value_at(text, end)) ? end : i;
}

// A tick or a cross right after 打 is the mark a form asks to draw (打✓ 打勾, 打✗ 打叉): a word, said, not
// a picture (session 33: unsaid).
bool is_mark_to_draw(const std::vector<CodePoint>& text, std::size_t i) {
    if (i == 0 || text[i - 1].value != U'打') return false;
    const auto mark = text[i].value;
    return mark == 0x2713 || mark == 0x2714 || mark == 0x2717 || mark == 0x2718;
}

}  // namespace

std::vector<std::size_t> find_drawing_ends(const std::vector<CodePoint>& text) {
    std::vector<std::size_t> ends(text.size());
    for (std::size_t k = 0; k < text.size(); ++k) ends[k] = k;
    std::size_t last_end = 0;  // the end of the last drawing found
    for (std::size_t i = 0; i < text.size();) {
        if (is_emoji(text[i].value) && !is_mark_to_draw(text, i)) {
            auto end = i + 1;
            while (end < text.size() && (is_emoji(text[end].value) || joins_emoji(text[end].value))) ++end;
            ends[i] = last_end = end;
            i = end;
            continue;
        }
        if (const auto typed_end = ascii_face_end(text, i); typed_end != i) {
            ends[i] = last_end = typed_end;
            i = typed_end;
            continue;
        }
        const auto bracket_end = face_bracket_end(text, i);
        if (bracket_end == i) {
            ++i;
            continue;
        }
        // The signs touching the face before it, back to the end of an earlier drawing (an emoji).
        auto begin = i;
        // An = between two such signs is drawn too: the dust a running face kicks up (ε=ε=┏(゜ロ゜;)┛;
        // session 34: each ε and = warned of as a symbol).
        while (begin > last_end && (is_touching_sign(text[begin - 1].value) ||
                                    (text[begin - 1].value == '=' && begin >= 2 + last_end &&
                                     is_touching_sign(text[begin - 2].value))))
            --begin;
        // A Latin letter alone touching the face is a hand or an arm drawn with it (o(╥﹏╥)o, ヾ(≧▽≦*)o,
        // b(￣▽￣)d; session 34: said, ou), where no letter or digit beside it makes it a word's.
        if (begin > last_end && is_lone_letter(text, begin - 1)) --begin;
        auto end = bracket_end;
        while (is_touching_sign(value_at(text, end))) ++end;
        if (is_lone_letter(text, end)) ++end;
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

#include "text/line_sentences.hpp"

#include <algorithm>
#include <cstddef>

#include "text/sentence_marks.hpp"
#include "text/written_number_scan.hpp"

namespace talkface::detail {

namespace {

// A line's extent in the text: from its first code point to past its last one that is not a space.
struct Line {
    int number = 0;
    std::size_t begin = 0;
    std::size_t end = 0;  // past the last code point that is not a space; begin where none is
    int columns = 0;      // its width between them, a wide character two
};

int columns_of(char32_t c) {
    // CJK, kana, Hangul and full-width forms take two columns, as a terminal or an editor shows them.
    return c >= 0x1100 && (c <= 0x115F || (c >= 0x2E80 && c <= 0xA4CF) || (c >= 0xAC00 && c <= 0xD7A3) ||
                           (c >= 0xF900 && c <= 0xFAFF) || (c >= 0xFE30 && c <= 0xFE4F) ||
                           (c >= 0xFF00 && c <= 0xFF60) || (c >= 0xFFE0 && c <= 0xFFE6) || c >= 0x20000)
               ? 2
               : 1;
}

std::vector<Line> lines_of(const std::vector<CodePoint>& text) {
    std::vector<Line> lines;
    std::size_t i = 0;
    while (i < text.size()) {
        Line line{text[i].line, i, i, 0};
        std::size_t k = i;
        for (; k < text.size() && text[k].value != '\n'; ++k) {
            if (!is_space(text[k].value)) line.end = k + 1;
        }
        for (auto m = line.begin; m < line.end; ++m) line.columns += columns_of(text[m].value);
        lines.push_back(line);
        i = k + 1;
    }
    return lines;
}

// A sentence ends inside the line, text after it: a full stop, as wrapped prose ends its sentences
// wherever the width falls. Not ! ? … ; of a line of dialogue (好！走吧), nor a dot of a number.
bool ends_sentence_inside(const std::vector<CodePoint>& text, const Line& line) {
    for (auto k = line.begin; k + 1 < line.end; ++k) {
        const auto c = text[k].value;
        const bool full_stop = c == 0x3002 /*。*/ || c == 0xFF61 /*｡*/;
        // A dot ends an English sentence after a word's small letter; after a list item's number (1. 苹果) or
        // a choice's letter (A. 正确) it ends none.
        const bool english_stop = c == '.' && k > line.begin && text[k - 1].value >= 'a' &&
                                  text[k - 1].value <= 'z' && is_space(text[k + 1].value);
        if (!full_stop && !english_stop) continue;
        auto next = k + 1;
        while (next < line.end && (closes_quote(text[next].value) || is_space(text[next].value))) ++next;
        if (next < line.end) return true;
    }
    return false;
}

// The line goes on into the next: it ends with a pause mark or a dash, or it ends a sentence itself.
bool runs_on_or_ends(const std::vector<CodePoint>& text, const Line& line) {
    auto last = line.end;
    while (last > line.begin && closes_quote(text[last - 1].value)) --last;
    if (last == line.begin) return false;
    const auto c = text[last - 1].value;
    if (last < line.end) return ends_sentence(c);  // 「好。」 ends; 「好」 does not
    return ends_sentence(c) || marks_pause(c) || is_dash(c);
}

}  // namespace

std::vector<int> lines_ending_sentences(const std::vector<CodePoint>& text) {
    constexpr int kFullColumns = 40;  // a wrapped line's least width: 20 Chinese characters
    constexpr int kWidthSlack = 2;  // a wrap that keeps a mark off a line's start leaves it a character short
    std::vector<int> ending;
    const auto lines = lines_of(text);
    for (std::size_t first = 0; first < lines.size();) {
        while (first < lines.size() && lines[first].end == lines[first].begin) ++first;
        auto last = first;  // past the paragraph's last line
        while (last < lines.size() && lines[last].end > lines[last].begin) ++last;
        const auto begin = lines.begin() + static_cast<std::ptrdiff_t>(first);
        const auto end = lines.begin() + static_cast<std::ptrdiff_t>(last);
        const bool running =
            std::any_of(begin, end, [&](const Line& line) { return ends_sentence_inside(text, line); });
        int widest = 0;
        for (auto line = begin; line != end; ++line) widest = std::max(widest, line->columns);
        for (auto line = begin; !running && line + 1 < end; ++line) {
            const bool fills = line->columns >= kFullColumns && line->columns + kWidthSlack >= widest;
            if (!fills && !runs_on_or_ends(text, *line)) ending.push_back(line->number);
        }
        first = last;
    }
    return ending;
}

}  // namespace talkface::detail

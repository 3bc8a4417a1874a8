#include "text/legend_shapes.hpp"

#include <string>
#include <string_view>
#include <utility>

#include "text/sentence_marks.hpp"
#include "text/written_number_scan.hpp"

namespace talkface::detail {

std::optional<SpokenForm> read_legend_shape(const std::vector<CodePoint>& text, std::size_t i) {
    // Each shape by the name of its form, filled or hollow alike, as a key is read out: an up-pointing
    // triangle 三角, a down-pointing one 倒三角, a dot 圆点 and a ring 圆圈, a filled square 方块 and a
    // hollow one 方框, a diamond 菱形. Those who say 实心三角 fix it in place: ▲{实心三角}表示上涨.
    constexpr std::pair<char32_t, const char*> kNames[] = {
        {0x25B2, "三角"}, {0x25B3, "三角"}, {0x25BC, "倒三角"}, {0x25BD, "倒三角"},
        {0x25CF, "圆点"}, {0x25CB, "圆圈"}, {0x25EF, "圆圈"},   {0x25A0, "方块"},
        {0x25A1, "方框"}, {0x25C6, "菱形"}, {0x25C7, "菱形"},
    };
    const char* name = nullptr;
    for (const auto& [shape, said] : kNames) {
        if (text[i].value == shape) name = said;
    }
    if (name == nullptr) return std::nullopt;
    // A shape opening its line is a bullet (▲为您推荐, ● 国内油价) unless a key's own words follow it.
    constexpr std::string_view kMeaning[] = {"表示", "代表", "为", "為", "是", "指", "即"};
    constexpr std::string_view kKeyMeaning[] = {"表示", "代表"};
    constexpr std::string_view kMarking[] = {"用", "以", "带", "帶", "标有", "標有"};
    // A reading fix right after the shape (▲{实心三角}表示) stands between it and its key's words.
    auto next = i + 1;
    if (next < text.size() && text[next].value == '{') {
        while (next < text.size() && text[next].value != '}' && text[next].value != '\n') ++next;
        if (next < text.size() && text[next].value == '}') ++next;
    }
    const auto after = text_between(text, next, next + 2);
    const bool explained = marks_bullet(text, i)
                               ? starts_with_any(after, kKeyMeaning)
                               : starts_with_any(after, kMeaning) ||
                                     ends_with_any(text_between(text, i >= 2 ? i - 2 : 0, i), kMarking);
    if (!explained) return std::nullopt;
    SpokenForm form;
    form.end = i + 1;
    form.words = name;
    return form;
}

}  // namespace talkface::detail

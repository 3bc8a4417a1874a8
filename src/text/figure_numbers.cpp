#include "text/figure_numbers.hpp"

#include "text/number_words.hpp"
#include "text/written_number_scan.hpp"

namespace talkface::detail {

namespace {

// Whether text[i] is 关 naming a game's stage (卡在1-3关, 打到2-5關了), not a word that begins with it
// (关于 关注 关系 关键 关门).
bool names_stage_at(const std::vector<CodePoint>& text, std::size_t i) {
    return is_one_of(value_at(text, i), U"关關") &&
           !is_one_of(value_at(text, i + 1), U"于於注心系係键鍵门門闭閉掉机機");
}

}  // namespace

bool numbers_labelled_item(const std::vector<CodePoint>& text, std::size_t start) {
    const auto label = text_between(text, start >= 2 ? start - 2 : 0, start);
    if (is_any_of(label, {"附件", "附表", "附图", "附圖"})) return true;
    if (start == 0 || !is_one_of(text[start - 1].value, U"图圖表")) return false;
    // 图 and 表 end words that count (手表2块, 代表2人, 发表2篇, 地图2张): the label stands where a clause
    // opens or after a word that points to it (见表2, 如图2所示, 由表2可知).
    const auto before = value_at(text, start - 2);
    return start == 1 || is_one_of(before, U"，,。.；;：:、（(「“\n 见見如由据據按在和与與及") ||
           text_between(text, start >= 3 ? start - 3 : 0, start - 1) == "参见";
}

std::optional<SpokenForm> read_figure_number(const std::vector<CodePoint>& text, std::size_t start,
                                             const WrittenNumber& first) {
    constexpr std::size_t kMostParts = 3;
    constexpr std::size_t kMostDigits = 2;
    // 例 is a worked example's label (例3-2) but where it ends a word for cases (病例 案例), whose numbers
    // count.
    const bool names_example = start > 0 && text[start - 1].value == U'例' &&
                               (start == 1 || !is_one_of(text[start - 2].value, U"病案"));
    // An annex is numbered so too (附件2-3 附件二杠三, the third of annex 2's parts; session 36: 二到三, a
    // range): 件 alone ends counts (3-5件), so only the word 附件.
    const bool names_annex = text_between(text, start >= 2 ? start - 2 : 0, start) == "附件";
    const bool after_label =
        start > 0 && (is_one_of(text[start - 1].value, U"图圖表式") || names_example || names_annex);
    // A game's stage is numbered so too, its world and its place in it (卡在1-3关 一杠三关, as players say
    // it; session 33: 一到三关); a range of stages takes 第 (第1-3关 第一到三关).
    const bool may_name_stage = start == 0 || text[start - 1].value != U'第';
    if (!(after_label || may_name_stage) || first.has_point || first.has_separators ||
        first.whole.size() > kMostDigits || !is_dash(value_at(text, first.end)) ||
        !is_digit_at(text, first.end + 1))
        return std::nullopt;
    SpokenForm form;
    form.words = cardinal_words(first.whole, false);
    auto i = first.end;
    std::size_t parts = 1;
    while (parts < kMostParts && is_dash(value_at(text, i)) && is_digit_at(text, i + 1)) {
        auto k = i + 1;
        const auto part = digits_from(text, k);
        if (part.size() > kMostDigits) return std::nullopt;
        form.words += "杠" + cardinal_words(part, false);
        i = k;
        ++parts;
    }
    const auto after = value_at(text, i);
    // 所 of 如图3-2所示 is no measure word (300多所学校).
    const bool measures = takes_liang(after) && text_between(text, i, i + 2) != "所示";
    if (!after_label && !names_stage_at(text, i)) return std::nullopt;
    if (after_label && (is_digit_at(text, i) || is_dash(after) || after == '.' || measures || after == '%'))
        return std::nullopt;
    form.end = i;
    return form;
}

}  // namespace talkface::detail

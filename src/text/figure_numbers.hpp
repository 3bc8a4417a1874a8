// A textbook's figure, table, formula and example numbers as a lesson reads them (图3-2 图三杠二, 表2-1
// 表二杠一): the part of the written-form reader that tells a label's chapter and place from a range or a
// score (docs/written-forms.md).
#ifndef TALKFACE_TEXT_FIGURE_NUMBERS_HPP
#define TALKFACE_TEXT_FIGURE_NUMBERS_HPP

#include <cstddef>
#include <optional>
#include <vector>

#include "text/code_points.hpp"
#include "text/written_number_scan.hpp"
#include "text/written_numbers.hpp"

namespace talkface::detail {

// Two or three numbers of one or two digits joined by dashes right after 图 表 式 附件 (图3-2, 附表2-1,
// 式3-2-1, 附件2-3), or 例 (例3-2, a worked example; not 病例 案例, whose cases count), and before no measure
// word or magnitude: a chapter and the label's place in it, each part counted with 杠 between, as teachers
// read them (session 29: 三到两, a range, and 二比一, a score; session 30: 例3-2 三到二; session 36: 附件2-3
// 二到三). A range after such a word counts something and says what (发表3-5篇, 代表3-5人 stay ranges). So
// is a game's stage before 关 without 第 (卡在1-3关 一杠三关, its world and its place; 第1-3关 stays a range
// of stages).
// Whether the number at text[start] names a figure, a table or an annex (表2 表二, 如图2所示, 附件2): its
// place among them, said as an ordinal is, 二 before a measure word too (表2列出 表二列出; session 35: 两,
// 列 counted).
bool numbers_labelled_item(const std::vector<CodePoint>& text, std::size_t start);

std::optional<SpokenForm> read_figure_number(const std::vector<CodePoint>& text, std::size_t start,
                                             const WrittenNumber& first);

}  // namespace talkface::detail

#endif

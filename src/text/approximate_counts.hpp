// Two neighbouring numbers written with 、 for an approximate count (3、4个 三四个, 2、3天 两三天, 70、80年代
// 七八十年代): the part of the written-form reader that says the pair's low end as speakers run the two
// together (docs/written-forms.md).
#ifndef TALKFACE_TEXT_APPROXIMATE_COUNTS_HPP
#define TALKFACE_TEXT_APPROXIMATE_COUNTS_HPP

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "text/code_points.hpp"
#include "text/written_number_scan.hpp"

namespace talkface::detail {

// The words of `number` at text[start] as the low end of an approximate count, or nothing where it is
// none: the number, 、 and the next number up, both of one digit (2、3天 两三天, 1、2个) or both round tens
// (70、80年代 七八十年代, 30、40个 三四十个), the pair before a measure word, with no 第 before it and no
// third number listed (session 29: 二三天 and 七十八十年代, a list said number by number). The high end is
// read as it stands, before its measure word (两 for 2: 一两个). An ordering measure (层 期 届 章 页 集 册
// 节 局, and 年级) keeps the list: 2、3层 are floors two and three, 二、三层; but not right after a verb's
// 了, where the pair counts what was done (看了2、3期 两三期; session 29 left it a list).
std::optional<std::string> approximate_low_end(const std::vector<CodePoint>& text, std::size_t start,
                                               const WrittenNumber& number);

}  // namespace talkface::detail

#endif

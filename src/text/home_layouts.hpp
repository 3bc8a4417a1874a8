// A home's layout as listings and property news write it, its rooms counted one after another (3室2厅2卫
// 三室两厅两卫, 3房2廳2衛 三房兩廳兩衛, 1梯2户 一梯两户): the part of the written-form reader that tells such
// a count from a room's or a hall's name (2室 of an office, 302室, 影院2厅), docs/written-forms.md.
#ifndef TALKFACE_TEXT_HOME_LAYOUTS_HPP
#define TALKFACE_TEXT_HOME_LAYOUTS_HPP

#include <cstddef>
#include <vector>

#include "text/code_points.hpp"
#include "text/written_number_scan.hpp"

namespace talkface::detail {

// Whether `number` at text[start] counts a part of a home in a layout: a whole number of one or two digits
// before a part's word (室 房 厅 卫 厨, in either script, and a building's 梯 and 户), with another such
// count right before or right after it. Counted so, a 2 is 两 as before a measure word (session 34: 二,
// a room's name: 三室二厅二卫). One part alone stays as it was: 2室 may be an office's name, 2厅 a
// cinema's hall.
bool counts_in_layout(const std::vector<CodePoint>& text, std::size_t start, const WrittenNumber& number);

}  // namespace talkface::detail

#endif

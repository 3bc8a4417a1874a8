// A whole told by its parts counted one after another: a home's layout as listings and property news write
// it (3室2厅2卫 三室两厅两卫, 3房2廳2衛 三房兩廳兩衛, 1梯2户 一梯两户) and a team's lineup as players call
// for it (1坦2補 一坦兩補, 2奶3射): the part of the written-form reader that tells such a count from a room's
// or a hall's name (2室 of an office, 302室, 影院2厅), docs/written-forms.md.
#ifndef TALKFACE_TEXT_COUNTED_PARTS_HPP
#define TALKFACE_TEXT_COUNTED_PARTS_HPP

#include <cstddef>
#include <vector>

#include "text/code_points.hpp"
#include "text/written_number_scan.hpp"

namespace talkface::detail {

// Whether `number` at text[start] counts a part of a whole: a whole number of one or two digits before a
// part's word, with another such count of the same whole's parts right before or right after it. A home's
// parts are 室 房 厅 卫 厨, in either script, and a building's 梯 and 户; a team's roles are a game's tank,
// healer, support, marksman, mage, warrior and assassin (坦 奶 补 補 辅 輔 射 法 战 戰 刺). Counted so, a 2
// is 两 as before a measure word (session 34: 二, a room's name: 三室二厅二卫; session 40: 一坦二補). One
// part alone stays as it was: 2室 may be an office's name, 2厅 a cinema's hall, 2法 a second law.
bool counts_in_layout(const std::vector<CodePoint>& text, std::size_t start, const WrittenNumber& number);

}  // namespace talkface::detail

#endif

// Buildings counted by 栋 or 幢 as news counts them where a fire, a flood or a building plan names them
// (烧毁了2栋民房 两栋民房, 新建2幢住宅楼, 2棟大樓): 栋 is kept out of the measure words a 2 is 两 before,
// because 2栋 alone names a building (住在2栋301, 2栋楼下 of a housing estate's block); before a building's
// own noun it counts them, as 两座 and 两间 do. docs/written-forms.md.
#ifndef TALKFACE_TEXT_COUNTED_BUILDINGS_HPP
#define TALKFACE_TEXT_COUNTED_BUILDINGS_HPP

#include <vector>

#include "text/code_points.hpp"
#include "text/written_number_scan.hpp"

namespace talkface::detail {

// Whether `number` counts buildings: a whole number of one or two digits right before 栋 棟 or 幢 and a
// building's noun right after it (民房 房屋 楼房 大楼 住宅 建筑 厂房 宿舍 别墅 平房 民宅 教学楼 办公楼, and
// their Traditional forms; 楼 alone is left to the block's name, 2栋楼下).
bool counts_buildings(const std::vector<CodePoint>& text, const WrittenNumber& number);

}  // namespace talkface::detail

#endif

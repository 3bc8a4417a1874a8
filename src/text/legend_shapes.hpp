// A shape a legend explains (说明：▲表示上涨, 图中●为观测站): said by its name, as one reads a chart's or a
// table's key aloud (docs/written-forms.md).
#ifndef TALKFACE_TEXT_LEGEND_SHAPES_HPP
#define TALKFACE_TEXT_LEGEND_SHAPES_HPP

#include <cstddef>
#include <optional>
#include <vector>

#include "text/code_points.hpp"
#include "text/written_numbers.hpp"

namespace talkface::detail {

// The shape at text[i] (▲ △ ▼ ▽ ● ○ ■ □ ◆ ◇), named where its clause explains it: a word of meaning
// right after it (表示 代表 为 是 指 即) or a word that marks with it right before it (用 以 带 标有), at a
// line's start 表示 or 代表 only; nullopt elsewhere (a bullet opening its line, a ticker's ▲ before a number
// and a triangle's △ABC are read elsewhere; any other shape inside a line is still a mark without a reading).
std::optional<SpokenForm> read_legend_shape(const std::vector<CodePoint>& text, std::size_t i);

}  // namespace talkface::detail

#endif

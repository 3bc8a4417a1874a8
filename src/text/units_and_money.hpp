// Units and money written beside a number (5km, 25℃, 3nm, 256GB, 25元/公斤, ¥199, NT$300, HK$5):
// the part of the written-form reader that finds them and names them as newsreaders and lessons
// say them (docs/written-forms.md).
#ifndef TALKFACE_TEXT_UNITS_AND_MONEY_HPP
#define TALKFACE_TEXT_UNITS_AND_MONEY_HPP

#include <cstddef>
#include <optional>
#include <string_view>
#include <vector>

#include "text/code_points.hpp"
#include "text/written_numbers.hpp"

namespace talkface::detail {

struct Unit {
    std::string_view written;
    const char* words;
};

// The unit written at text[i] (after at most one space when it is Latin), or nullptr.
const Unit* unit_at(const std::vector<CodePoint>& text, std::size_t i, std::size_t& end);

// KB MB GB TB PB after a number (256GB, 2 TB): a unit, so the number counts (两 TB, not a phone
// number's digits), said as its letters, which the Latin reader reads after the number. So is the
// capital alone before a word of stored data (2G流量, 4G内存; session 27).
// Whether text[i] starts a rate's basis points written bp (25bp, 降息2bp): said as its letters, as finance
// says them (二十五 bi pi), but a measure as a unit is, so a 2 before it is 两 (两 bi pi; session 32: 二).
bool is_basis_points_at(const std::vector<CodePoint>& text, std::size_t i);

bool is_byte_unit_at(const std::vector<CodePoint>& text, std::size_t i);

// A unit written alone where a lesson names it, after 单位是, 单位为 or 单位： (速度的单位是m/s 米每秒,
// 功率的单位是W 瓦), said by its name as after a number (session 33: its letters); nullopt elsewhere.
std::optional<SpokenForm> read_named_unit(const std::vector<CodePoint>& text, std::size_t i);

struct Currency {
    std::u32string_view written;
    const char* before;  // said before the amount
    const char* after;   // said after it
};

const Currency* currency_at(const std::vector<CodePoint>& text, std::size_t i, std::size_t& end);

}  // namespace talkface::detail

#endif

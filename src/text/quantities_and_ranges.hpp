// One number or a range of two (3-5, -8~-3℃, 10%-20%) said with what follows it (issue 13): its power,
// its magnitude (a chat's 1w and 8k too), its unit and what the unit is per (7.0mmol/L 每升), its currency's
// word, the + of a count "or more", and its signs where a temperature or a change says them.
#ifndef TALKFACE_TEXT_QUANTITIES_AND_RANGES_HPP
#define TALKFACE_TEXT_QUANTITIES_AND_RANGES_HPP

#include <cstddef>
#include <string>
#include <vector>

#include "text/code_points.hpp"
#include "text/number_context.hpp"
#include "text/units_and_money.hpp"
#include "text/written_number_scan.hpp"
#include "text/written_numbers.hpp"

namespace talkface::detail {

// A range mark at text[mark] between two quantities with the same unit (-5℃~3℃, 5km-10km): 到, as between
// two dates (session 19: the mark was silent after the first's unit, 零下五摄氏度三摄氏度).
bool joins_quantities(const std::vector<CodePoint>& text, std::size_t mark);

// What a slash after a quantity's unit ending at text[end] is per, said 每 and moving `end` past it: another
// unit, with its number where it has one (7.0mmol/L 每升, 35μg/m³ 每立方米, 80mg/100ml 每一百毫升), or a
// measure word, which is read after it as the text it is (0.3g/粒 零点三克每粒, 100mg/片; session 19: the
// slash was silent). "" where none follows.
std::string per_unit_words(const std::vector<CodePoint>& text, std::size_t& end);

// One number, or a range of two (3-5, 3~5), said with what follows the last of them: its power, its
// magnitude, its unit or its currency's word, the + of a count "or more"; its signs said as a temperature's,
// a change's or a rise's where the text says so.
SpokenForm read_quantity(const std::vector<CodePoint>& text, std::size_t start, const WrittenNumber& number,
                         const std::string& sign_words, const Currency* currency, NumberContext context);

}  // namespace talkface::detail

#endif

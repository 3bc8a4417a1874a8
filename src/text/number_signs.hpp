// A number's sign as the text around it says it (issue 13): the written-form reader's part that reads
// a +, a -, a ± or an arrow before the digits (正, 负, 加, 减, 正负, 涨, 跌) and words a sign as a
// temperature's (零下), a game's bonus (加), or a change's after a comparison or a reported amount
// (同比增长, 下降).
#ifndef TALKFACE_TEXT_NUMBER_SIGNS_HPP
#define TALKFACE_TEXT_NUMBER_SIGNS_HPP

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "text/code_points.hpp"
#include "text/units_and_money.hpp"

namespace talkface::detail {

// A chat's +1 that closes its clause after a person, in a clause a post's person opens (我+1, 楼上+1,
// 楼上说得对+1) or after a word of agreement (收到+1, 同意+1): "me too", 加一, as a +1 standing alone is
// (session 20: 正一); and those who answer so, a +1 opening its clause before 的 (+1的請留言). 温差+1 and
// 电荷为+1的离子 keep their sign.
bool agrees_in_chat(const std::vector<CodePoint>& text, std::size_t start, std::size_t end);

// A number's sign or currency before its digits at text[start] and where its digits start: the sign
// said (正, 负, 加, 减; ± 正负, ↑ ▲ 涨, ↓ ▼ 跌) or "" where none is said or a dash is no sign; nullopt where
// no digit follows.
struct LeadingSign {
    const Currency* currency = nullptr;
    std::string words;
    std::size_t digits = 0;
};

std::optional<LeadingSign> read_leading_sign(const std::vector<CodePoint>& text, std::size_t start);

// The signs of a number or a range's ends (`signs`, each 正, 负 or "" as written) said as the text around
// them says: a temperature's 零下 and 零上, a quantity's 加, a change's after a comparison or an amount
// (增长, 下降), a percentage's rise and fall (涨, 跌). `unit_end` is where its unit ends.
void word_signs(const std::vector<CodePoint>& text, std::size_t start, std::size_t unit_end,
                bool is_temperature, bool is_percent, bool is_per_mille, std::vector<std::string>& signs);

}  // namespace talkface::detail

#endif

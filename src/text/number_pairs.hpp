// Two numbers about a mark, each said alone with a word between (issue 13): a score or a ratio (3:1 三比一),
// a race's or a clock's time, a product (7×24, 1920x1080), a fraction (1/3 三分之一), a blood pressure
// (140/90mmHg 一百四十比九十), a place in a whole (第3/10篇), a game's record of kills (战绩0-10 零杠十) and
// a result between two teams' names (曼城2-1阿森纳).
#ifndef TALKFACE_TEXT_NUMBER_PAIRS_HPP
#define TALKFACE_TEXT_NUMBER_PAIRS_HPP

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "text/code_points.hpp"
#include "text/number_context.hpp"
#include "text/units_and_money.hpp"
#include "text/written_number_scan.hpp"
#include "text/written_numbers.hpp"

namespace talkface::detail {

// A game's record of kills, deaths and assists (战绩0-10, KDA 5-2-10), each part said with 杠 between, as
// players read it out (零杠十; session 16: a range, 零到十). Up to three parts of one or two digits,
// where 战绩 or KDA stands earlier in the clause, or right after one player's pronoun with the record
// closing its clause (这把我0-8， 零杠八; session 23: a range, 零到八): a range closing a clause has a word
// to count (3-5天), and a team's 我们2-1 and a match's 决赛他3-1 are scores.
std::optional<SpokenForm> read_game_record(const std::vector<CodePoint>& text, std::size_t start,
                                           const WrittenNumber& first);

// A result between two teams' names (曼城2-1阿森纳, 上海海港3-3北京国安, 皇马3-0巴萨): a range is written
// from its low end up, so two whole numbers that fall or stay level between two names are a score
// (session 16; they were a range, 二到一). Not after 第, nor before a measure word or a word of a
// date, a time, a floor or a degree (3-1日, 5-3楼). A space on each side of the score is the results
// table's (曼城 2-2 利物浦; session 41).
bool is_result_between_names(const std::vector<CodePoint>& text, std::size_t start,
                             const WrittenNumber& first, const WrittenNumber& second);

// A score standing as a clause of its own, as a match report writes it after a goal (武磊推射破门，1-0。,
// 终场 前扳平，1-1。): two whole numbers that fall or stay level, between clause marks (session 35: a range,
// 一到零).
bool is_result_standing_alone(const std::vector<CodePoint>& text, std::size_t start,
                              const WrittenNumber& first, const WrittenNumber& second);

// Two numbers said each alone with a word between, the first after its sign: a score (3:1, and 2-1
// where the clause speaks of a match: 2-1领先), a product (7×24 七乘二十四).
SpokenForm join_two(const WrittenNumber& first, const std::string& sign_words, const WrittenNumber& second,
                    const char* joiner, const NumberContext& each);

// Two numbers about a colon (number, then text[number.end]): a race's or a clock's time where no score
// is spoken of, else a score or a ratio of two parts or more, 比 between them; nullopt where no number
// follows the colon.
std::optional<SpokenForm> read_colon_pair(const std::vector<CodePoint>& text, std::size_t start,
                                          const WrittenNumber& number, const NumberContext& context);

// A small x between two numbers is a times sign typed (4x400米接力, 1920x1080), said 乘 as × is.
// An interval as a lesson writes it, its two ends between brackets and a comma, one bracket square at least
// or 区间 before it ([0,1), (-1,3], 区间(0,2), [0,+∞)): the ends joined by 到 (零到一), as a teacher reads
// the numbers it holds from and to, the brackets unsaid; ∞ 无穷 after its sign (session 33: the comma was a
// pause, 零，一). A point's coordinates in round brackets ((1,2)) are none. `start` is where the first end's
// sign starts, `number` its digits.
std::optional<SpokenForm> read_interval(const std::vector<CodePoint>& text, std::size_t start,
                                        const WrittenNumber& number, const std::string& sign_words);

std::optional<SpokenForm> read_product(const std::vector<CodePoint>& text, const WrittenNumber& number);

// Two numbers about a slash (number, then text[number.end]): a blood pressure (blood_pressure_unit), 24/7,
// or a fraction, its denominator said first (1/3 三分之一), and a range to a second one (1/3~1/2); nullopt
// where no number follows the slash or the first has a point.
std::optional<SpokenForm> read_slashed_pair(const std::vector<CodePoint>& text, std::size_t start,
                                            const WrittenNumber& number, const std::string& sign_words,
                                            const Currency* currency);

// Two models of a maker's series joined by a slash (HP 1200/1500系列, RTX 4090/4080), as a part's or a
// cartridge's copy lists what it fits: each number said as a model's digits, the slash unsaid (session 32: a
// fraction, 一千五百分之一千二百). The first is a model's (NumberContext::is_model: after its maker's
// capitals and a space); the second has as many digits, three or more, as a model's do. A game's
// HP：1200/1500 (a colon) is no model's. nullopt where they are not two such models.
std::optional<SpokenForm> read_slashed_models(const std::vector<CodePoint>& text, const WrittenNumber& first,
                                              const NumberContext& context);

// A body's length, width and height joined by slashes where the clause names them (长宽高分别为
// 5130/1999/1800mm, as a car's or a box's spec sheet writes them): each a number, the slashes unsaid and the
// unit said after the last (session 32: a fraction and a third number after it); nullopt where they are not
// three such numbers after 长宽高.
std::optional<SpokenForm> read_dimensions(const std::vector<CodePoint>& text, std::size_t start,
                                          const WrittenNumber& first);

}  // namespace talkface::detail

#endif

// How one number is said by the words around it (issue 13): the written-form reader's part that reads a
// number's context off the page (第 before it, a phone word, a model's name, a unit, a date's word after
// it ...) and says the number so, counted (一千二百), by its digits (a phone's, a model's, a chat's 666),
// as a year, a version or a station's frequency.
#ifndef TALKFACE_TEXT_NUMBER_CONTEXT_HPP
#define TALKFACE_TEXT_NUMBER_CONTEXT_HPP

#include <cstddef>
#include <string>
#include <vector>

#include "text/code_points.hpp"
#include "text/units_and_money.hpp"
#include "text/written_number_scan.hpp"

namespace talkface::detail {

// Whether text[start, end) stands alone as a clause: at the start of the text or after a mark that
// ends a clause (not a colon, which introduces a value), and before one or the end.
bool stands_alone(const std::vector<CodePoint>& text, std::size_t start, std::size_t end);

// How one number is said, given what follows it.
struct NumberContext {
    char32_t next = 0;             // the code point after the form ('%' counts as the unit)
    bool has_unit = false;         // a unit follows (5km): a measure, so 2 is 两
    bool is_ordinal = false;       // 第 before it
    bool is_phone = false;         // a phone word earlier in the sentence, or a hotline's right after it
    bool is_dialled = false;  // right after a verb of dialling (拨打 撥打 致电): dialled before any word
    bool is_named = false;         // a naming word right before it (房间号是1208)
    bool is_service_call = false;  // dialled or named (打110, 110报警)
    bool is_model = false;  // right after the capitals of a model's name (C919, A380) or a maker (波音737)
    bool is_train = false;  // a train's or a flight's number (G1234次, CA1831航班)
    bool is_flight = false;     // a flight's number (CA1831航班, 3U8633航班)
    bool is_unlettered_train = false;  // a train's number without a class's capital (自強號123次)
    bool has_currency = false;  // a currency sign before it (¥666)
    bool names_place = false;  // a room's or building's name after it (302会议室), a city's before (台北101)
    bool names_day = false;      // a day named by its date's digits (618大促, 今天是520)
    bool names_type = false;     // before 型 or 式, a type's number (737型, 99式)
    bool is_generation = false;  // two digits right before 后 (90后, 00后), or a list of them (80、90后)
    bool is_house_number = false;  // a street's (路 街 道 段 巷 弄) before 号: 文化路一段100號 一百號
    bool is_stake_metres = false;   // the metres after a motorway's stake and its +: K15+200路段 二百
    bool is_hundredths = false;     // right after the seconds of a time (9秒83) or a jump's metres (8米22)
    bool is_grade = false;          // a respirator's filter grade (N95)
    bool is_span_of_years = false;  // four digits before 年 that count years, not name one (距今约5000年)
    bool is_code =
        false;  // a stock's code, an index's or a programme's number (（600519）, 日经225, 985高校)
    bool is_version = false;        // after a software's name or a v (Python 3.12, v2.15): a version
    bool names_year = false;        // a year before a word it names (2025财年, 2026款)
    bool after_laugh = false;       // right after a laugh's character (哈哈233)
    bool after_final_particle = false;  // closing its clause right after a final particle (见啦88～)
    bool is_whole_clause = false;   // the number alone between clause marks (88，下次再聊)
    bool measures_degrees = false;  // before a 度 of a temperature or an angle (2度左右 两度)
    bool is_frequency = false;      // a station's frequency after FM, AM or 调频 (FM103.9 一零三点九)
    bool is_count_over = false;     // a + after it and no term after that (99+ 九十九加; 666+1 is a sum)
    bool after_times = false;  // right after a times sign, a count of items (金币×888 乘八百八十八)
    bool names_schedule =
        false;  // a work schedule by its hours and days (996, 955), not after a price (售价996)
    bool counts_kuai = false;  // money counted in 块, casual speech's (200块, 300多块, a shop's 满200)
    bool counts_in_layout = false;  // a part of a home's layout or a team's lineup (3室2厅, 1坦2補): 2 is 两
    bool counts_buildings = false;  // 栋 or 幢 before a building's noun (2栋民房): 2 is 两
    bool follows_ratio = false;     // right after a number and 比 (2比2平): a score's or a ratio's term
    bool next_heads_word = false;  // 男 or 女 after it heads a word (9秒58男子), no count of people, or a
                                   // measure word opens a word of rank (876排在)
};

struct SaidNumber {
    std::string words;
    bool is_year = false;
    bool is_dialled = false;  // a phone's, a service's or a flight's number, 1 said 幺 (一 in Taiwan)
    std::string warning;
};

SaidNumber say_number(const WrittenNumber& number, const NumberContext& context);

// How the text about `number` (its digits at text[i], its sign or currency from text[start]) says it
// is said; what follows its last digits and unit (NumberContext::next, has_unit, measures_degrees,
// is_count_over) read_quantity sets.
NumberContext context_of_number(const std::vector<CodePoint>& text, std::size_t start, std::size_t i,
                                const WrittenNumber& number, const std::string& sign_words,
                                const Currency* currency);

}  // namespace talkface::detail

#endif

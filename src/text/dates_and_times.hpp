// Dates, clock times, durations and scores as written (2026-12-01, 9/18, 3·15, 3:30, 2:05:30, 1:28.65,
// 2024/25赛季, 2026年, 618): the part of the written-form reader that tells a time from a score
// and says each (docs/written-forms.md).
#ifndef TALKFACE_TEXT_DATES_AND_TIMES_HPP
#define TALKFACE_TEXT_DATES_AND_TIMES_HPP

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "text/code_points.hpp"
#include "text/written_number_scan.hpp"
#include "text/written_numbers.hpp"

namespace talkface::detail {

// Two numbers joined by a colon are a score, not a clock time, where the sentence speaks of a
// match: a score word earlier in the clause (比分是21:19) or a result right after (2:0战胜,
// 21:19获胜). Without either, a colon that can be a time is one (下午3:30). Joined by a dash
// (`dashed`), they are a score where a result of two characters comes anywhere later in the clause
// too, as a tennis result lists its sets first (6-3、6-4直落两盘获胜): a dash makes no clock time to
// mistake, only a range, which the caller tells by its measure word (3-5天后获胜).
bool is_score(const std::vector<CodePoint>& text, std::size_t start, std::size_t end, bool dashed = false);

// A colon's time where the clause speaks of how long something took (跑出了2:05:30的成绩, 用时3:35,
// 通关时间：02:35) or waits as a timer shows it (预计等待时间05:20): a duration, 两小时零五分三十秒,
// 三分三十五秒, not a time of day.
bool speaks_of_duration(const std::vector<CodePoint>& text, std::size_t start);

// A place in a recording (视频1:23处 一分二十三秒处, 进度条拉到12:45): minutes and seconds, not a time of
// day, where 处 follows the time, 那里 or 那段 a time in a clause naming a video (视频0:45那里), or the
// clause speaks of a player's progress bar (进度条 时间轴 拉到 跳到); or where a show's notes list its
// chapters, a time opening its line before a space and the chapter's title in a transcript that names a
// podcast or an episode (03:15 为什么要做播客) or whose list opens at 0:00 or 00:00 (00:00 开场).
bool names_place_in_recording(const std::vector<CodePoint>& text, std::size_t start, std::size_t end);

// A year of the Republic of China written with three digits (113 for 2024), as Taiwan dates its
// papers (113/12/31, 113.10.15): counted, 一百一十三年, as 民國113年 is.
bool is_republic_year(const std::string& digits);

// A date's year as said: four digits one by one (二零二六年), a year of the Republic counted.
std::string said_year(const std::string& digits);

// A day named by its date's digits (520 五二零, 618大促 六一八大促, 今天是1111): three or four digits
// that are a month and a day, a festival's or a sale's word right after them or a day's before
// them (今天是). Elsewhere such a number counts (520人, 股价涨到了520).
bool names_a_day(const std::vector<CodePoint>& text, std::size_t start, const WrittenNumber& number);

// Four digits before 年 name a year (2026年 二零二六年) unless they count years: a number past any
// year a text names as a date (距今约5000年: no one dates by the year 5000), a year before the common
// era, said as a count (公元前2070年 公元前两千零七十年), or a span with 历史 or 之久 after it (1200年
// 历史, 3000年之久).
bool counts_years(const std::vector<CodePoint>& text, std::size_t start, const WrittenNumber& number);

// A year that names what follows it without 年 (2025财年, 2025赛季, 2026款, 2025届, 2024版, 2023级, 2026春晚,
// 2030世界杯), new or a season's between them allowed (2024新款, 2024秋冬款): digit by digit, as a year is
// (二零二五财年); a count elsewhere (2000人, 2000多). So are a
// release's or a quarter's two digits before its half or quarter (24H2 二四 H 二, 25Q1 二五 Q 一).
bool names_year_before_word(const std::vector<CodePoint>& text, const WrittenNumber& number);

// A year named after a mark of its own: a fiscal year after FY (FY25 二五, FY2024 二零二四) and a year after
// a quarter or a half and a space (Q4 2024 Q 四 二零二四, H1 2025), two digits or four from 19 or 20, said
// digit by digit as a year is (session 30: FY25 二十五, Q4 2024 两千零二十四); not before a measure word (Q4
// 2000人).
bool names_year_after_mark(const std::vector<CodePoint>& text, std::size_t start,
                           const WrittenNumber& number);

// A year of three digits after 公元 or 公元前 and before 年 (公元前221年 公元前二二一年, 公元618年
// 公元六一八年), said digit by digit as history teachers and documentaries say it (session 33: counted,
// 二百二十一); four digits after 公元前 count (公元前2070年 两千零七十年), as counts_years says.
bool names_era_year(const std::vector<CodePoint>& text, std::size_t start, const WrittenNumber& number);

// A year from 19 or 20 closing a title's name after a word (《歌手2024》 歌手二零二四, 《乘风2023》), as a
// show's season named by its year is said (session 34: counted, 两千零二十四); a title of the digits alone
// (《1984》) is a book's number and counts.
bool names_year_in_title(const std::vector<CodePoint>& text, std::size_t start, const WrittenNumber& number);

// The dash or ~ at text[i] between a year's quarters or halves (2024Q1-Q3 二零二四 Q 一到 Q 三, Q2~Q4,
// H1-H2): a range, said 到 as a range of numbers is (session 30: unsaid, Q 一 Q 三).
bool joins_periods(const std::vector<CodePoint>& text, std::size_t i);

// A year by its last two digits before a month (24年12月5日 二四年十二月五日, 08年8月 零八年八月), as
// mainland news and chat write a recent year; counted where two digits are a year of the Republic, in a
// Traditional transcript or after 民国 (88年9月21日 八十八年). Before anything but a month two digits and 年
// count years (23年以来, 12年3个月).
bool names_short_year(const std::vector<CodePoint>& text, std::size_t start, const WrittenNumber& number);

// A year listed before another with 、 (2022、2023年 二零二二、二零二三年, 2024、2025赛季): four digits
// whose list ends on a year said as one (before 年 and not counting years, or before a word it names);
// the last takes the 年 (session 20: the first counted, 两千零二十二).
bool lists_year(const std::vector<CodePoint>& text, const WrittenNumber& number);

// 3:30 三点三十分, 10:05 十点零五分, 2:00 两点; nullopt when the text after the colon is not
// minutes (3:2 is a score). A `duration` is said in its units: 2:05:30 两小时零五分三十秒 (hours,
// minutes and seconds), 3:35 三分三十五秒 (minutes and seconds).
std::optional<SpokenForm> read_clock_time(const std::vector<CodePoint>& text, const WrittenNumber& hour,
                                          bool duration = false);

// 2026-12-01, 2026/12/1, and Taiwan's 113/12/31 (a year of the Republic): a year, a month and a day,
// and a range of two of them (113/09/01~113/09/30 ... 到 ...).
std::optional<SpokenForm> read_numeric_date(const std::vector<CodePoint>& text, const WrittenNumber& year);

// Whether a range mark at `mark` follows a date or a clock time (9月1日-9月5日, 3点-5点, 12:00-14:00):
// the first part of a range that ended the form before the mark, so the mark is 到, not a sign.
bool follows_date_or_time(const std::vector<CodePoint>& text, std::size_t mark);

// A season, or a school or financial year, written as two years that follow each other
// (2024/25赛季, 2024-25, 2024-2025学年): the years digit by digit joined by 至, as sports and
// school news read them (二零二四至二五赛季). A range of years before 年 stays a range
// (2020-2025年 二零二零到二零二五年); two years that do not follow each other are not a season.
std::optional<SpokenForm> read_season(const std::vector<CodePoint>& text, const WrittenNumber& first);

// A year and a month with a dot between them, as a label or a card dates its validity (有效期至2027.03
// 二零二七年三月, 生产日期：2025.10, 2019.05-2029.05 二零一九年五月到二零二九年五月): a year from 1900 to
// 2099 and a month of two digits, where its clause names a period or a date before it (有效期 日期 期限
// 保质期 到期 截止 截至; not 期货's price), 起 前 or 止 follows it, or it is a range to a second one (- ~ 至
// 到, read with it), and no count's word, unit or price follows (2026.08元 is a price; 收于2025.10 an index's
// value). nullopt elsewhere (session 31: a decimal, 两千零二十七点零三).
std::optional<SpokenForm> read_year_and_month(const std::vector<CodePoint>& text, std::size_t start,
                                              const WrittenNumber& year);

// A day named by its month and day with a middle dot between them, as an event is (3·15晚会 三一五
// 晚会, 5·12地震 五一二, 9·11 九一一): digit by digit, the dot not said.
std::optional<SpokenForm> read_dotted_day(const std::vector<CodePoint>& text, const WrittenNumber& month);

// A month and a day without a year, 9/18 (as Taiwan and Hong Kong write dates, and weather and
// event notices everywhere): 九月十八日 where the clause places something in time, with a word of
// time right after it (9/18起, 12/31前, 9/20晚间, 9/18(週三)) or 于 於 before it (请於12/31, not
// 小于1/3). A range mark after it is no sign: 1/3~1/2 is a range of fractions as often as 10/1-10/7
// is one of days. Elsewhere it is a fraction (1/3的学生, 1/2杯, 答案是3/4), and so it is before 的, a measure
// word or 决赛, the knockout rounds' (于1/4决赛中出局), whatever stands before it.
std::optional<SpokenForm> read_month_and_day(const std::vector<CodePoint>& text, std::size_t start,
                                             const WrittenNumber& month);

// A month and a day of two digits each joined by a dash, one of them padded with a zero, as a caption or a
// feed stamps a post (更新于12-06 20:15 十二月六日, 发布于03-15): a date, 月 and 日 said as other dates are
// (session 36: 一二杠零六, a code's digits). A score, a range or a count never writes its zero; a part of a
// longer code (A12-06, 010-12-06) is none.
std::optional<SpokenForm> read_padded_month_and_day(const std::vector<CodePoint>& text, std::size_t start,
                                                    const WrittenNumber& month);

// A clock time on the 12-hour clock, as English-speaking and Hong Kong shops write their hours (10AM
// 上午十点, 8PM 晚上八点, 7:30pm 晚上七点三十分, 10AM-8PM ... 到 ...): the part of the day said before the
// hour, as Mandarin says it (AM 上午, 12AM 凌晨; PM 12 中午, 1-5 下午, 6-11 晚上), the hour 1 to 12.
std::optional<SpokenForm> read_twelve_hour_time(const std::vector<CodePoint>& text,
                                                const WrittenNumber& hour);

// A day of the week in brackets right after a date, one character (12/24(三) 十二月二十四日星期三,
// 12月25日（四）, 1/1(日)), as Taiwan's and Hong Kong's notices date a day: 星期 and the character
// (session 39: the character alone, 三). nullopt elsewhere: the bracket at text[start] follows a digit,
// 日, 号 or 號.
std::optional<SpokenForm> read_weekday_bracket(const std::vector<CodePoint>& text, std::size_t start);

// A race's time, minutes and seconds with their tenths or hundredths (1:28.65 一分二十八秒六五,
// 3:27.46): the seconds' decimal point is what a clock's minutes never have. A subtitle's timestamp
// (00:01.500: minutes with a leading zero, thousandths) is no race's.
std::optional<SpokenForm> read_race_time(const WrittenNumber& minutes, const WrittenNumber& seconds);

// Minutes and seconds written with primes, 5'30" or 6′10″ (a runner's pace, a lap, an angle's minutes):
// 五分三十秒, the seconds of two digits below 60 and closed by their double prime (6'2" is no time).
std::optional<SpokenForm> read_primed_time(const std::vector<CodePoint>& text, const WrittenNumber& minutes);

// An angle's minutes with their prime and no seconds, right after its degrees (东经116°23′, 北纬39°54'):
// 二十三分, below 60; `start` is where the minutes are written.
std::optional<SpokenForm> read_arc_minutes(const std::vector<CodePoint>& text, std::size_t start,
                                           const WrittenNumber& minutes);

// A height in feet and inches written with primes, 6'2" or 5′7″: 六英尺两英寸, as 6英尺2英寸 is said. The
// inches of one digit, which a time's seconds never are, or 10 and 11 where the clause speaks of a
// height (身高5'10"; 配速5'10" stays a time).
std::optional<SpokenForm> read_feet_and_inches(const std::vector<CodePoint>& text, std::size_t start,
                                               const WrittenNumber& feet);

}  // namespace talkface::detail

#endif

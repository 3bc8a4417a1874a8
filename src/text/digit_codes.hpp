// Numbers that name by their digits, said one by one: phone and service numbers (幺 for 1 where
// dialled), rooms and buildings, codes and stock codes, models, trains and flights, versions, IP
// addresses: the part of the written-form reader that tells them from counts (docs/written-forms.md).
#ifndef TALKFACE_TEXT_DIGIT_CODES_HPP
#define TALKFACE_TEXT_DIGIT_CODES_HPP

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "text/code_points.hpp"
#include "text/written_number_scan.hpp"
#include "text/written_numbers.hpp"

namespace talkface::detail {

// Words before which a number names a room, a bus route or a house, said digit by digit when it
// has three or more digits (305室 三零五室, 302路 三零二路).
bool names_by_digits(char32_t c);

// A room's or a building's name after the number at text[end): a word of up to three characters
// ending in 室 (302会议室, 306教室: a measure word first, 200间教室, counts) or 大楼 大厦 (台北101
// 大樓): the number names it as 305室 does.
bool names_room_or_building(const std::vector<CodePoint>& text, std::size_t end);

// A landmark or a district named by its number right after its city's name (台北101, 北京798, 台北市101): a
// number of three or four digits that counts nothing (no measure word, magnitude, 多 余 强 or 以上 after it:
// 上海101人, 北京300多所, 深圳500强 count), said digit by digit as its name is.
bool names_landmark_after_city(const std::vector<CodePoint>& text, std::size_t start,
                               const WrittenNumber& number);

// A place to meet named by its number alone, three or four digits after 在 and right before a verb of
// meeting (在101見 在一零一見, 在305碰面, 在1203等你): a landmark's or a room's name, said digit by digit,
// not a year (19xx, 20xx) nor a round hundred.
bool names_meeting_place(const std::vector<CodePoint>& text, std::size_t start, const WrittenNumber& number);

// Service and emergency numbers (110 police, 119 fire, 120 ambulance, 12345 the city's hotline,
// 10086 a carrier, 95xxx a bank's line; the government's 12xxx lines, 12123 traffic, 12366 tax,
// 12393 medical insurance, 12395 sea rescue): said digit by digit with 幺 where they are dialled or
// named (打110, 110报警), as cardinals where they count (120人, 时速120).
bool is_service_number(const std::string& digits);

// A five-digit service number is a name wherever it does not count (12306购票, 12315投诉, 95588):
// no one says 一万二千三百零六 of it. 12345 and 10000 are counts as often as names.
bool is_named_anywhere(const std::string& digits);

// A service number is dialled or named: a dialling word before it, with nothing between but
// the service's name or 给 (打110, 拨打客服热线10086, 打给120), or a service's name right after
// it (110报警, 120急救车), or the service naming itself as it answers (这里是110).
bool is_service_call(const std::vector<CodePoint>& text, std::size_t start, std::size_t end);

// A naming word right before the number (房间号是1208, 编号：305, and a code's: 密码是86753090,
// 验证码：5408), or a floor, a building or a staircase with its number before it (3楼302, 5栋1203,
// 2单元301: the room's number follows): said digit by digit as a room's number is.
bool follows_name_word(const std::vector<CodePoint>& text, std::size_t start);

// A word earlier in the sentence that makes the numbers after it phone numbers. 号码 after a card's,
// a document's or an account's name is theirs (身份证号码, 银行卡号码, 护照号码, 订单号码): read out,
// not dialled, so its digits are said with 一.
bool follows_phone_word(const std::vector<CodePoint>& text, std::size_t start);

// A hotline's word right after a number, 热线 or 专线 (1823熱線, 1999专线): the number is the line's, dialled
// as after a phone word (热线1999), where it was counted (session 32: 1823熱線 一千八百二十三).
bool precedes_hotline_word(const std::vector<CodePoint>& text, std::size_t end);

// 010-12345678, 0912-345-678: groups of digits joined by dashes, said digit by digit (a first group
// with a leading zero and seven digits or more in all, or three groups, or a phone word before).
// After a naming word (is_named: 取件码3-2-1108) three groups or more that start with one or two
// digits are a code's, said with 杠 between and 1 as 一, and so are a book's number's groups
// (is_book: ISBN 978-7-02-008701-9).
std::optional<SpokenForm> read_dashed_digits(const std::vector<CodePoint>& text, const WrittenNumber& first,
                                             bool is_phone, bool is_named, bool is_book);

// Right after ISBN or ISSN (a space or a colon between allowed): a book's or a journal's number, read out
// digit by digit with 1 as 一, its dashes 杠, as a code's (session 20: dialled, 幺, the dashes unsaid).
bool follows_book_number(const std::vector<CodePoint>& text, std::size_t start);

// A dash before a group of digits with a leading zero (A2024-0315, a document's, a case's or a
// product's number) joins a code's parts: no count is written with a leading zero, so it is no
// range. Each part is said digit by digit and the dash 杠, as codes are read out (session 14; it
// was 到). A year and a month (2024-03) are left as they were.
std::optional<SpokenForm> read_code_with_dash(const std::vector<CodePoint>& text, const WrittenNumber& first);

// A standard's number after its prefix (GB/T 19001-2016, GB 2762-2022, ISO 9001:2015, YY/T 0287-2017: GB,
// ISO and the other bodies' names, or capitals with /T or /Z, a space between or none) and the year of its
// edition after a dash or ISO's colon: the number and the year digit by digit, the dash 杠 as a code's and
// the colon unsaid, as the code is read out (session 31: a range, 到, and a ratio, 比). nullopt where no
// such prefix stands before `number` (at text[start]) or no year of four digits from 19 or 20 follows.
std::optional<SpokenForm> read_standard_code(const std::vector<CodePoint>& text, std::size_t start,
                                             const WrittenNumber& number);

// A processor's series and model joined by a hyphen (i7-13700H, R7-7840HS, i5-12400F): one or two letters
// and the series' one or two digits (`first`, at text[start]), the hyphen, and a model's number of three or
// more digits with its capital suffix. The series counts, the model is said digit by digit and the hyphen
// not at all, as reviews read them (i七 一三七零零 H; session 20: a range, 七到一三七零零).
std::optional<SpokenForm> read_series_and_model(const std::vector<CodePoint>& text, std::size_t start,
                                                const WrittenNumber& first);

// An aircraft's variant after its model's number (`model`, three or more digits after a model's name:
// A320-200, 波音737-800, A350-1000): a hyphen and a round hundred or thousand, counted, or one digit (737-8),
// the model said digit by digit and the hyphen not at all, as pilots and spotters say them (A三二零二百,
// 七三七八百, 七三七八; session 21: a range, 三二零到二零零).
std::optional<SpokenForm> read_model_variant(const std::vector<CodePoint>& text, std::size_t start,
                                             const WrittenNumber& model);

bool follows_model_name(const std::vector<CodePoint>& text, std::size_t start);

// A model's number of three or more digits after its line's name and number with spaces between (XPS 13
// 9340 九三四零, a laptop's generation after its size: one or two digits in the line), no character after
// it: a model's, said digit by digit (it counted, 九千三百四十).
bool follows_model_name_and_number(const std::vector<CodePoint>& text, std::size_t start, std::size_t end);

// A respirator's filter grade (N95, KN95, P99: a class N R P KN KP and 90, 95 or 99, the share of
// particles it stops) or an enclosure's protection rating (IP68, IP54): a grade's name, said digit
// by digit (N九五, IP六八), where a model's two digits count (G20 G二十).
bool is_filter_grade(const std::vector<CodePoint>& text, std::size_t start, const std::string& digits);
// A camera's sensitivity after ISO (ISO 3200, the top of ISO 100-3200): a count, 三千二百, where a standard's
// number after ISO (ISO 9001) is a code said digit by digit.
bool is_camera_sensitivity(const std::vector<CodePoint>& text, std::size_t start, const std::string& digits);

// Right after a word with a small letter, with nothing between (Tiger2024, user123): a user
// name's or an ID's digits. (iPhone15 counts: fewer than three digits, as a model's do.)
bool follows_glued_name(const std::vector<CodePoint>& text, std::size_t start);

// Three or four digits after a hyphen that follows a name of letters with a capital (mRNA-1273, Boeing-747),
// or before a graphics card's suffix (8800 GT, 4090 Ti, 7900 XTX, and 8800gt as chat writes it: session
// 28, 八千八百): a code's or a model's digits, said one by one, where two after the hyphen count (COVID-19
// 十九) and no card's suffix leaves a count (8800元).
bool names_code_by_letters(const std::vector<CodePoint>& text, std::size_t start,
                           const WrittenNumber& number);

// A bare four-digit number shaped as a graphics card's (4090, 3060) in a sentence that named a card of that
// shape before it (这块RTX 3090用了三年，我打算换4090; RTX 4080的性能接近4090): that card's kind, said digit
// by digit as gamers say it (四零九零; session 28: 四千零九十). A count's measure after it (2060元) keeps a
// count.
bool repeats_card_model(const std::vector<CodePoint>& text, std::size_t start, const WrittenNumber& number);

// A graphics card's suffix starting at text[i], in capitals or not: GT GTS GTX XT XTX Ti.
bool is_card_suffix_at(const std::vector<CodePoint>& text, std::size_t i);

// The letters at text[start] are a card's suffix right after its four digits, a space between or none
// (RTX 4070 Ti, 1080ti): its letters, said one by one (Ti ti ai; session 28: the pinyin ti).
bool follows_card_model(const std::vector<CodePoint>& text, std::size_t start);

// Right after the Chinese name of an aircraft's maker (波音737, 空客 320) or of a chip's series
// (天玑9400 天玑九四零零, 骁龙888, 麒麟990, 鲲鹏920, 昇腾910, as reviews and news say them; session 14,
// they counted): its model's number. So are their Latin names (Boeing 737, Airbus 320, Snapdragon 865,
// Dimensity 9400, Kirin 9000; session 29: they counted).
bool follows_maker_name(const std::vector<CodePoint>& text, std::size_t start);

// A number that names by its digits what it stands for, said one by one with 一 for 1 (where no
// measure word or unit makes it count):
// - a stock's code alone in brackets after the company's name (贵州茅台（600519）, 台積電（2330）,
//   腾讯控股(00700.HK)): four to six digits, a closing bracket or the exchange's suffix after them;
//   so is a year in a document's number (国发〔2024〕10号 国发二零二四十号);
// - the Nikkei's number (日经225 日经二二五, as Japanese and Chinese market news say it; the other
//   indices count their shares: 沪深300 三百, 标普500 五百);
// - a programme's number before its word (985高校, 211工程, 863计划), also in a list joined by 、 or a
//   slash (985、211高校, 985/211/双一流高校);
// - a video's resolution, lines and a p (1080P 一零八零P, 720p);
// - a battery cell's format, its diameter and length in millimetres, before 电池 电芯 锂电 圆柱
//   (4680大圆柱电池 四六八零, 18650电芯 一八六五零, 21700电池; session 30: they counted): four or five
//   digits, not a round thousand.
bool names_by_its_digits(const std::vector<CodePoint>& text, std::size_t start, const WrittenNumber& number);

// Whether text[k] starts 双一流 (雙一流), the third name of China's top schools after 985 and 211, which a
// list of the three writes after a slash (985/211/双一流高校) that is no per's.
bool names_top_schools(const std::vector<CodePoint>& text, std::size_t k);

// A version after a software's name and a space (Python 3.12, iOS 17.12: a word with a small
// letter), right after a v (v2.15, V3.12) or after 版本 (新版本13.24, 版本号：2.3.10).
bool follows_software_name(const std::vector<CodePoint>& text, std::size_t start);

// The Chinese designation of an aircraft, a missile or a rocket before a hyphen (歼-20 歼二十, 运-20,
// 东风-41, 长征-5): the hyphen joins, it is no minus sign.
bool follows_designation(const std::vector<CodePoint>& text, std::size_t dash);

// A chemical element's name right before text[start] (碳-14, 铀-235, 碘131): an isotope's mass number,
// joined to it by a hyphen, which is no minus sign, and said as a model's number is (碳十四, 铀二三五).
bool follows_element(const std::vector<CodePoint>& text, std::size_t start);

// A train's number: one capital of a train's class (G D C Z T K L Y S) right before the digits and
// 次 after them (G1234次: 次 names the train there, it does not count) or 车次 before them in the
// clause (车次：G101).
bool is_train_number(const std::vector<CodePoint>& text, std::size_t start, std::size_t end);

// A train's number without a class's capital, one to four digits, as Taiwan's railway numbers its trains
// and the mainland its oldest: 次 after it and a train's kind right before it or after 次 (自強號123次,
// 2101次區間車, 普快1461次), or 車次 right before or after it (車次：123, 4235車次). A count of times
// (坐了100次火车) has neither beside it.
bool is_unlettered_train_number(const std::vector<CodePoint>& text, std::size_t start, std::size_t end);

// A flight's number: an airline's two capitals and three or four digits (CA1831, MU 5101), with
// 航班 or 班机 right after it or earlier in the clause (航班号CA1831).
bool is_flight_number(const std::vector<CodePoint>& text, std::size_t start, std::size_t end);

// A country calling code, +86: said 加八六 as the + key is named, with the phone number that
// follows it in groups (+86 10 6512 3456), digit by digit with 幺 for 1. A + and one to three
// digits is one where a group follows, a phone word is earlier in the sentence, or 区号 stands
// right before it; elsewhere it is a sign (+5 正五).
std::optional<SpokenForm> read_calling_code(const std::vector<CodePoint>& text, std::size_t start);

// Three or more groups of digits joined by dots: a date (2026.03.15: a four-digit year, a month
// and a day, 二零二六年三月十五日), an IP address (four groups of up to three digits, each at most
// 255: 192.168.1.1 一九二点一六八点一点一, digit by digit as it is read out) or a version (1.2.3
// 一点二点三, 10.15.7 十点十五点七: each group a number, 点 between).
std::optional<SpokenForm> read_dotted_groups(const std::vector<CodePoint>& text, std::size_t start);

// Past a stock code's exchange suffix (00700.HK, 600519.SH, 2330.TW: a dot and an exchange's capitals,
// is_exchange_suffix), which is not said, as market news reads the code (session 15: it was 点 H K):
// where the code's form ends; `end` itself where no suffix follows.
std::size_t past_exchange_suffix(const std::vector<CodePoint>& text, std::size_t end);

// A floor written with an F after its number, as Taiwan, Hong Kong and shopping centres write it (2F
// 二楼, 89F 八十九楼, 1F 一楼), or a slash and the F, as Hong Kong's addresses do (3/F 三楼; session 32:
// 三 ai fu): the number as an ordinal is said, and 楼 for the F (session 15: it was 二 F). Up to three digits
// after no letter (B1F is a basement's), a capital F that ends the letters (°F and 100℉ are Fahrenheit's, a
// unit), and no seat's (12F号, 12F座, 7车12F, 3号车厢12F, 座位是12F; session 18 and 45: 十二楼). nullopt
// elsewhere.
std::optional<SpokenForm> read_floor(const std::vector<CodePoint>& text, std::size_t start, const WrittenNumber& number);

// Whether the clause before text[start) names a seat (座位 座号 座席 位子 选座 登机牌 值机, a window or an
// aisle seat, 靠窗 靠过道, Simplified or Traditional), or the number is sat in (坐32A, 坐在12F), so that a
// number and a letter after it are a seat's row and letter, said as they are written (座位是12F 十二 F,
// 登机牌上写着32A 三十二 A; session 45: 十二楼, 三十二安; 我坐32A, 靠窗的12A; session 46: 三十二安), not a
// floor or amperes.
bool names_seat_before(const std::vector<CodePoint>& text, std::size_t start);

// A number masked from its start (尾号****5678, 卡号：****1234), as a bank's or a shop's message shows a
// card's or a phone's tail: no digits before the stars hold a place, so they are unsaid, and the digits after
// them are said one by one as a masked number's are (尾号五六七八; session 32: each star skipped with a
// warning, the digits counted), dialled with 幺 after a phone's word. nullopt where no run of stars starts a
// number at text[start].
std::optional<SpokenForm> read_masked_tail(const std::vector<CodePoint>& text, std::size_t start);

// A number with some of its digits masked by stars, as a prize list or a login notice shows a phone's or a
// card's (138****6621, 6222****1234): its digits one by one and each star 星, as such a number is read out;
// a mobile's (eleven places, the first a 1) or one after a phone's word dialled, its 1 幺. `number` starts
// the form; nullopt where no run of two stars or more follows its digits.
std::optional<SpokenForm> read_masked_number(const std::vector<CodePoint>& text, const WrittenNumber& number,
                                             bool is_phone);

}  // namespace talkface::detail

#endif

#include "text/written_numbers.hpp"

#include <algorithm>
#include <string_view>
#include <utility>

#include "text/latin_words.hpp"
#include "text/number_words.hpp"

namespace talkface::detail {

namespace {

bool is_digit_at(const std::vector<CodePoint>& text, std::size_t i) {
    if (i >= text.size()) return false;
    const auto c = ascii_form(text[i].value);
    return c >= '0' && c <= '9';
}

char32_t value_at(const std::vector<CodePoint>& text, std::size_t i) {
    return i < text.size() ? ascii_form(text[i].value) : 0;
}

std::string digits_from(const std::vector<CodePoint>& text, std::size_t& i) {
    std::string digits;
    while (is_digit_at(text, i)) digits += static_cast<char>(ascii_form(text[i++].value));
    return digits;
}

// A number as written: 1,234.5 is whole "1234", fraction "5".
struct WrittenNumber {
    std::string whole;
    std::string fraction;
    bool has_point = false;
    bool has_separators = false;
    std::size_t end = 0;
};

WrittenNumber parse_number(const std::vector<CodePoint>& text, std::size_t i) {
    WrittenNumber number;
    number.whole = digits_from(text, i);
    // Thousands separators: an ASCII comma and exactly three digits (1,234,567). The ideographic
    // comma ，stays a pause: 1，2，3 is a list.
    if (number.whole.size() <= 3) {
        while (i + 3 < text.size() + 1 && text[i].value == ',' && is_digit_at(text, i + 1) &&
               is_digit_at(text, i + 2) && is_digit_at(text, i + 3) && !is_digit_at(text, i + 4)) {
            for (std::size_t k = 1; k <= 3; ++k) number.whole += static_cast<char>(ascii_form(text[i + k].value));
            number.has_separators = true;
            i += 4;
        }
    }
    if (value_at(text, i) == '.' && is_digit_at(text, i + 1)) {
        ++i;
        number.has_point = true;
        number.fraction = digits_from(text, i);
    }
    number.end = i;
    return number;
}

// A month and a day of it, each of one or two digits (a longer run is no date, and is not parsed
// as a number: 2026-12-123456789012345678901 is read digit by digit, not thrown on).
bool is_month_and_day(const std::string& month, const std::string& day) {
    if (month.empty() || month.size() > 2 || day.empty() || day.size() > 2) return false;
    const int month_value = std::stoi(month);
    const int day_value = std::stoi(day);
    return month_value >= 1 && month_value <= 12 && day_value >= 1 && day_value <= 31;
}

bool is_one_of(char32_t c, std::u32string_view set) {
    return set.find(c) != std::u32string_view::npos;
}

std::string text_between(const std::vector<CodePoint>& text, std::size_t first, std::size_t end) {
    std::string between;
    for (std::size_t i = first; i < std::min(end, text.size()); ++i) between += text[i].text;
    return between;
}

// Measure words and magnitudes before which 2 is 两 (两本书, 两个, 两万, 两步, 两男三女). Not 月 号
// 日 楼 路 度 代, where 2 is a name or an ordinal (二月, 二号, 二楼, 二代).
bool takes_liang(char32_t c) {
    return is_one_of(c, U"个個本位名只隻条條张張件次天年岁歲人种種块塊元倍台臺部辆輛家份杯碗瓶双雙对對层層场場"
                        U"周週遍斤米千万萬亿億百项項篇首页頁座所间間节節门門架把支枝根片头頭匹颗顆粒趟套声聲句"
                        U"样樣章口股群批排队隊段堆吨噸升克里码碼毛角点點成分秒小公届屆期美港欧歐英"
                        U"步下回圈眼拳脚腳刀枪槍盒包袋箱桶罐盘盤幅集册冊封轮輪局男女"
                        U"勺匙滴串束朵棵株盆锅鍋桌副顶頂艘连連"
                        // A record's wins, losses and draws (3局2胜 三局两胜, 2胜1负 两胜一负; session 14).
                        U"胜勝负負平"
                        // A medal table's golds, silvers and bronzes (奪得2金5銅 兩金五銅; session 14).
                        U"金银銀铜銅");
}

// Words before which a number names a room, a bus route or a house, said digit by digit when it
// has three or more digits (305室 三零五室, 302路 三零二路).
bool names_by_digits(char32_t c) {
    return is_one_of(c, U"室房路号號");
}

// A room's or a building's name after the number at text[end): a word of up to three characters
// ending in 室 (302会议室, 306教室: a measure word first, 200间教室, counts) or 大楼 大厦 (台北101
// 大樓): the number names it as 305室 does.
bool names_room_or_building(const std::vector<CodePoint>& text, std::size_t end) {
    constexpr std::size_t kLongestWord = 3;  // characters: 会议室, 办公室
    if (end >= text.size() || takes_liang(text[end].value)) return false;
    for (std::size_t k = end; k < std::min(text.size(), end + kLongestWord); ++k)
        if (is_one_of(text[k].value, U"室")) return true;
    const auto word = text_between(text, end, end + 2);
    return word == "大楼" || word == "大樓" || word == "大厦" || word == "大廈";
}

// Service and emergency numbers (110 police, 119 fire, 120 ambulance, 12345 the city's hotline,
// 10086 a carrier, 95xxx a bank's line; the government's 12xxx lines, 12123 traffic, 12366 tax,
// 12393 medical insurance, 12395 sea rescue): said digit by digit with 幺 where they are dialled or
// named (打110, 110报警), as cardinals where they count (120人, 时速120).
bool is_service_number(const std::string& digits) {
    for (const std::string_view number : {"110", "112", "114", "119", "120", "122", "999", "12110", "12117", "12121",
                                          "12123", "12306", "12308", "12309", "12315", "12318", "12320", "12328", "12333",
                                          "12338", "12345", "12348", "12355", "12358", "12365", "12366", "12369", "12378",
                                          "12380", "12388", "12393", "12395", "10000", "10010", "10086"})
        if (digits == number) return true;
    return digits.size() == 5 && (digits.rfind("95", 0) == 0 || digits.rfind("96", 0) == 0);
}

// A five-digit service number is a name wherever it does not count (12306购票, 12315投诉, 95588):
// no one says 一万二千三百零六 of it. 12345 and 10000 are counts as often as names.
bool is_named_anywhere(const std::string& digits) {
    return digits.size() == 5 && digits != "12345" && digits != "10000";
}

bool ends_with(const std::string& text, std::string_view end) {
    return text.size() >= end.size() && text.compare(text.size() - end.size(), end.size(), end) == 0;
}

// Names of a service, said with its number: before it (客服热线10086) or after it (110报警).
constexpr std::string_view kServiceWords[] = {"报警", "報警", "急救", "火警", "查号", "查號", "热线", "熱線", "电话",
                                              "電話", "服务", "服務", "客服", "求助", "救护", "救護", "平台", "平臺",
                                              "专线", "專線", "中心", "号码", "號碼"};

// A service number is dialled or named: a dialling word before it, with nothing between but
// the service's name or 给 (打110, 拨打客服热线10086, 打给120), or a service's name right after
// it (110报警, 120急救车).
bool is_service_call(const std::vector<CodePoint>& text, std::size_t start, std::size_t end) {
    constexpr std::size_t kLookBack = 12;  // code points: a dialling word and a service's name or two
    std::string before = text_between(text, start >= kLookBack ? start - kLookBack : 0, start);
    for (bool stripped = true; stripped;) {
        stripped = false;
        for (const std::string_view word : kServiceWords) {
            if (ends_with(before, word)) {
                before.erase(before.size() - word.size());
                stripped = true;
            }
        }
        for (const std::string_view word : {"给", "給", " "}) {
            if (ends_with(before, word)) {
                before.erase(before.size() - word.size());
                stripped = true;
            }
        }
    }
    for (const std::string_view word : {"打", "拨", "撥", "叫", "call", "Call"})
        if (ends_with(before, word)) return true;
    const std::string after = text_between(text, end, end + 2);
    for (const std::string_view word : kServiceWords)
        if (after.rfind(word, 0) == 0) return true;
    return false;
}

// The text before text[start] back to the last end mark or line break (the sentence so far), and
// with `clause_only` to the last pause mark too.
std::string text_before(const std::vector<CodePoint>& text, std::size_t start, bool clause_only) {
    std::string before;
    for (std::size_t i = start; i-- > 0;) {
        const auto c = ascii_form(text[i].value);
        if (c == '.' || c == '!' || c == '?' || c == ';' || c == 0x3002 || c == '\n') break;
        if (clause_only && (c == ',' || c == 0x3001 /*、*/)) break;
        before.insert(0, text[i].text);
    }
    return before;
}

// The text after text[end) up to the next pause or end mark (the rest of the clause; 、 does not
// end it: 6-3、6-4 获胜 is one clause).
std::string text_after(const std::vector<CodePoint>& text, std::size_t end) {
    std::string after;
    for (auto i = end; i < text.size(); ++i) {
        const auto c = ascii_form(text[i].value);
        if (c == '.' || c == '!' || c == '?' || c == ';' || c == ',' || c == 0x3002 || c == '\n') break;
        after += text[i].text;
    }
    return after;
}

// Two numbers joined by a colon are a score, not a clock time, where the sentence speaks of a
// match: a score word earlier in the clause (比分是21:19) or a result right after (2:0战胜,
// 21:19获胜). Without either, a colon that can be a time is one (下午3:30). Joined by a dash
// (`dashed`), they are a score where a result of two characters comes anywhere later in the clause
// too, as a tennis result lists its sets first (6-3、6-4直落两盘获胜): a dash makes no clock time to
// mistake, only a range, which the caller tells by its measure word (3-5天后获胜).
bool is_score(const std::vector<CodePoint>& text, std::size_t start, std::size_t end, bool dashed = false) {
    const std::string before = text_before(text, start, true);
    for (const std::string_view word : {"比分", "比數", "比数", "战成", "戰成", "打成", "踢成"})
        if (before.find(word) != std::string::npos) return true;
    const std::string after = text_between(text, end, end + 2);
    constexpr std::string_view kResults[] = {"战胜", "戰勝", "击败", "擊敗", "获胜", "獲勝", "取胜", "取勝", "领先", "領先",
                                             "落后", "落後", "险胜", "險勝", "大胜", "大勝", "完胜", "完勝", "逆转", "逆轉",
                                             "告负", "告負", "战平", "戰平", "打平", "逼平", "胜", "勝", "负", "負", "赢",
                                             "贏", "输", "輸"};
    for (const auto word : kResults)
        if (after.rfind(word, 0) == 0) return true;
    if (!dashed) return false;
    const std::string clause = text_after(text, end);
    for (const auto word : kResults)
        if (word.size() > std::string_view("胜").size() && clause.find(word) != std::string::npos) return true;
    return false;
}

// A colon's time where the clause speaks of how long something took (跑出了2:05:30的成绩, 用时3:35):
// a duration, 两小时零五分三十秒, 三分三十五秒, not a time of day.
bool speaks_of_duration(const std::vector<CodePoint>& text, std::size_t start) {
    const std::string before = text_before(text, start, true);
    for (const std::string_view word : {"成绩", "成績", "用时", "用時", "耗时", "耗時", "历时", "歷時", "跑出", "游出",
                                        "完赛", "完賽", "时长", "時長"})
        if (before.find(word) != std::string::npos) return true;
    return false;
}

// A day named by its date's digits (520 五二零, 618大促 六一八大促, 今天是1111): three or four digits
// that are a month and a day, a festival's or a sale's word right after them or a day's before
// them (今天是). Elsewhere such a number counts (520人, 股价涨到了520).
bool names_a_day(const std::vector<CodePoint>& text, std::size_t start, const WrittenNumber& number) {
    const auto& digits = number.whole;
    if (number.has_point || number.has_separators || digits.size() < 3 || digits.size() > 4) return false;
    const auto month_length = digits.size() - 2;
    if (!is_month_and_day(digits.substr(0, month_length), digits.substr(month_length))) return false;
    const std::string after = text_between(text, number.end, number.end + 3);
    for (const std::string_view word : {"节", "節", "大促", "促销", "促銷", "购物", "購物", "晚会", "晚會", "活动", "活動",
                                        "当天", "當天", "这天", "這天", "那天", "快乐", "快樂", "狂欢", "狂歡", "表白"})
        if (after.rfind(word, 0) == 0) return true;
    const std::string before = text_before(text, start, true);
    for (const std::string_view word : {"今天是", "明天是", "昨天是", "后天是", "後天是", "今天就是", "又到了", "迎来", "迎來"})
        if (ends_with(before, word)) return true;
    return false;
}

// Four digits before 年 name a year (2026年 二零二六年) unless they count years: a number past any
// year a text names as a date (距今约5000年: no one dates by the year 5000), a year before the common
// era, said as a count (公元前2070年 公元前两千零七十年), or a span with 历史 or 之久 after it (1200年
// 历史, 3000年之久).
bool counts_years(const std::vector<CodePoint>& text, std::size_t start, const WrittenNumber& number) {
    constexpr int kLatestYearNamed = 2100;
    if (number.has_point || number.has_separators || number.whole.size() != 4 || value_at(text, number.end) != U'年')
        return false;
    if (std::stoi(number.whole) > kLatestYearNamed || ends_with(text_before(text, start, true), "公元前")) return true;
    const std::string after = text_between(text, number.end + 1, number.end + 4);
    for (const std::string_view word : {"历史", "歷史", "的历史", "的歷史", "之久"})
        if (after.rfind(word, 0) == 0) return true;
    return false;
}

// A year that names what follows it without 年 (2025财年, 2025赛季, 2026款, 2025届, 2024版, 2023级, 2026春晚,
// 2030世界杯): digit by digit, as a year is (二零二五财年); a count elsewhere (2000人, 2000多).
bool names_year_before_word(const std::vector<CodePoint>& text, const WrittenNumber& number) {
    if (number.has_point || number.has_separators || number.whole.size() != 4 ||
        !(number.whole.rfind("19", 0) == 0 || number.whole.rfind("20", 0) == 0)) {
        return false;
    }
    const std::string after = text_between(text, number.end, number.end + 3);
    for (const std::string_view word : {"财年", "財年", "赛季", "賽季", "款", "届", "屆", "级", "級", "版", "春晚", "世界杯",
                                        "奥运", "奧運", "冬奥", "冬奧", "亚运", "亞運", "全运", "全運"})
        if (after.rfind(word, 0) == 0) return true;
    return false;
}

// A bonus to a game's attribute (攻击力+15, 暴击率+5%, 防御+20, 攻击速度+10%): the + is 加, as a
// game's screen is read. The attribute is a word ending in 力 or 值 (攻击力, 经验值), or one of the
// stats games show, alone or with 率 after it (暴击率, 命中率).
bool follows_game_attribute(const std::vector<CodePoint>& text, std::size_t start) {
    if (start == 0) return false;
    if (is_one_of(text[start - 1].value, U"力值")) return true;
    std::string before = text_before(text, start, true);
    if (ends_with(before, "率")) before.erase(before.size() - std::string_view("率").size());
    for (const std::string_view stat : {"攻击", "攻擊", "攻速", "速度", "移速", "防御", "防禦", "护甲", "護甲", "魔抗",
                                        "暴击", "暴擊", "暴伤", "暴傷", "闪避", "閃避", "命中", "生命", "血量", "法力",
                                        "伤害", "傷害", "穿透", "吸血", "韧性", "韌性", "格挡", "格擋", "抗性", "敏捷",
                                        "力量", "智力", "体质", "體質", "耐力", "精神", "经验", "經驗", "金币", "金幣"})
        if (ends_with(before, stat)) return true;
    return false;
}

// A word earlier in the clause that names a change (涨幅, 增长, 上升, 同比): a + after it is not said.
bool names_change(const std::vector<CodePoint>& text, std::size_t start) {
    const std::string before = text_before(text, start, true);
    for (const std::string_view word : {"涨", "漲", "跌", "增", "升", "降", "减", "減", "幅", "同比", "环比", "環比"})
        if (before.find(word) != std::string::npos) return true;
    return false;
}

// A naming word right before the number (房间号是1208, 编号：305, and a code's: 密码是86753090,
// 验证码：5408), or a floor, a building or a staircase with its number before it (3楼302, 5栋1203,
// 2单元301: the room's number follows): said digit by digit as a room's number is.
bool follows_name_word(const std::vector<CodePoint>& text, std::size_t start) {
    std::size_t i = start;
    for (int skipped = 0; skipped < 2 && i > 0 && is_one_of(text[i - 1].value, U" 是为為：:\u3000"); ++skipped) --i;
    if (i > 0 && is_one_of(text[i - 1].value, U"号號室房码碼")) return true;
    // A postcode after 邮编 (邮编100080 一零零零八零; session 14: it counted), as 邮政编码 is after 码.
    if (const auto word = text_between(text, i >= 2 ? i - 2 : 0, i); word == "邮编" || word == "郵編") return true;
    if (start >= 2 && is_one_of(text[start - 1].value, U"楼樓栋棟层層") && is_digit_at(text, start - 2)) return true;
    const auto staircase = text_between(text, start >= 2 ? start - 2 : 0, start);
    return (staircase == "单元" || staircase == "單元") && start >= 3 && is_digit_at(text, start - 3);
}

// A word earlier in the sentence that makes the numbers after it phone numbers. 号码 after a card's,
// a document's or an account's name is theirs (身份证号码, 银行卡号码, 护照号码, 订单号码): read out,
// not dialled, so its digits are said with 一.
bool follows_phone_word(const std::vector<CodePoint>& text, std::size_t start) {
    const std::string before = text_before(text, start, false);
    for (const std::string_view word : {"电话", "電話", "手机", "手機", "热线", "熱線", "拨打", "撥打", "致电", "致電",
                                        "分机", "分機", "传真", "傳真", "座机", "座機", "固话", "固話"}) {
        if (before.find(word) != std::string::npos) return true;
    }
    // Right after an area code in brackets, (07)123-4567 and （02）2345-6789, as Taiwan writes a
    // number: the rest is the number (session 14: 123-4567 was a range).
    if (start >= 4 && is_one_of(value_at(text, start - 1), U")\uFF09")) {
        auto k = start - 1;
        std::size_t digits = 0;
        while (k > 0 && is_digit_at(text, k - 1)) {
            --k;
            ++digits;
        }
        constexpr std::size_t kLongestAreaCode = 4;
        if (digits >= 2 && digits <= kLongestAreaCode && value_at(text, k) == '0' && k > 0 &&
            is_one_of(value_at(text, k - 1), U"(\uFF08")) {
            return true;
        }
    }
    for (const std::string_view word : {"号码", "號碼"}) {
        for (auto at = before.find(word); at != std::string::npos; at = before.find(word, at + 1)) {
            const auto owner = before.substr(0, at);
            bool not_a_phone = false;
            for (const std::string_view document : {"证", "證", "卡", "照", "单", "單", "户", "戶", "票"})
                not_a_phone = not_a_phone || ends_with(owner, document);
            if (!not_a_phone) return true;
        }
    }
    return false;
}

struct Unit {
    std::string_view written;
    const char* words;
};

// Latin unit symbols right after a number (5km, 2 kg). Case matters: m is metres, M is not a unit.
constexpr Unit kUnits[] = {
    {"km", "公里"}, {"m", "米"}, {"cm", "厘米"}, {"mm", "毫米"}, {"kg", "公斤"}, {"g", "克"},
    {"mg", "毫克"}, {"t", "吨"}, {"ml", "毫升"}, {"mL", "毫升"}, {"L", "升"}, {"h", "小时"},
    {"min", "分钟"}, {"s", "秒"}, {"ms", "毫秒"}, {"Hz", "赫兹"}, {"kHz", "千赫"}, {"MHz", "兆赫"},
    {"kW", "千瓦"}, {"W", "瓦"}, {"V", "伏"}, {"mAh", "毫安时"}, {"kWh", "千瓦时"}, {"km/h", "公里每小时"},
    {"m/s", "米每秒"}, {"m²", "平方米"}, {"km²", "平方公里"}, {"㎡", "平方米"}, {"㎞", "公里"}, {"㎏", "公斤"},
    {"℃", "摄氏度"}, {"℉", "华氏度"}, {"°C", "摄氏度"}, {"°F", "华氏度"}, {"°", "度"}, {"%", ""},
    // Session 13: the units news writes of chips, networks, power, weather and blood tests, said by
    // their Chinese names as newsreaders say them (3nm 三纳米, 950hPa 九百五十百帕, 50dB 五十分贝);
    // bits per second by their names too (500Mbps 五百兆比特每秒; 千兆 for 1000Mbps is a fix in
    // place), where KB MB GB are said as letters (is_byte_unit_at). μ is written as the Greek mu or
    // the micro sign.
    {"nm", "纳米"}, {"μm", "微米"}, {"µm", "微米"}, {"μg", "微克"}, {"µg", "微克"}, {"m³", "立方米"},
    {"cm²", "平方厘米"}, {"cm³", "立方厘米"}, {"GHz", "吉赫兹"}, {"dB", "分贝"}, {"MW", "兆瓦"}, {"GW", "吉瓦"},
    {"MWh", "兆瓦时"}, {"GWh", "吉瓦时"}, {"TWh", "太瓦时"}, {"kV", "千伏"}, {"mA", "毫安"}, {"Pa", "帕"},
    {"hPa", "百帕"}, {"kPa", "千帕"}, {"MPa", "兆帕"}, {"kbps", "千比特每秒"}, {"Mbps", "兆比特每秒"},
    {"Gbps", "吉比特每秒"}, {"mol", "摩尔"}, {"mmol", "毫摩尔"}, {"kcal", "千卡"},
    // Session 14: the units a physics lesson writes, by the names it reads them by (220V 二百二十伏
    // was there): 3.6×10⁶J 焦耳, 20N 牛, 0.5A 安, 10Ω 欧 (the Greek capital or the ohm sign), and
    // the kilowatt-hour with its product dot (1kW·h 一千瓦时, as kWh is). J N A alone are units only
    // where no Chinese word but 的 follows them (5A景区, a grade, and 3A游戏 are said 五A, 三A).
    {"J", "焦耳"}, {"kJ", "千焦"}, {"N", "牛"}, {"A", "安"}, {"Ω", "欧"}, {"Ω", "欧"}, {"kΩ", "千欧"},
    {"kW·h", "千瓦时"}, {"kW⋅h", "千瓦时"}, {"m/s²", "米每二次方秒"},
};

// A unit of one capital (J N A) that a grade or a name also writes after a number: a unit only
// before 的 or anything but a Chinese character (0.5A。, 20N的力; not 5A景区).
bool is_lone_capital_unit_at(const std::vector<CodePoint>& text, const Unit& unit, std::size_t end) {
    if (unit.written != "J" && unit.written != "N" && unit.written != "A") return true;
    const auto next = value_at(text, end);
    return next == U'的' || next < 0x3400 || next > 0x9FFF;
}

// The unit written at text[i] (after at most one space when it is Latin), or nullptr.
const Unit* unit_at(const std::vector<CodePoint>& text, std::size_t i, std::size_t& end) {
    const auto start = value_at(text, i) == ' ' && is_ascii_letter(value_at(text, i + 1)) ? i + 1 : i;
    const Unit* best = nullptr;
    for (const auto& unit : kUnits) {
        std::string written;
        std::size_t k = start;
        while (k < text.size() && written.size() < unit.written.size()) {
            const auto c = ascii_form(text[k].value);  // ％ is %
            if (c < 0x80) {
                written += static_cast<char>(c);
            } else {
                written += text[k].text;
            }
            ++k;
        }
        if (written != unit.written) continue;
        // A Latin unit must end the letters: 5kgs or 3mind are words, not units; nor is a letter
        // between two numbers one (5V5 五 V 五, a match of five against five).
        if (is_ascii_letter(static_cast<char32_t>(unit.written.back())) &&
            (is_ascii_letter(value_at(text, k)) || is_digit_at(text, k))) {
            continue;
        }
        if (!is_lone_capital_unit_at(text, unit, k)) continue;
        if (best == nullptr || unit.written.size() > best->written.size()) {
            best = &unit;
            end = k;
        }
    }
    return best;
}

// KB MB GB TB PB after a number (256GB, 2 TB): a unit, so the number counts (两 TB, not a phone
// number's digits), said as its letters, which the Latin reader reads after the number.
bool is_byte_unit_at(const std::vector<CodePoint>& text, std::size_t i) {
    if (value_at(text, i) == ' ') ++i;
    return is_one_of(value_at(text, i), U"KMGTP") && value_at(text, i + 1) == 'B' && !is_ascii_letter(value_at(text, i + 2));
}

struct Currency {
    std::u32string_view written;
    const char* before;  // said before the amount
    const char* after;   // said after it
};

constexpr Currency kCurrencies[] = {
    {U"NT$", "新台币", "元"}, {U"US$", "", "美元"}, {U"HK$", "", "港元"}, {U"S$", "", "新加坡元"},
    {U"$", "", "美元"},      {U"¥", "", "元"},     {U"￥", "", "元"},     {U"€", "", "欧元"},
    {U"£", "", "英镑"},
};

const Currency* currency_at(const std::vector<CodePoint>& text, std::size_t i, std::size_t& end) {
    for (const auto& currency : kCurrencies) {
        std::size_t k = 0;
        while (k < currency.written.size() && i + k < text.size() && text[i + k].value == currency.written[k]) ++k;
        if (k == currency.written.size() && is_digit_at(text, i + k)) {
            end = i + k;
            return &currency;
        }
    }
    return nullptr;
}

constexpr const char* kTooLongWarning = "a number of more than 16 digits; read digit by digit";

// Whether text[start, end) stands alone as a clause: at the start of the text or after a mark that
// ends a clause (not a colon, which introduces a value), and before one or the end.
bool stands_alone(const std::vector<CodePoint>& text, std::size_t start, std::size_t end) {
    constexpr std::u32string_view kClauseMarks = U"，,。.！!？?～~…\n";
    auto before = start;
    while (before > 0 && text[before - 1].value == ' ') --before;
    auto after = end;
    while (after < text.size() && text[after].value == ' ') ++after;
    return (before == 0 || kClauseMarks.find(text[before - 1].value) != std::u32string_view::npos) &&
           (after == text.size() || kClauseMarks.find(text[after].value) != std::u32string_view::npos);
}

// How one number is said, given what follows it.
struct NumberContext {
    char32_t next = 0;          // the code point after the form ('%' counts as the unit)
    bool has_unit = false;      // a unit follows (5km): a measure, so 2 is 两
    bool is_ordinal = false;    // 第 before it
    bool is_phone = false;      // a phone word earlier in the sentence
    bool is_named = false;      // a naming word right before it (房间号是1208)
    bool is_service_call = false;  // dialled or named (打110, 110报警)
    bool is_model = false;      // right after the capitals of a model's name (C919, A380) or a maker (波音737)
    bool is_train = false;      // a train's or a flight's number (G1234次, CA1831航班)
    bool has_currency = false;  // a currency sign before it (¥666)
    bool names_place = false;   // a room's or a building's name after it (302会议室, 101大楼)
    bool names_day = false;     // a day named by its date's digits (618大促, 今天是520)
    bool names_type = false;    // before 型 or 式, a type's number (737型, 99式)
    bool is_generation = false;  // two digits right before 后 (90后, 00后)
    bool is_hundredths = false;  // right after the seconds of a time (9秒83)
    bool is_grade = false;       // a respirator's filter grade (N95)
    bool is_span_of_years = false;  // four digits before 年 that count years, not name one (距今约5000年)
    bool is_code = false;        // a stock's code, an index's or a programme's number (（600519）, 日经225, 985高校)
    bool is_version = false;     // after a software's name or a v (Python 3.12, v2.15): a version
    bool names_year = false;     // a year before a word it names (2025财年, 2026款)
    bool after_laugh = false;    // right after a laugh's character (哈哈233)
    bool is_whole_clause = false;  // the number alone between clause marks (88，下次再聊)
};

struct SaidNumber {
    std::string words;
    bool is_year = false;
    bool is_dialled = false;  // a phone's or a service's number, 1 said 幺
    std::string warning;
};

SaidNumber say_number(const WrittenNumber& number, const NumberContext& context) {
    SaidNumber said;
    const auto& whole = number.whole;
    if (number.has_point) {
        // A version's part after the point is a number (Python 3.12 三点十二, as 10.15.7 is 十点十五点七);
        // a decimal's digits are said one by one (3.12 三点一二).
        const bool counts = context.has_unit || takes_liang(context.next) || context.next == '%';
        if (context.is_version && !counts && whole.size() <= kMostCardinalDigits && number.fraction.size() >= 2 &&
            number.fraction.size() <= kMostCardinalDigits && number.fraction.front() != '0') {
            said.words = cardinal_words(whole, false) + "点" + cardinal_words(number.fraction, false);
            return said;
        }
        if (whole.size() > kMostCardinalDigits) {
            said.words = digit_words(whole) + "点" + digit_words(number.fraction);
            said.warning = "more than 16 digits before the point; read digit by digit";
        } else {
            said.words = decimal_words(whole, number.fraction);
        }
        return said;
    }
    if (whole.size() > kMostCardinalDigits) {
        said.words = digit_words(whole);
        said.warning = kTooLongWarning;
        return said;
    }
    if (!number.has_separators) {
        const bool is_mobile = whole.size() == 11 && whole.front() == '1';
        // A phone word earlier in the sentence does not make an amount a phone number (这款手机售价5999元).
        const bool counts = !context.is_train && (context.has_unit || takes_liang(context.next) || context.next == '%');
        if ((context.is_phone && whole.size() >= 3 && !counts) || is_mobile) {
            said.words = digit_words(whole, true);
            said.is_dialled = true;
            return said;
        }
        // An hour written with two digits before 时 or 点 is the hour (06时 六时, 00时 零时), as the
        // weather's and the timetables' 24-hour clock is read; elsewhere a leading zero is read out.
        if (whole.size() == 2 && whole.front() == '0' && is_one_of(context.next, U"时時点點")) {
            said.words = digit_words(whole.substr(1));
            return said;
        }
        if (whole.size() >= 2 && whole.front() == '0') {
            said.words = digit_words(whole);
            return said;
        }
        // A train's or a flight's number is said digit by digit with 幺 for 1, as station and
        // airport announcers say it (G101次 G幺零幺次, CA1831 C A 幺八三幺).
        if (context.is_train) {
            said.words = digit_words(whole, true);
            return said;
        }
        // A generation (90后 九零后), the hundredths of a sprint (9秒83 九秒八三), a model's
        // number of three or more digits (C919 C九一九, A380) and a type's of two or more (99式
        // 九九式, 737型), a day named by its date (618 六一八) and one digit said three or more
        // times over, as a chat cheers (666 六六六, 888), are said digit by digit.
        // So is a chat's laugh, 2333 (a 2 and three or more 3s: 二三三三, after an emoticon's number).
        const bool is_one_digit_over = whole.size() >= 3 && whole.find_first_not_of(whole.front()) == std::string::npos;
        // A chat's goodbye, 88 or 886 (拜拜, 拜拜了) as a clause of its own (88，下次再聊), is said digit by
        // digit, 八八 (session 14); a bare 88 after a colon or in a clause counts (得分：88, 考了88分).
        if ((whole == "88" || whole == "886") && context.is_whole_clause) {
            said.words = digit_words(whole);
            return said;
        }
        // A chat's vow, 1314 (一生一世) and 5201314, counting nothing, is said digit by digit (我爱你1314
        // 一三一四; session 14), as 520 is where it names its day.
        if ((whole == "1314" || whole == "5201314") && !counts && !context.has_currency && !context.is_ordinal) {
            said.words = digit_words(whole);
            return said;
        }
        // 233 too, right after a laugh's character (哈哈哈233, 笑死233; session 14); elsewhere it counts (233人).
        const bool is_laugh = whole.front() == '2' && whole.find_first_not_of('3', 1) == std::string::npos &&
                              (whole.size() >= 4 || (whole.size() == 3 && context.after_laugh));
        // A filter grade is a name before any word (N95口罩: 口 is no measure word there). A round
        // thousand after capitals is a tier, not a model (WTA 1000 一千, RTX 5000 五千).
        const bool is_round_thousands = whole.size() >= 4 && whole.compare(whole.size() - 3, 3, "000") == 0;
        if (context.is_grade ||
            (!counts && (context.is_generation || context.is_hundredths || context.is_code ||
                         (context.is_model && whole.size() >= 3 && !is_round_thousands) ||
                         (context.names_type && whole.size() >= 2) || context.names_day ||
                         ((is_one_digit_over || is_laugh) && !context.has_currency && !context.is_ordinal)))) {
            said.words = digit_words(whole);
            return said;
        }
        if (context.names_year) {
            said.words = digit_words(whole);
            return said;
        }
        if (whole.size() == 4 && (context.next == U'年') && !context.is_span_of_years) {
            said.words = digit_words(whole);
            said.is_year = true;
            return said;
        }
        if ((context.is_service_call || is_named_anywhere(whole)) && is_service_number(whole) && !counts) {
            said.words = digit_words(whole, true);
            said.is_dialled = true;
            return said;
        }
        if (whole.size() >= 3 && (names_by_digits(context.next) || context.is_named || (context.names_place && !counts))) {
            said.words = digit_words(whole);
            return said;
        }
    }
    if (whole == "2" && !context.is_ordinal && !context.is_model && (context.has_unit || takes_liang(context.next))) {
        said.words = "两";
        return said;
    }
    said.words = cardinal_words(whole, !context.is_ordinal);
    return said;
}

void append_warning(SpokenForm& form, const std::string& warning) {
    if (warning.empty()) return;
    if (!form.warning.empty()) form.warning += "; ";
    form.warning += warning;
}

// 3:30 三点三十分, 10:05 十点零五分, 2:00 两点; nullopt when the text after the colon is not
// minutes (3:2 is a score). A `duration` is said in its units: 2:05:30 两小时零五分三十秒 (hours,
// minutes and seconds), 3:35 三分三十五秒 (minutes and seconds).
std::optional<SpokenForm> read_clock_time(const std::vector<CodePoint>& text, const WrittenNumber& hour,
                                          bool duration = false) {
    auto i = hour.end + 1;
    const auto minutes = digits_from(text, i);
    constexpr int kLastHour = 24;
    constexpr int kLastMinute = 59;  // a duration's first part may be minutes (25:30 in a 5000 m race)
    if (hour.has_point || hour.has_separators || hour.whole.size() > 2 ||
        std::stoi(hour.whole) > (duration ? kLastMinute : kLastHour) || minutes.size() != 2 || minutes > "59") {
        return std::nullopt;
    }
    auto say_part = [](const std::string& digits, const char* unit) -> std::string {
        if (digits == "00") return "";
        if (digits.front() == '0') return std::string("零") + digit_words(digits.substr(1)) + unit;
        return cardinal_words(digits, false) + unit;
    };
    SpokenForm form;
    const auto first = hour.whole == "2" ? std::string("两") : cardinal_words(hour.whole, false);
    const bool has_seconds = value_at(text, i) == ':' && is_digit_at(text, i + 1) && is_digit_at(text, i + 2) &&
                             !is_digit_at(text, i + 3);
    if (duration) {
        form.words = first + (has_seconds ? "小时" : "分") + say_part(minutes, has_seconds ? "分" : "秒");
    } else {
        form.words = first + "点" + say_part(minutes, "分");
    }
    if (has_seconds) {
        auto k = i + 1;
        const auto seconds = digits_from(text, k);
        if (seconds <= "59") {
            if (minutes == "00" && seconds != "00") form.words += "零";
            form.words += say_part(seconds, "秒");
            i = k;
        }
    }
    form.end = i;
    return form;
}

bool is_dash(char32_t c) {
    return c == '-' || c == 0x2013 /*–*/ || c == 0x2014 /*—*/ || c == 0x2212 /*−*/;
}

// A sign of a relation between two terms, as a lesson writes it: = ≈ ≠ < > ≤ ≥.
bool is_relation_sign(char32_t c) {
    return is_one_of(c, U"=<>\u2248\u2260\u2264\u2265");
}

// A relation sign after text[end] (spaces allowed): the numbers before it are a lesson's terms.
bool relation_follows(const std::vector<CodePoint>& text, std::size_t end) {
    while (value_at(text, end) == ' ') ++end;
    return is_relation_sign(value_at(text, end));
}

bool is_range_mark(char32_t c) {
    return is_dash(c) || c == '~' || c == 0x301C /*〜*/;
}

// 2026-12-01, 2026/12/1: a year, a month and a day.
std::optional<SpokenForm> read_numeric_date(const std::vector<CodePoint>& text, const WrittenNumber& year) {
    const auto separator = value_at(text, year.end);
    if (year.has_point || year.has_separators || year.whole.size() != 4 || !(separator == '-' || separator == '/')) {
        return std::nullopt;
    }
    auto i = year.end + 1;
    const auto month = digits_from(text, i);
    if (month.empty() || month.size() > 2 || value_at(text, i) != separator) return std::nullopt;
    ++i;
    const auto day = digits_from(text, i);
    if (!is_month_and_day(month, day)) return std::nullopt;
    SpokenForm form;
    form.words = digit_words(year.whole) + "年" + cardinal_words(month, false) + "月" + cardinal_words(day, false) + "日";
    form.end = i;
    return form;
}

// A phone number's groups of digits, each said digit by digit with 幺 for 1; a group too long to be
// read as a number carries the warning (once).
void append_phone_groups(SpokenForm& form, const std::vector<std::string>& groups) {
    form.is_dialled = true;
    for (const auto& group : groups) {
        form.words += digit_words(group, true);
        if (group.size() > kMostCardinalDigits && form.warning.empty()) form.warning = kTooLongWarning;
    }
}

// 010-12345678, 0912-345-678: groups of digits joined by dashes, said digit by digit.
std::optional<SpokenForm> read_dashed_digits(const std::vector<CodePoint>& text, const WrittenNumber& first,
                                             bool is_phone) {
    if (first.has_point || first.has_separators) return std::nullopt;
    std::vector<std::string> groups{first.whole};
    auto i = first.end;
    while (is_dash(value_at(text, i)) && is_digit_at(text, i + 1)) {
        ++i;
        groups.push_back(digits_from(text, i));
    }
    const bool looks_like_phone = first.whole.front() == '0' || groups.size() >= 3 || is_phone;
    if (groups.size() < 2 || !looks_like_phone) return std::nullopt;
    SpokenForm form;
    append_phone_groups(form, groups);
    form.end = i;
    return form;
}

// A dash before a group of digits with a leading zero (A2024-0315, a document's, a case's or a
// product's number) joins a code's parts: no count is written with a leading zero, so it is no
// range. Each part is said digit by digit and the dash 杠, as codes are read out (session 14; it
// was 到). A year and a month (2024-03) are left as they were.
std::optional<SpokenForm> read_code_with_dash(const std::vector<CodePoint>& text, const WrittenNumber& first) {
    if (first.has_point || first.has_separators || !is_dash(value_at(text, first.end)) ||
        !is_digit_at(text, first.end + 1)) {
        return std::nullopt;
    }
    auto i = first.end + 1;
    const auto second = digits_from(text, i);
    constexpr std::size_t kYearDigits = 4;
    const bool year_and_month = first.whole.size() == kYearDigits && second.size() == 2 && is_month_and_day(second, "1");
    if (second.size() < 2 || second.front() != '0' || year_and_month || value_at(text, i) == '.') return std::nullopt;
    SpokenForm form;
    form.words = digit_words(first.whole) + "杠" + digit_words(second);
    form.end = i;
    return form;
}

// Whether a range mark at `mark` follows a date or a clock time (9月1日-9月5日, 3点-5点, 12:00-14:00):
// the first part of a range that ended the form before the mark, so the mark is 到, not a sign.
bool follows_date_or_time(const std::vector<CodePoint>& text, std::size_t mark) {
    if (mark >= 2 && is_one_of(text[mark - 1].value, U"年月日号號点點时時分秒")) return is_digit_at(text, mark - 2);
    return mark >= 4 && is_digit_at(text, mark - 1) && is_digit_at(text, mark - 2) && value_at(text, mark - 3) == ':' &&
           is_digit_at(text, mark - 4);
}

// The capitals of a model's name right before text[start], with nothing, a hyphen or a space
// between (C919, A380, B-52, RTX 4090), or the middle dot of a licence plate (京A·12345, where the
// digits are a name as a model's are): one to three capitals that start a word and are spelled
// (TOP in TOP 10 is the word top, a rank: latin_words.hpp), not after a digit (4K 120帧: the 4K is
// a quantity, and 120 counts). Empty where there are none.
std::string model_name_before(const std::vector<CodePoint>& text, std::size_t start) {
    auto i = start;
    if (i > 0 && is_one_of(text[i - 1].value, U"- \u00B7\u30FB")) --i;
    std::string capitals;
    while (i > 0 && is_ascii_capital(value_at(text, i - 1))) {
        --i;
        capitals.insert(capitals.begin(), static_cast<char>(ascii_form(text[i].value)));
    }
    constexpr std::size_t kMostCapitals = 3;
    const bool starts_word = i == 0 || !(is_ascii_letter(value_at(text, i - 1)) || is_digit_at(text, i - 1));
    if (capitals.size() > kMostCapitals || is_said_as_word(capitals) || !starts_word) return {};
    return capitals;
}

bool follows_model_name(const std::vector<CodePoint>& text, std::size_t start) {
    return !model_name_before(text, start).empty();
}

// A respirator's filter grade (N95, KN95, P99: a class N R P KN KP and 90, 95 or 99, the share of
// particles it stops): a grade's name, said digit by digit (N九五), where a model's two digits count
// (G20 G二十).
bool is_filter_grade(const std::vector<CodePoint>& text, std::size_t start, const std::string& digits) {
    const auto capitals = model_name_before(text, start);
    const bool filter_class = capitals == "N" || capitals == "R" || capitals == "P" || capitals == "KN" || capitals == "KP";
    return filter_class && (digits == "90" || digits == "95" || digits == "99");
}

// Right after a word with a small letter, with nothing between (Tiger2024, user123): a user
// name's or an ID's digits. (iPhone15 counts: fewer than three digits, as a model's do.)
bool follows_glued_name(const std::vector<CodePoint>& text, std::size_t start) {
    auto i = start;
    bool has_small = false;
    while (i > 0 && is_ascii_letter(value_at(text, i - 1))) {
        --i;
        const auto c = value_at(text, i);
        has_small = has_small || (c >= 'a' && c <= 'z');
    }
    return i < start && has_small;
}

// Right after the Chinese name of an aircraft's maker (波音737, 空客 320) or of a chip's series
// (天玑9400 天玑九四零零, 骁龙888, 麒麟990, 鲲鹏920, 昇腾910, as reviews and news say them; session 14,
// they counted): its model's number.
bool follows_maker_name(const std::vector<CodePoint>& text, std::size_t start) {
    auto i = start;
    if (i > 0 && text[i - 1].value == ' ') --i;
    const auto before = text_between(text, i >= 2 ? i - 2 : 0, i);
    for (const std::string_view maker : {"波音", "空客", "麦道", "麥道", "商飞", "商飛", "天玑", "天璣", "骁龙", "驍龍",
                                         "麒麟", "鲲鹏", "鯤鵬", "昇腾", "昇騰", "飞腾", "飛騰", "龙芯", "龍芯"})
        if (before == maker) return true;
    return false;
}

// A number that names by its digits what it stands for, said one by one with 一 for 1 (where no
// measure word or unit makes it count):
// - a stock's code alone in brackets after the company's name (贵州茅台（600519）, 台積電（2330）,
//   腾讯控股(00700.HK)): four to six digits, a closing bracket or the exchange's suffix after them;
//   so is a year in a document's number (国发〔2024〕10号 国发二零二四十号);
// - the Nikkei's number (日经225 日经二二五, as Japanese and Chinese market news say it; the other
//   indices count their shares: 沪深300 三百, 标普500 五百);
// - a programme's number before its word (985高校, 211工程, 863计划), also in a list (985、211高校);
// - a video's resolution, lines and a p (1080P 一零八零P, 720p).
bool names_by_its_digits(const std::vector<CodePoint>& text, std::size_t start, const WrittenNumber& number) {
    if (number.has_point || number.has_separators) return false;
    const auto& digits = number.whole;
    if ((digits.size() == 3 || digits.size() == 4) && is_one_of(value_at(text, number.end), U"pP") &&
        !is_ascii_letter(value_at(text, number.end + 1))) {
        return true;
    }
    constexpr std::size_t kShortestCode = 4;
    constexpr std::size_t kLongestCode = 6;
    // A magnitude after the bracket makes it a count's ((2000)万); a word after it may be anything
    // (贵州茅台（600519）股价: 股 is no measure word there).
    const bool closes = is_one_of(value_at(text, number.end), U")\uFF09\u3015]") &&
                        !is_one_of(value_at(text, number.end + 1), U"万萬亿億千百");
    if (start > 0 && is_one_of(value_at(text, start - 1), U"(\u3014[") && digits.size() >= kShortestCode &&
        digits.size() <= kLongestCode &&
        (closes || (value_at(text, number.end) == '.' && is_ascii_capital(value_at(text, number.end + 1))))) {
        return true;
    }
    const auto before = text_between(text, start >= 2 ? start - 2 : 0, start);
    if (before == "日经" || before == "日經") return true;
    if (digits.size() != 3) return false;
    auto end = number.end;
    // Past the rest of a list of such numbers (985、211高校) to the word they share.
    while (value_at(text, end) == 0x3001 /*、*/ && is_digit_at(text, end + 1)) {
        auto k = end + 1;
        if (digits_from(text, k).size() != 3) return false;
        end = k;
    }
    const auto after = text_between(text, end, end + 2);
    for (const std::string_view word : {"工程", "计划", "計劃", "高校", "院校", "名校", "大学", "大學"})
        if (after == word) return true;
    return false;
}

// A version after a software's name and a space (Python 3.12, iOS 17.12: a word with a small
// letter) or right after a v (v2.15, V3.12).
bool follows_software_name(const std::vector<CodePoint>& text, std::size_t start) {
    if (start == 0) return false;
    if (is_one_of(value_at(text, start - 1), U"vV")) return start == 1 || !is_ascii_letter(value_at(text, start - 2));
    return value_at(text, start - 1) == ' ' && start >= 2 && is_ascii_letter(value_at(text, start - 2)) &&
           follows_glued_name(text, start - 1);
}

// The Chinese designation of an aircraft, a missile or a rocket before a hyphen (歼-20 歼二十, 运-20,
// 东风-41, 长征-5): the hyphen joins, it is no minus sign.
bool follows_designation(const std::vector<CodePoint>& text, std::size_t dash) {
    if (dash == 0) return false;
    if (is_one_of(text[dash - 1].value, U"歼殲运運轰轟直教")) return true;
    const auto before = text_between(text, dash >= 2 ? dash - 2 : 0, dash);
    for (const std::string_view name : {"东风", "東風", "长征", "長征", "红旗", "紅旗", "鹰击", "鷹擊", "巨浪", "空警",
                                        "霹雳", "霹靂", "快舟"})
        if (before == name) return true;
    return false;
}

// A train's number: one capital of a train's class (G D C Z T K L Y S) right before the digits and
// 次 after them (G1234次: 次 names the train there, it does not count) or 车次 before them in the
// clause (车次：G101).
bool is_train_number(const std::vector<CodePoint>& text, std::size_t start, std::size_t end) {
    if (start < 1 || !is_one_of(value_at(text, start - 1), U"GDCZTKLYS") ||
        (start >= 2 && is_ascii_letter(value_at(text, start - 2)))) {
        return false;
    }
    const std::string before = text_before(text, start, true);
    return is_one_of(value_at(text, end), U"次") || before.find("车次") != std::string::npos ||
           before.find("車次") != std::string::npos;
}

// A flight's number: an airline's two capitals and three or four digits (CA1831, MU 5101), with
// 航班 or 班机 right after it or earlier in the clause (航班号CA1831).
bool is_flight_number(const std::vector<CodePoint>& text, std::size_t start, std::size_t end) {
    const auto digit_count = end - start;
    if (model_name_before(text, start).size() != 2 || digit_count < 3 || digit_count > 4) return false;
    const std::string after = text_between(text, end, end + 3);
    const std::string before = text_before(text, start, true);
    for (const std::string_view word : {"航班", "班机", "班機"}) {
        if (after.rfind(word, 0) == 0 || after.rfind(std::string("次") + std::string(word), 0) == 0 ||
            before.find(word) != std::string::npos) {
            return true;
        }
    }
    return false;
}

// A season, or a school or financial year, written as two years that follow each other
// (2024/25赛季, 2024-25, 2024-2025学年): the years digit by digit joined by 至, as sports and
// school news read them (二零二四至二五赛季). A range of years before 年 stays a range
// (2020-2025年 二零二零到二零二五年); two years that do not follow each other are not a season.
std::optional<SpokenForm> read_season(const std::vector<CodePoint>& text, const WrittenNumber& first) {
    const auto mark = value_at(text, first.end);
    if (first.has_point || first.has_separators || first.whole.size() != 4 || !(first.whole[0] == '1' || first.whole[0] == '2') ||
        !(mark == '/' || is_dash(mark))) {
        return std::nullopt;
    }
    auto i = first.end + 1;
    const auto second = digits_from(text, i);
    const int next_year = std::stoi(first.whole) + 1;
    const bool follows = (second.size() == 2 && std::stoi(second) == next_year % 100) ||
                         (second.size() == 4 && std::stoi(second) == next_year);
    if (!follows || value_at(text, i) == '.' || (value_at(text, i) == U'年' && value_at(text, i + 1) != U'度')) return std::nullopt;
    SpokenForm form;
    form.words = digit_words(first.whole) + "至" + digit_words(second);
    form.end = i;
    return form;
}

// A country calling code, +86: said 加八六 as the + key is named, with the phone number that
// follows it in groups (+86 10 6512 3456), digit by digit with 幺 for 1. A + and one to three
// digits is one where a group follows, a phone word is earlier in the sentence, or 区号 stands
// right before it; elsewhere it is a sign (+5 正五).
std::optional<SpokenForm> read_calling_code(const std::vector<CodePoint>& text, std::size_t start) {
    if (value_at(text, start) != '+' || !is_digit_at(text, start + 1)) return std::nullopt;
    if (start > 0 && (is_digit_at(text, start - 1) || is_ascii_letter(value_at(text, start - 1)))) return std::nullopt;
    auto i = start + 1;
    const auto code = digits_from(text, i);
    constexpr std::size_t kLongestCode = 3;
    if (code.size() > kLongestCode || value_at(text, i) == '.' || value_at(text, i) == '%') return std::nullopt;
    std::vector<std::string> groups;
    auto end = i;
    while ((value_at(text, end) == ' ' || is_dash(value_at(text, end))) && is_digit_at(text, end + 1)) {
        auto k = end + 1;
        groups.push_back(digits_from(text, k));
        end = k;
    }
    std::size_t word_end = start;
    for (int skipped = 0; skipped < 2 && word_end > 0 && is_one_of(text[word_end - 1].value, U" 是为為：:"); ++skipped)
        --word_end;
    const auto before = text_between(text, word_end >= 2 ? word_end - 2 : 0, word_end);
    const bool is_code = !groups.empty() || follows_phone_word(text, start) || before == "区号" || before == "區號";
    if (!is_code) return std::nullopt;
    SpokenForm form;
    form.words = "加" + digit_words(code, true);
    append_phone_groups(form, groups);
    form.end = end;
    return form;
}

// Three or more groups of digits joined by dots: a date (2026.03.15: a four-digit year, a month
// and a day, 二零二六年三月十五日), an IP address (four groups of up to three digits, each at most
// 255: 192.168.1.1 一九二点一六八点一点一, digit by digit as it is read out) or a version (1.2.3
// 一点二点三, 10.15.7 十点十五点七: each group a number, 点 between).
std::optional<SpokenForm> read_dotted_groups(const std::vector<CodePoint>& text, std::size_t start) {
    std::vector<std::string> groups;
    auto i = start;
    groups.push_back(digits_from(text, i));
    while (value_at(text, i) == '.' && is_digit_at(text, i + 1)) {
        ++i;
        groups.push_back(digits_from(text, i));
    }
    constexpr std::size_t kFewestGroups = 3;
    if (groups.size() < kFewestGroups) return std::nullopt;
    SpokenForm form;
    form.end = i;
    if (groups.size() == 3 && groups[0].size() == 4 && is_month_and_day(groups[1], groups[2])) {
        form.words = digit_words(groups[0]) + "年" + cardinal_words(groups[1], false) + "月" + cardinal_words(groups[2], false) + "日";
        return form;
    }
    const bool is_ip_address = groups.size() == 4 && std::all_of(groups.begin(), groups.end(), [](const std::string& group) {
                                   return group.size() <= 3 && std::stoi(group) <= 255;
                               });
    for (std::size_t k = 0; k < groups.size(); ++k) {
        const auto& group = groups[k];
        if (k > 0) form.words += "点";
        if (group.size() > kMostCardinalDigits) {
            form.words += digit_words(group);
            form.warning = kTooLongWarning;
        } else if (is_ip_address || (group.size() > 1 && group.front() == '0')) {
            form.words += digit_words(group);
        } else {
            form.words += cardinal_words(group, false);
        }
    }
    return form;
}

// A day named by its month and day with a middle dot between them, as an event is (3·15晚会 三一五
// 晚会, 5·12地震 五一二, 9·11 九一一): digit by digit, the dot not said.
std::optional<SpokenForm> read_dotted_day(const std::vector<CodePoint>& text, const WrittenNumber& month) {
    const auto dot = value_at(text, month.end);
    if (month.has_point || month.has_separators || !(dot == 0xB7 /*·*/ || dot == 0x30FB /*・*/ || dot == 0x2022 /*•*/) ||
        !is_digit_at(text, month.end + 1)) {
        return std::nullopt;
    }
    auto i = month.end + 1;
    const auto day = digits_from(text, i);
    if (!is_month_and_day(month.whole, day)) return std::nullopt;
    SpokenForm form;
    form.words = digit_words(month.whole) + digit_words(day);
    form.end = i;
    return form;
}

// A month and a day without a year, 9/18 (as Taiwan and Hong Kong write dates, and weather and
// event notices everywhere): 九月十八日 where the clause places something in time, with a word of
// time right after it (9/18起, 12/31前, 9/20晚间, 9/18(週三)) or 于 於 before it (请於12/31, not
// 小于1/3). A range mark after it is no sign: 1/3~1/2 is a range of fractions as often as 10/1-10/7
// is one of days. Elsewhere it is a fraction (1/3的学生, 1/2杯, 答案是3/4), and so it is before 的, a measure
// word or 决赛, the knockout rounds' (于1/4决赛中出局), whatever stands before it.
std::optional<SpokenForm> read_month_and_day(const std::vector<CodePoint>& text, std::size_t start,
                                             const WrittenNumber& month) {
    if (month.has_point || month.has_separators || value_at(text, month.end) != '/') return std::nullopt;
    auto i = month.end + 1;
    const auto day = digits_from(text, i);
    if (!is_month_and_day(month.whole, day) || value_at(text, i) == '.' || value_at(text, i) == '/') return std::nullopt;
    // A range of two days (10/1-10/7): the second day no earlier than the first (1/3~1/2 is no range
    // of days), and the words after the second day decide for both.
    auto first_end = i;
    std::string second_day_words;
    if (is_range_mark(value_at(text, i)) && is_digit_at(text, i + 1)) {
        auto k = i + 1;
        const auto second_month = digits_from(text, k);
        if (value_at(text, k) == '/' && is_digit_at(text, k + 1)) {
            ++k;
            const auto second_day = digits_from(text, k);
            if (is_month_and_day(second_month, second_day) && value_at(text, k) != '/' && value_at(text, k) != '.' &&
                std::make_pair(std::stoi(second_month), std::stoi(second_day)) >=
                    std::make_pair(std::stoi(month.whole), std::stoi(day))) {
                second_day_words = "到" + cardinal_words(second_month, false) + "月" + cardinal_words(second_day, false) + "日";
                i = k;
            }
        }
    }
    bool in_time = false;
    const std::string after = text_between(text, i, i + 2);
    for (const std::string_view word : {"起", "前", "后", "後", "晚", "早", "上午", "下午", "中午", "凌晨", "夜", "当天",
                                        "當天", "(", "（", "星期", "周", "週", "礼拜", "禮拜", "期间", "期間"})
        if (after.rfind(word, 0) == 0) in_time = true;
    const bool is_fraction = after == "决赛" || after == "決賽" || value_at(text, i) == U'的' ||
                             (i < text.size() && takes_liang(text[i].value));
    if (!in_time && is_fraction) return std::nullopt;
    auto before = text_before(text, start, true);
    // A word of time before it names what the day is (展会时间为12/3-12/5, 日期：9/18).
    auto named = before;
    while (!named.empty() && (ends_with(named, "为") || ends_with(named, "為") || ends_with(named, "是") ||
                              ends_with(named, "：") || ends_with(named, ":") || ends_with(named, " ")))
        named.erase(named.size() - (named.back() == ':' || named.back() == ' ' ? 1 : std::string_view("为").size()));
    for (const std::string_view word : {"时间", "時間", "日期"}) in_time = in_time || ends_with(named, word);
    // In brackets after a day of the week (本週三（12/4）, 周五(3/8)), as news dates an event.
    if (ends_with(named, "（") || ends_with(named, "(")) {
        named.erase(named.size() - (named.back() == '(' ? 1 : std::string_view("（").size()));
        for (const std::string_view week : {"周", "週", "星期", "礼拜", "禮拜"})
            for (const std::string_view weekday : {"一", "二", "三", "四", "五", "六", "日", "天"})
                in_time = in_time || ends_with(named, std::string(week) + std::string(weekday));
    }
    for (const std::string_view word : {"于", "於"}) {
        if (!ends_with(before, word)) continue;
        const auto rest = before.substr(0, before.size() - word.size());
        bool compares = false;
        for (const std::string_view comparing : {"小", "大", "等", "低", "高", "多", "少", "当", "當", "属", "屬", "至", "由",
                                                 "对", "對", "关", "關", "相"})
            compares = compares || ends_with(rest, comparing);
        in_time = in_time || !compares;
    }
    if (!in_time) return std::nullopt;
    SpokenForm form;
    form.words = cardinal_words(month.whole, false) + "月" + cardinal_words(day, false) + "日" + second_day_words;
    form.end = second_day_words.empty() ? first_end : i;
    return form;
}

// A race's time, minutes and seconds with their tenths or hundredths (1:28.65 一分二十八秒六五,
// 3:27.46): the seconds' decimal point is what a clock's minutes never have. A subtitle's timestamp
// (00:01.500: minutes with a leading zero, thousandths) is no race's.
std::optional<SpokenForm> read_race_time(const WrittenNumber& minutes, const WrittenNumber& seconds) {
    constexpr std::size_t kLongestMinutes = 2;
    constexpr std::size_t kLongestFraction = 2;
    if (minutes.has_point || minutes.has_separators || minutes.whole.size() > kLongestMinutes ||
        (minutes.whole.size() > 1 && minutes.whole.front() == '0') || !seconds.has_point || seconds.whole.size() != 2 ||
        seconds.whole > "59" || seconds.fraction.size() > kLongestFraction) {
        return std::nullopt;
    }
    SpokenForm form;
    form.words = (minutes.whole == "2" ? std::string("两") : cardinal_words(minutes.whole, false)) + "分" +
                 (seconds.whole.front() == '0' ? "零" + digit_words(seconds.whole.substr(1)) : cardinal_words(seconds.whole, false)) +
                 "秒" + digit_words(seconds.fraction);
    form.end = seconds.end;
    return form;
}

}  // namespace

std::optional<SpokenForm> read_number_form(const std::vector<CodePoint>& text, std::size_t start) {
    if (is_range_mark(value_at(text, start)) && is_digit_at(text, start + 1) && follows_date_or_time(text, start)) {
        auto second = read_number_form(text, start + 1);
        if (second) second->words = "到" + second->words;
        return second;
    }
    if (auto code = read_calling_code(text, start)) return code;
    auto i = start;
    const Currency* currency = currency_at(text, i, i);
    std::string sign_words;
    const auto first = value_at(text, i);
    // After a term (a digit, a letter, a square: x²+2x) a + or a - joins it to the next, a sign no more.
    const bool after_word = start > 0 && (is_digit_at(text, start - 1) || is_ascii_letter(value_at(text, start - 1)) ||
                                          is_one_of(text[start - 1].value, U"\u00B2\u00B3"));
    if (currency == nullptr && is_dash(first) && is_digit_at(text, i + 1) && follows_designation(text, start)) {
        ++i;
    } else if (currency == nullptr && (is_dash(first) || first == '+') && is_digit_at(text, i + 1) && !after_word) {
        sign_words = first == '+' ? "正" : "负";
        if (first == '+' && follows_game_attribute(text, start)) sign_words = "加";
        ++i;
    }
    if (!is_digit_at(text, i)) return std::nullopt;

    NumberContext context;
    std::size_t previous = start;
    while (previous > 0 && text[previous - 1].value == ' ') --previous;
    context.is_ordinal = previous > 0 && (text[previous - 1].value == U'第');
    context.is_phone = follows_phone_word(text, start);

    const auto number = parse_number(text, i);
    // A chat's +1 as a clause of its own (+1，我也觉得), "me too", is 加一 (session 14; it was 正一).
    if (sign_words == "正" && number.whole == "1" && !number.has_point && stands_alone(text, start, number.end))
        sign_words = "加";
    context.is_named = follows_name_word(text, start);
    context.is_model = sign_words.empty() && currency == nullptr &&
                       (follows_model_name(text, start) || follows_maker_name(text, start) ||
                        follows_glued_name(text, start));
    context.is_train = context.is_model && !number.has_point && !number.has_separators &&
                       (is_train_number(text, start, number.end) || is_flight_number(text, start, number.end));
    context.has_currency = currency != nullptr;
    context.names_place = names_room_or_building(text, number.end);
    context.names_day = sign_words.empty() && currency == nullptr && names_a_day(text, start, number);
    context.names_type = is_one_of(value_at(text, number.end), U"型式");
    context.is_generation = number.whole.size() == 2 && !number.has_point && !number.has_separators &&
                            is_one_of(value_at(text, number.end), U"后後");
    context.is_hundredths = start >= 2 && text[start - 1].value == U'秒' && is_digit_at(text, start - 2);
    context.is_grade = context.is_model && is_filter_grade(text, start, number.whole);
    context.is_span_of_years = counts_years(text, start, number);
    context.is_service_call = is_service_call(text, start, number.end);
    context.is_code = sign_words.empty() && currency == nullptr && names_by_its_digits(text, i, number);
    context.is_version = sign_words.empty() && currency == nullptr && follows_software_name(text, i);
    context.after_laugh = sign_words.empty() && start > 0 && is_one_of(value_at(text, start - 1), U"哈呵嘿嘻笑死");
    context.is_whole_clause = sign_words.empty() && currency == nullptr && stands_alone(text, start, number.end);
    context.names_year =
        sign_words.empty() && currency == nullptr && !context.is_ordinal && names_year_before_word(text, number);
    SpokenForm form;
    // Two numbers said each alone with a word between: a score (3:1, and 2-1 where the clause
    // speaks of a match: 2-1领先), a product (7×24 七乘二十四).
    auto join_two = [&](const WrittenNumber& second, const char* joiner, const NumberContext& each) {
        const auto first_said = say_number(number, each);
        const auto second_said = say_number(second, each);
        form.words = sign_words + first_said.words + joiner + second_said.words;
        append_warning(form, first_said.warning);
        append_warning(form, second_said.warning);
        form.end = second.end;
        return form;
    };
    if (sign_words.empty() && currency == nullptr && value_at(text, number.end) == ':' &&
        is_digit_at(text, number.end + 1)) {
        auto second = parse_number(text, number.end + 1);
        if (!is_score(text, start, second.end)) {
            if (auto time = read_race_time(number, second)) return time;
            if (auto time = read_clock_time(text, number, speaks_of_duration(text, start))) return time;
        }
        return join_two(second, "比", context);
    }
    // A small x between two numbers is a times sign typed (4x400米接力, 1920x1080), said 乘 as × is.
    if (is_one_of(value_at(text, number.end), U"×*x") && is_digit_at(text, number.end + 1) && currency == nullptr) {
        join_two(parse_number(text, number.end + 1), "乘", {});
        // Scientific notation (3×10⁸m/s 三乘十的八次方米每秒): the power and a unit after it go with it.
        if (auto power = read_power(text, form.end)) {
            form.words += power->words;
            form.end = power->end;
            std::size_t unit_end = form.end;
            if (const Unit* unit = unit_at(text, form.end, unit_end); unit != nullptr && unit->written != "%") {
                form.words += unit->words;
                form.end = unit_end;
            }
        }
        return form;
    }
    if (sign_words.empty() && currency == nullptr) {
        if (auto day = read_dotted_day(text, number)) return day;
        if (auto dotted = read_dotted_groups(text, i)) return dotted;
        if (auto date = read_numeric_date(text, number)) return date;
        if (auto season = read_season(text, number)) return season;
        if (auto digits = read_dashed_digits(text, number, context.is_phone)) return digits;
        if (auto code = read_code_with_dash(text, number)) return code;
        if (is_dash(value_at(text, number.end)) && is_digit_at(text, number.end + 1)) {
            auto second = parse_number(text, number.end + 1);
            // A measure word after the pair makes it a range (3-5天后获胜), whatever the clause says.
            const bool may_be_listed_score = !takes_liang(value_at(text, second.end));
            if (is_score(text, start, second.end, may_be_listed_score)) return join_two(second, "比", {});
            if (relation_follows(text, second.end)) return join_two(second, "减", {});  // 5-3=2
        }
    }
    if (sign_words.empty() && currency == nullptr) {
        if (auto date = read_month_and_day(text, start, number)) return date;
    }
    if (value_at(text, number.end) == '/' && is_digit_at(text, number.end + 1) && !number.has_point) {
        const auto denominator = parse_number(text, number.end + 1);
        const auto said_denominator = say_number(denominator, {});
        const auto said_numerator = say_number(number, {});
        form.words = sign_words + said_denominator.words + "分之" + said_numerator.words;
        append_warning(form, said_denominator.warning);
        append_warning(form, said_numerator.warning);
        form.end = denominator.end;
        // A range of two fractions, 1/3~1/2 三分之一到二分之一 (the mark was left unsaid).
        if (is_range_mark(value_at(text, form.end)) && is_digit_at(text, form.end + 1)) {
            const auto upper = parse_number(text, form.end + 1);
            if (!upper.has_point && value_at(text, upper.end) == '/' && is_digit_at(text, upper.end + 1)) {
                const auto upper_denominator = parse_number(text, upper.end + 1);
                const auto said_upper = say_number(upper, {});
                const auto said_upper_denominator = say_number(upper_denominator, {});
                form.words += "到" + said_upper_denominator.words + "分之" + said_upper.words;
                append_warning(form, said_upper_denominator.warning);
                append_warning(form, said_upper.warning);
                form.end = upper_denominator.end;
            }
        }
        return form;
    }

    // One number, or a range of two (3-5, 3~5), said with what follows the last of them.
    std::vector<WrittenNumber> numbers{number};
    std::vector<std::string> signs{sign_words};
    auto after_first = number.end;
    const bool first_is_percent = value_at(text, after_first) == '%';
    if (first_is_percent) ++after_first;  // 10%-20%
    // The first end's 万 or 亿 before the range mark is said with it: 3万-5万元 三万到五万元.
    std::string first_magnitude;
    if (is_one_of(value_at(text, after_first), U"万萬亿億") && is_range_mark(value_at(text, after_first + 1)) &&
        is_digit_at(text, after_first + 2)) {
        first_magnitude = is_one_of(value_at(text, after_first), U"万萬") ? "万" : "亿";
        ++after_first;
    }
    if (is_range_mark(value_at(text, after_first))) {
        // The second number may carry its own sign: -8~-3℃ 零下八到零下三摄氏度.
        auto second_start = after_first + 1;
        std::string second_sign;
        const auto mark = value_at(text, second_start);
        if ((is_dash(mark) || mark == '+') && is_digit_at(text, second_start + 1)) {
            second_sign = mark == '+' ? "正" : "负";
            ++second_start;
        }
        if (is_digit_at(text, second_start)) {
            auto second = parse_number(text, second_start);
            if (!first_is_percent || value_at(text, second.end) == '%') {
                numbers.push_back(std::move(second));
                signs.push_back(std::move(second_sign));
            }
        }
    }
    auto end = numbers.back().end;
    // A power after one number (10⁵ 十的五次方, 2^10) is said before the unit after it (10⁵Pa).
    std::string power_words;
    if (numbers.size() == 1) {
        if (auto power = read_power(text, end)) {
            power_words = std::move(power->words);
            end = power->end;
        }
    }
    std::size_t unit_end = end;
    const Unit* unit = unit_at(text, end, unit_end);
    context.next = value_at(text, numbers.back().end);
    // A Latin unit after the number's 万 or 亿 (1.6万km² 一点六万平方公里) is said after it.
    std::string magnitude_words;
    if (unit == nullptr && currency == nullptr && is_one_of(context.next, U"万萬亿億")) {
        const Unit* after_magnitude = unit_at(text, end + 1, unit_end);
        if (after_magnitude != nullptr && after_magnitude->written != "%") {
            unit = after_magnitude;
            magnitude_words = is_one_of(context.next, U"万萬") ? "万" : "亿";
        }
    }
    context.has_unit = power_words.empty() && ((unit != nullptr && unit->written != "%") || is_byte_unit_at(text, end));
    std::string unit_words = unit == nullptr ? "" : unit->words;
    const bool is_percent = unit != nullptr && unit->written == "%";
    const bool is_per_mille = end < text.size() && text[end].value == 0x2030 /*‰*/;
    const bool is_temperature = unit != nullptr && std::string_view(unit->words).find("氏度") != std::string_view::npos;
    // A temperature's sign is said 零下 or 零上 (-3℃ 零下三摄氏度, +5℃ 零上五摄氏度).
    for (auto& sign : signs) {
        if (sign == "负" && is_temperature) sign = "零下";
        if (sign == "正" && is_temperature) sign = "零上";
    }
    // A + before a percentage is a rise, said 涨 as market reports read it (腾讯+2.35% 腾讯涨百分之
    // 二点三五); not said where the clause already names the change (涨幅+2.35%, 同比增长+5%) or
    // after the first end of a range. A - stays 负 (增速-6.8% 增速负百分之六点八: 负增长).
    if (is_percent || is_per_mille) {
        for (std::size_t k = 0; k < signs.size(); ++k)
            if (signs[k] == "正") signs[k] = k == 0 && !names_change(text, start) ? "涨" : "";
    }
    // ¥1,299.00 is 一千二百九十九元, $3.50 三点五美元: a price's trailing zeros are written, not said.
    for (auto& price : numbers) {
        if (currency == nullptr || !price.has_point) continue;
        price.fraction.erase(price.fraction.find_last_not_of('0') + 1);
        price.has_point = !price.fraction.empty();
    }

    for (std::size_t k = 0; k < numbers.size(); ++k) {
        const auto said = say_number(numbers[k], context);
        if (k > 0) form.words += "到";
        form.words += signs[k];
        if (currency != nullptr) form.words += currency->before;
        if (is_percent) form.words += "百分之";
        if (is_per_mille) form.words += "千分之";
        // 100% is 百分之百, as it is said (百分之百的把握), not 百分之一百.
        const auto& whole = numbers[k].whole;
        form.words += is_percent && whole == "100" && !numbers[k].has_point ? "百" : said.words;
        if (k == 0 && numbers.size() > 1) form.words += first_magnitude;
        if (said.is_year) {
            form.words += "年";
            // The 年 of a year belongs to the form; after a range, only the last takes it.
            if (k + 1 < numbers.size()) form.words.erase(form.words.size() - std::string_view("年").size());
        }
        append_warning(form, said.warning);
        form.is_dialled = form.is_dialled || said.is_dialled;
        if (said.is_year && k + 1 == numbers.size()) end += 1;
    }
    if (unit != nullptr) end = unit_end;
    // A unit per another (7.0mmol/L 七点零毫摩尔每升, 35μg/m³ 三十五微克每立方米, 80mg/100ml 八十毫克每
    // 一百毫升): 每 and the second unit, with its number where it has one (km/h and m/s are units of
    // their own above).
    if (unit != nullptr && unit->written != "%" && value_at(text, end) == '/') {
        auto k = end + 1;
        std::string divisor_words;
        if (is_digit_at(text, k)) {
            const auto divisor = parse_number(text, k);
            divisor_words = say_number(divisor, {}).words;
            k = divisor.end;
        }
        std::size_t per_end = k;
        const Unit* per = value_at(text, k) == ' ' ? nullptr : unit_at(text, k, per_end);
        if (per != nullptr && per->written != "%") {
            unit_words += "每" + divisor_words + per->words;
            end = per_end;
        }
    }
    if (is_per_mille) end += 1;
    form.words += power_words + magnitude_words + unit_words;
    if (currency != nullptr) {
        // $5万 is 五万美元: the magnitude comes before the currency's name.
        if (is_one_of(value_at(text, end), U"万萬亿億千")) {
            form.words += text[end].text;
            ++end;
        }
        form.words += currency->after;
    }
    form.end = end;
    return form;
}

std::optional<SpokenForm> read_per_unit(const std::vector<CodePoint>& text, std::size_t i) {
    if (value_at(text, i) != '/' || i < 3 || value_at(text, i - 1) != 'B' || !is_one_of(value_at(text, i - 2), U"KMGTP"))
        return std::nullopt;
    auto number_end = i - 2;
    if (value_at(text, number_end - 1) == ' ') --number_end;
    if (!is_digit_at(text, number_end - 1) || value_at(text, i + 1) == ' ') return std::nullopt;
    std::size_t end = i + 1;
    const Unit* per = unit_at(text, i + 1, end);
    if (per == nullptr || per->written == "%") return std::nullopt;
    SpokenForm form;
    form.words = std::string("每") + per->words;
    form.end = end;
    return form;
}

bool slash_reads_per(const std::vector<CodePoint>& text, std::size_t i) {
    const auto is_han = [&](std::size_t k) { return k < text.size() && text[k].value >= 0x3400 && text[k].value <= 0x9FFF; };
    if (value_at(text, i) != '/' || !is_han(i + 1)) return false;
    constexpr std::size_t kLongestUnit = 3;  // characters: 元, 美元, 平方米
    for (std::size_t k = 1; k <= kLongestUnit && k <= i; ++k) {
        if (!is_han(i - k)) return is_digit_at(text, i - k);
    }
    return i > kLongestUnit && is_digit_at(text, i - kLongestUnit - 1);
}

namespace {

// Greek letters a lesson writes, said by the names Mandarin readers give them (π 派).
std::string_view greek_letter_name(char32_t c) {
    switch (c) {
        case 0x3B1: return "阿尔法";        // α
        case 0x3B2: return "贝塔";          // β
        case 0x3B3: return "伽马";          // γ
        case 0x394: case 0x3B4: return "德尔塔";  // Δ δ
        case 0x3B8: return "西塔";          // θ
        case 0x3BB: return "兰姆达";        // λ
        case 0x3C0: return "派";            // π
        case 0x3A3: case 0x3C3: return "西格马";  // Σ σ
        case 0x3C6: return "斐";            // φ
        case 0x3A9: case 0x3C9: return "欧米伽";  // Ω ω
        default: return {};
    }
}

// A term of a formula: a digit, a Latin or Greek letter, a closing bracket or a square (x², (a+b)),
// a degree or a percentage.
bool is_formula_term(char32_t c) {
    // A degree or a percentage ends a term too (sin30°=1/2, 25%=1/4; session 14: the = was skipped).
    return (c >= '0' && c <= '9') || is_ascii_letter(c) || !greek_letter_name(c).empty() || c == ')' || c == 0xB2 ||
           c == 0xB3 || c == 0xB0 || c == '%' || c == 0x2103 /*℃*/;
}

// A relation sign in the clause around text[i]: the signs in it are a formula's (a-b>0: 减).
bool clause_has_relation(const std::vector<CodePoint>& text, std::size_t i) {
    const auto ends_clause = [](char32_t c) {
        return c == ',' || c == ';' || c == '!' || c == '?' || c == 0x3001 /*、*/ || c == 0x3002 /*。*/ || c == '\n';
    };
    for (auto k = i; k < text.size() && !ends_clause(value_at(text, k)); ++k)
        if (is_relation_sign(value_at(text, k))) return true;
    for (auto k = i; k-- > 0 && !ends_clause(value_at(text, k));)
        if (is_relation_sign(value_at(text, k))) return true;
    return false;
}

}  // namespace

bool is_named_service_number(const std::string& digits) {
    return is_named_anywhere(digits) && is_service_number(digits);
}

std::string_view said_math_sign(const std::vector<CodePoint>& text, std::size_t i) {
    const auto sign = value_at(text, i);
    if (const auto name = greek_letter_name(sign); !name.empty()) return name;
    auto before = i;
    while (before > 0 && text[before - 1].value == ' ') --before;
    auto after = i + 1;
    while (value_at(text, after) == ' ') ++after;
    const char32_t left = before > 0 ? value_at(text, before - 1) : 0;
    const char32_t right = value_at(text, after);
    const bool is_han_left = left >= 0x3400 && left <= 0x9FFF;
    const bool is_han_right = right >= 0x3400 && right <= 0x9FFF;
    // A relation's right side may be a signed term (x=-2 x等于负二, -3<-1 负三小于负一): the sign is
    // the number's, read with it.
    const bool signed_right = (is_dash(right) || right == '+') && is_formula_term(value_at(text, after + 1));
    const bool relation_right = is_formula_term(right) || signed_right;
    const bool between_terms = is_formula_term(left) && is_formula_term(right);
    switch (sign) {
        case '=': case 0x2248: case 0x2260: {  // = ≈ ≠, between a character and a term too (答案是x=5, 等于号)
            if (!(is_formula_term(left) || is_han_left) || !(relation_right || is_han_right)) return {};
            return sign == '=' ? "等于" : sign == 0x2248 ? "约等于" : "不等于";
        }
        // ASCII < > around words are brackets: <标题>
        case '>': return is_formula_term(left) && relation_right ? "大于" : "";
        case '<': return is_formula_term(left) && relation_right ? "小于" : "";
        // ≥ and ≤ are never brackets: after a character too, before a term (含量≥80mg 含量大于等于八十毫克).
        case 0x2265: return (is_formula_term(left) || is_han_left) && relation_right ? "大于等于" : "";  // ≥
        case 0x2264: return (is_formula_term(left) || is_han_left) && relation_right ? "小于等于" : "";  // ≤
        // Geometry's signs as a lesson reads them (session 14): ∠A 角A, before a letter or a digit
        // (∠1); AB⊥CD AB垂直于CD, AB∥CD AB平行于CD, between two terms.
        case 0x2220: return is_formula_term(right) ? "角" : "";           // ∠
        case 0x25B3: return is_ascii_capital(right) ? "三角形" : "";       // △ABC 三角形ABC
        // ≌ and ∽ between two figures (△ABC≌△DEF 三角形ABC全等于三角形DEF).
        case 0x224C: case 0x2245: return is_formula_term(left) && (is_formula_term(right) || right == 0x25B3) ? "全等于" : "";  // ≌ ≅
        case 0x223D: return is_formula_term(left) && (is_formula_term(right) || right == 0x25B3) ? "相似于" : "";  // ∽
        case 0x22A5: return between_terms ? "垂直于" : "";                 // ⊥
        case 0x2225: case 0x2016: return between_terms ? "平行于" : "";    // ∥, and ‖ written for it
        // + between two digits (1+1), two letters (A+B) or in a formula (x+1=3); - only in a formula,
        // since a hyphen joins words and numbers elsewhere (Wi-Fi, B-52).
        case '+': {
            // A letter and a digit too: a sum of capacities (12GB+256GB 十二GB加二百五十六GB), 5G+AI.
            const auto is_alphanumeric = [](char32_t c) { return is_ascii_letter(c) || (c >= '0' && c <= '9'); };
            const bool alphanumeric = is_alphanumeric(left) && is_alphanumeric(right);
            // After a square or a cube, a sum of terms (a²+b²; session 14: said only beside a relation sign).
            const bool after_power = is_one_of(left, U"\u00B2\u00B3");
            return between_terms && (alphanumeric || after_power || clause_has_relation(text, i)) ? "加" : "";
        }
        case '-': case 0x2212: return between_terms && clause_has_relation(text, i) ? "减" : "";
        // A * before ST marks a share at risk of delisting (*ST康美), said 星 as market news says it.
        case '*': {
            const bool before_st = value_at(text, after) == 'S' && value_at(text, after + 1) == 'T' &&
                                   !is_ascii_letter(value_at(text, after + 2));
            return before_st ? "星" : "";
        }
        // × after a character too, before a number (经验值×2 经验值乘二, a game's bonus; session 14).
        case 0xD7: return between_terms || (is_han_left && right >= '0' && right <= '9') ? "乘" : "";  // ×
        case 0xF7: return between_terms ? "除以" : "";   // ÷
        case 0x221A: return is_formula_term(right) || right == '(' ? "根号" : "";  // √2, √(x+1)
        // A square or a cube after a term: x² x平方, 3² 三的平方.
        case 0xB2: case 0xB3: {
            if (!is_formula_term(left) || before != i) return {};
            const bool after_digit = left >= '0' && left <= '9';
            if (sign == 0xB2) return after_digit ? "的平方" : "平方";
            return after_digit ? "的立方" : "立方";
        }
        default: return {};
    }
}

namespace {

// The digit a superscript writes (⁰ ¹ ² ³ ⁴ ... ⁹), or -1.
int superscript_digit(char32_t c) {
    switch (c) {
        case 0x2070: return 0;
        case 0xB9: return 1;
        case 0xB2: return 2;
        case 0xB3: return 3;
        default: return c >= 0x2074 && c <= 0x2079 ? static_cast<int>(c - 0x2070) : -1;
    }
}

}  // namespace

std::optional<SpokenForm> read_number_character(const std::vector<CodePoint>& text, std::size_t i) {
    const auto c = value_at(text, i);
    int number = 0;
    if (c >= 0x2460 && c <= 0x2473) number = static_cast<int>(c - 0x2460) + 1;  // ① ... ⑳
    if (c >= 0x2474 && c <= 0x2487) number = static_cast<int>(c - 0x2474) + 1;  // ⑴ ... ⒇
    if (c >= 0x2488 && c <= 0x249B) number = static_cast<int>(c - 0x2488) + 1;  // ⒈ ... ⒛
    if (c >= 0x2776 && c <= 0x277F) number = static_cast<int>(c - 0x2776) + 1;  // ❶ ... ❿
    if (c >= 0x2780 && c <= 0x2793) number = static_cast<int>((c - 0x2780) % 10) + 1;  // ➀ ... ➉, ➊ ... ➓
    if (c >= 0x2160 && c <= 0x216B) number = static_cast<int>(c - 0x2160) + 1;  // Ⅰ ... Ⅻ
    if (c >= 0x2170 && c <= 0x217B) number = static_cast<int>(c - 0x2170) + 1;  // ⅰ ... ⅻ
    SpokenForm form;
    form.end = i + 1;
    if (number > 0) {
        form.words = cardinal_words(std::to_string(number), false);
        return form;
    }
    // A fraction written as one character: its denominator 分之 its numerator, as 1/2 is.
    constexpr std::pair<char32_t, const char*> kFractions[] = {
        {0xBD, "二分之一"},   {0x2153, "三分之一"}, {0x2154, "三分之二"}, {0xBC, "四分之一"}, {0xBE, "四分之三"},
        {0x2155, "五分之一"}, {0x2156, "五分之二"}, {0x2157, "五分之三"}, {0x2158, "五分之四"}, {0x2159, "六分之一"},
        {0x215A, "六分之五"}, {0x2150, "七分之一"}, {0x215B, "八分之一"}, {0x215C, "八分之三"}, {0x215D, "八分之五"},
        {0x215E, "八分之七"}, {0x2151, "九分之一"}, {0x2152, "十分之一"},
    };
    for (const auto& [written, said] : kFractions) {
        if (c != written) continue;
        form.words = said;
        return form;
    }
    return std::nullopt;
}

std::optional<SpokenForm> read_power(const std::vector<CodePoint>& text, std::size_t i) {
    if (i == 0 || !is_formula_term(value_at(text, i - 1))) return std::nullopt;
    bool negative = false;
    std::string exponent;
    auto k = i;
    if (value_at(text, k) == '^') {
        ++k;
        if (is_dash(value_at(text, k))) {
            negative = true;
            ++k;
        }
        exponent = digits_from(text, k);
    } else {
        if (value_at(text, k) == 0x207B /*⁻*/) {
            negative = true;
            ++k;
        }
        for (int digit = superscript_digit(value_at(text, k)); digit >= 0; digit = superscript_digit(value_at(text, k))) {
            exponent += static_cast<char>('0' + digit);
            ++k;
        }
        // A lone ² or ³ is said_math_sign's (平方 立方, and m² is a unit's).
        if (!negative && (exponent == "2" || exponent == "3")) return std::nullopt;
    }
    constexpr std::size_t kLongestExponent = 3;
    if (exponent.empty() || exponent.size() > kLongestExponent) return std::nullopt;
    SpokenForm form;
    form.end = k;
    const bool after_digit = is_digit_at(text, i - 1);
    if (!negative && (exponent == "2" || exponent == "3")) {
        form.words = std::string(after_digit ? "的" : "") + (exponent == "2" ? "平方" : "立方");
    } else {
        form.words = std::string("的") + (negative ? "负" : "") + cardinal_words(exponent, false) + "次方";
    }
    return form;
}

}  // namespace talkface::detail

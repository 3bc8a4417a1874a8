#include "text/written_numbers.hpp"

#include <algorithm>
#include <string_view>
#include <utility>

#include "text/approximate_counts.hpp"
#include "text/dates_and_times.hpp"
#include "text/digit_codes.hpp"
#include "text/figure_numbers.hpp"
#include "text/number_words.hpp"
#include "text/script_marks.hpp"
#include "text/units_and_money.hpp"
#include "text/written_number_scan.hpp"

namespace talkface::detail {

namespace {

bool is_han(char32_t c) {
    return (c >= 0x4E00 && c <= 0x9FFF) || (c >= 0x3400 && c <= 0x4DBF);
}

// A bonus or a penalty to a game's attribute (攻击力+15, 暴击率+5%, 防御+20, 移速-15%): the + is 加 and
// the - 减, as a game's screen is read. The attribute is a word ending in 力 or 值 (攻击力, 经验值), or one
// of the stats games show, alone or with 率 after it (暴击率, 命中率).
bool follows_game_attribute(const std::vector<CodePoint>& text, std::size_t start) {
    if (start == 0) return false;
    if (is_one_of(text[start - 1].value, U"力值")) return true;
    std::string before = text_before(text, start, true);
    if (ends_with(before, "率")) before.erase(before.size() - std::string_view("率").size());
    for (const std::string_view stat :
         {"攻击", "攻擊", "攻速", "速度", "移速", "防御", "防禦", "护甲", "護甲", "魔抗", "暴击", "暴擊",
          "暴伤", "暴傷", "闪避", "閃避", "命中", "生命", "血量", "法力", "伤害", "傷害", "穿透", "吸血",
          "韧性", "韌性", "格挡", "格擋", "抗性", "敏捷", "力量", "智力", "体质", "體質", "耐力", "精神",
          "经验", "經驗", "金币", "金幣",
          // A ranked game's points won (今天上分+50 加五十; session 21: 正五十).
          "上分", "积分", "積分",
          // An item's upgrade level (装备强化+12 加十二; session 20: 正十二).
          "强化", "強化", "精炼", "精煉"})
        if (ends_with(before, stat)) return true;
    return false;
}

// A gauge a game or a visual novel fills, a word in 度 (好感度+10 好感度加十, 亲密度+5, 熟练度-1: session 31,
// 正), with a whole count after the sign: its points, as 攻击力's are. Not a measure in degrees (温度 角度
// 纬度 经度 坡度), whose sign is a value's, nor a share (满意度+5%, 浓度+0.5), which a report changes.
bool follows_gauge(const std::vector<CodePoint>& text, std::size_t start) {
    if (start < 2 || text[start - 1].value != U'度' || is_one_of(text[start - 2].value, U"温溫角纬緯经經坡"))
        return false;
    auto end = start + 1;
    while (is_digit_at(text, end)) ++end;
    const auto after = value_at(text, end);
    return !is_one_of(after, U"%.‰°℃度") && !is_ascii_letter(after);
}

// A word for a temperature earlier in the sentence (气温, 低温, 温度, 氣溫): a 度 after a number is one.
bool speaks_of_temperature(const std::vector<CodePoint>& text, std::size_t start) {
    const std::string before = text_before(text, start, false);
    return contains_any(before, {"温", "溫"});
}

// A number at text[start] with `unit` after it (or none) and `next` the code point after it is a
// temperature: its unit is degrees Celsius or Fahrenheit (℃ 摄氏度, ℉ 华氏度), or a bare 度 where the
// sentence speaks of a temperature.
bool is_temperature_reading(const std::vector<CodePoint>& text, std::size_t start, const Unit* unit,
                            char32_t next) {
    if (unit != nullptr) return std::string_view(unit->words).find("氏度") != std::string_view::npos;
    return next == U'度' && speaks_of_temperature(text, start);
}

// Words that name a change (涨幅, 增长, 上升, 下降, 同比): a sign after them in their clause is not said as
// a rise or a fall again.
constexpr std::string_view kChangeWords[] = {"涨", "漲", "跌", "增",   "升",   "降",
                                             "减", "減", "幅", "同比", "环比", "環比"};

// The words that compare a figure with the same time a year before (同比) or with the period before
// (环比): a signed change right after one is said as news writes it (change_after_comparison).
constexpr std::string_view kComparisonWords[] = {"同比", "环比", "環比"};

// A comparison with an earlier time names that time after 较 or 比 (较上年, 比去年同期, 较上月, 较年初).
constexpr std::string_view kComparedWith[] = {"较", "較", "比"};
constexpr std::string_view kEarlierTimes[] = {"上年", "去年",   "同期", "上月",  "上周",
                                              "上週", "上季度", "年初", "上一年"};

// A rate's change in percentage points (毛利率同比+0.5个百分点): its rise is 提高.
constexpr std::string_view kPercentagePoints[] = {"个百分点", "個百分點"};

// What a subject names a price by (房价, 消费价格, CPI, PPI): its rise is 上涨.
constexpr std::string_view kPriceWords[] = {"价", "價", "CPI", "PPI"};

// The last word before a value that is written with its sign (收益率为-12.35%, 增速-6.8%): a
// verb that gives the value (为, 是, 至, 到, 约), or a rate's, a speed's or a value's word (率, 速,
// 值); a space keeps the sign apart from what moves too.
constexpr std::string_view kValueWordEnds[] = {"为", "為", "是", "率", "速", "值",
                                               "至", "到", "约", "約", " "};

// The amounts a company or an economy reports (净利润, 营收, 销量, 出口): a signed percentage right after
// one is its change (change_of_amount).
constexpr std::string_view kReportedAmounts[] = {
    "利润",   "利潤",   "净利",   "淨利",   "营收",   "營收",   "收入", "销量", "銷量",
    "销售额", "銷售額", "营业额", "營業額", "出货量", "出貨量", "产量", "產量", "成交量",
    "成交额", "成交額", "订单",   "訂單",   "出口",   "进口",   "進口"};

// A word that names both a rise and a fall (涨跌幅): the sign after it says which (涨跌幅+2.35% 正).
constexpr std::string_view kBothWaysWords[] = {"涨跌幅", "漲跌幅"};

// A word earlier in the clause that names a change (kChangeWords): a + after it is not said.
bool names_change(const std::vector<CodePoint>& text, std::size_t start) {
    return contains_any(text_before(text, start, true), kChangeWords);
}

// A signed change right after 同比 or 环比, or a comparison with an earlier time (较上年, 比去年同期,
// 较上月), is said as news writes it (同比+15% 同比增长百分之十五, 环比-3.2% 环比下降百分之三点二; session
// 27: 同比百分之十五, 负百分之三点二): a rise of a price 上涨 (房价, CPI, 消费价格), of a rate's percentage
// points 提高 (毛利率同比+0.5个百分点), of anything else 增长; a fall 下降. Empty where no comparison stands
// right before the sign.
std::string change_after_comparison(const std::vector<CodePoint>& text, std::size_t start, std::size_t end,
                                    bool rise) {
    std::string before = text_before(text, start, true);
    while (ends_with(before, " ")) before.pop_back();
    const bool compares_with_earlier_time =
        contains_any(before, kComparedWith) && ends_with_any(before, kEarlierTimes);
    if (!ends_with_any(before, kComparisonWords) && !compares_with_earlier_time) return {};
    if (!rise) return "下降";
    if (starts_with_any(text_between(text, end, end + 4), kPercentagePoints)) return "提高";
    // A clause that is its comparison word alone shares the sentence's subject
    // (消费价格同比-0.3%，环比+0.1%), looked for back to the sentence's end mark: text_before stops at the
    // decimal point of 0.3%.
    auto first = start;
    if (is_any_of(before, kComparisonWords))
        while (first > 0 && !is_one_of(text[first - 1].value, U"。！？；!?;\n")) --first;
    const std::string subject = first < start ? text_between(text, first, start) : before;
    return contains_any(subject, kPriceWords) ? "上涨" : "增长";
}

// A signed percentage right after an amount a company or an economy reports (净利润-5%, 营收+3%, 出口-2.1%)
// is its change, said as news says it: 下降 and 增长, as after 同比 (session 28: 负 and 涨, an index's
// words). The amount's own value stays signed (净利润-12亿元 负十二亿元, a loss).
std::string change_of_amount(const std::vector<CodePoint>& text, std::size_t start, bool rise) {
    const std::string before = text_before(text, start, true);
    if (!ends_with_any(before, kReportedAmounts)) return {};
    return rise ? "增长" : "下降";
}

// A - before a percentage right after what moves (恒指-0.8%, 腾讯-1.5%) is its fall, 跌, as its + is 涨;
// after a rate's or a value's word (增速-6.8%, 收益率为-12.35%, 涨跌幅-1.87%) it is the value's sign, 负.
bool is_fall_of_what_moves(const std::vector<CodePoint>& text, std::size_t start) {
    const std::string before = text_before(text, start, true);
    return !before.empty() && !names_change(text, start) && !ends_with_any(before, kValueWordEnds) &&
           !is_ascii_letter(value_at(text, start - 1)) && !is_digit_at(text, start - 1);
}

// A 度 after a number measures degrees (两度) where the sentence speaks of a temperature (气温只有2度),
// the clause of an angle (夹角是2度, 旋转2度), or an amount closes it (2度左右, 2度以上, 2度。); before a
// burn's or a frostbite's word it grades the injury (2度烫伤 二度烫伤), and elsewhere it may count
// times (2度夺冠 二度夺冠), so it stays 二 (session 16; 2度 was always 二度).
bool measures_degrees(const std::vector<CodePoint>& text, std::size_t start, std::size_t degree) {
    if (value_at(text, degree) != U'度') return false;
    const std::string after = text_between(text, degree + 1, degree + 3);
    for (const std::string_view injury : {"烧伤", "燒傷", "烫伤", "燙傷", "灼伤", "灼傷", "冻伤", "凍傷"})
        if (after == injury) return false;
    if (speaks_of_temperature(text, start)) return true;
    const std::string before = text_before(text, start, true);
    if (contains_any(before, {"角", "旋转", "旋轉", "转", "轉", "偏", "倾斜", "傾斜", "斜"})) return true;
    if (starts_with_any(after, {"左右", "以上", "以下", "以内", "以內", "之间", "之間", "的"})) return true;
    constexpr std::u32string_view kClauseEnds = U"，,。.！!？?；;、)）";
    return degree + 1 >= text.size() || kClauseEnds.find(text[degree + 1].value) != std::u32string_view::npos;
}

// The unit of a blood pressure and where it ends: mmHg (140/90mmHg), or none where the clause names one
// (血压130/85, ending at `end`).
struct PressureUnit {
    const char* words = "";
    std::size_t end = 0;
};

// Two numbers about a slash, text[start, end), are a blood pressure, the higher 比 the lower as a doctor
// reads them, before its unit (140/90mmHg) or where the clause names one (血压130/85); elsewhere they are
// a fraction (nullopt).
std::optional<PressureUnit> blood_pressure_unit(const std::vector<CodePoint>& text, std::size_t start,
                                                std::size_t end) {
    std::size_t unit_end = end;
    if (const Unit* unit = unit_at(text, end, unit_end); unit != nullptr && unit->written == "mmHg")
        return PressureUnit{unit->words, unit_end};
    const std::string before = text_before(text, start, true);
    if (!contains_any(before, {"血压", "血壓"})) return std::nullopt;
    return PressureUnit{"", end};
}

// A range's second end joined by 至 or 到 at text[end] (-3至5度, -5到3℃) and a temperature after it: the
// first end's sign is a temperature's too (零下三至五度; session 19: 负三).
bool range_word_before_temperature(const std::vector<CodePoint>& text, std::size_t start, std::size_t end) {
    if (!is_one_of(value_at(text, end), U"至到") || !is_digit_at(text, end + 1)) return false;
    const auto second = parse_number(text, end + 1);
    std::size_t unit_end = second.end;
    const Unit* unit = unit_at(text, second.end, unit_end);
    return is_temperature_reading(text, start, unit, value_at(text, second.end));
}

// A range mark at text[mark] between two quantities with the same unit (-5℃~3℃, 5km-10km): 到, as between
// two dates (session 19: the mark was silent after the first's unit, 零下五摄氏度三摄氏度).
bool joins_quantities(const std::vector<CodePoint>& text, std::size_t mark) {
    if (!is_range_mark(value_at(text, mark))) return false;
    constexpr std::size_t kLongestUnit = 6;  // code points: mmol/L
    const Unit* first = nullptr;
    for (std::size_t length = 1; length <= kLongestUnit && length < mark && first == nullptr; ++length) {
        std::size_t unit_end = mark - length;
        const Unit* unit = unit_at(text, mark - length, unit_end);
        if (unit != nullptr && unit_end == mark && is_digit_at(text, mark - length - 1)) first = unit;
    }
    if (first == nullptr || first->written == "%") return false;
    auto k = mark + 1;
    if (is_dash(value_at(text, k)) || value_at(text, k) == '+') ++k;
    if (!is_digit_at(text, k)) return false;
    const auto second = parse_number(text, k);
    std::size_t unit_end = second.end;
    const Unit* unit = unit_at(text, second.end, unit_end);
    return unit != nullptr && unit->written == first->written;
}

// Whether the clause around text[end] speaks of a picture's size (分辨率, 视频, 屏, 画质): a k after a number
// there is a resolution's (4k屏), not a thousand.
bool speaks_of_picture(const std::vector<CodePoint>& text, std::size_t end) {
    const std::string clause = text_before(text, end, true) + text_after(text, end);
    return contains_any(clause, {"分辨", "视频", "視頻", "屏", "画质", "畫質", "电视", "電視", "帧", "幀"});
}

// Whether the sentence around text[end] speaks of running, a race or a walk (跑 马拉松 配速 越野 徒步 骑行
// 健走 竞走): a k after a number there is the kilometres a runner counts (跑了个5k, 5K趣味跑), not a
// thousand.
bool speaks_of_running(const std::vector<CodePoint>& text, std::size_t end) {
    const std::string sentence = text_before(text, end, false) + text_after(text, end, false);
    return contains_any(
        sentence, {"跑", "马拉松", "馬拉松", "配速", "越野", "徒步", "骑行", "騎行", "健走", "竞走", "競走"});
}

// The magnitude a chat writes as a small letter right after a number in a Chinese line, as posts write
// it: w 万 (播放量破1w 一万, 存够5w; session 19: the letter, da bu liu) and k 千 (月薪8k 八千; session 20:
// the letter, kei), "" where there is none. Not before another letter (5wt) or a digit, not in a line
// without Chinese characters, and a k not where the clause speaks of a picture (4k屏 is a resolution's).
// Where the sentence speaks of running, a k, small or capital, is a runner's kilometres, 公里 (跑了个5k
// 五公里, 10K 十公里; session 21: 五千, and the capital a letter), as km is said.
std::string_view chat_magnitude(const std::vector<CodePoint>& text, std::size_t end) {
    const auto letter = value_at(text, end);
    if (!is_one_of(letter, U"wkK") || is_ascii_letter(value_at(text, end + 1)) || is_digit_at(text, end + 1))
        return {};
    if (!std::any_of(text.begin(), text.end(), [](const CodePoint& c) { return is_han(c.value); })) return {};
    if (letter != 'w' && speaks_of_running(text, end)) return "公里";
    if (letter == 'K') return {};
    if (letter == 'w') return "万";
    return speaks_of_picture(text, end) ? std::string_view{} : "千";
}

// A chat's +1 that closes its clause after a person (我+1, 楼上+1): "me too", 加一, as a +1 standing alone
// is (session 20: 正一). 温差+1 keeps its sign.
bool agrees_after_person(const std::vector<CodePoint>& text, std::size_t start, std::size_t end) {
    if (start == 0 || !(end >= text.size() || is_one_of(value_at(text, end), U"，,。.！!？?～~…\n ")))
        return false;
    if (is_one_of(text[start - 1].value, U"我你他她俺咱们們")) return true;
    const auto before = text_between(text, start >= 2 ? start - 2 : 0, start);
    return before == "楼上" || before == "樓上" || before == "楼主" || before == "樓主";
}

// A radio band right before a number (FM103.9, AM 639, 调频97.4; one space allowed): a station's frequency.
bool follows_station_band(const std::vector<CodePoint>& text, std::size_t start) {
    auto i = start;
    if (i > 0 && text[i - 1].value == ' ') --i;
    if (i >= 2 && value_at(text, i - 1) == 'M' && is_one_of(value_at(text, i - 2), U"FA") &&
        (i == 2 || !is_ascii_letter(value_at(text, i - 3)))) {
        return true;
    }
    const auto before = text_between(text, i >= 2 ? i - 2 : 0, i);
    return before == "调频" || before == "調頻" || before == "调幅" || before == "調幅";
}

// Whether the sentence around text[start, end) speaks of a sports season or a league's table.
bool speaks_of_season(const std::vector<CodePoint>& text, std::size_t start, std::size_t end) {
    std::string sentence = text_before(text, start, false);
    for (auto i = end; i < text.size() && !is_one_of(value_at(text, i), U"\u3002.!?;\n"); ++i) sentence += text[i].text;
    return contains_any(
        sentence, {"赛季", "賽季", "常规赛", "常規賽", "例行赛", "例行賽", "季后赛", "季後賽", "排名", "联盟",
                   "聯盟", "东部", "東部", "西部", "胜率", "勝率", "积分榜", "積分榜"});
}

// A game's record of kills, deaths and assists (战绩0-10, KDA 5-2-10), each part said with 杠 between, as
// players read it out (零杠十; session 16: a range, 零到十). Up to three parts of one or two digits,
// where 战绩 or KDA stands earlier in the clause, or right after one player's pronoun with the record
// closing its clause (这把我0-8， 零杠八; session 23: a range, 零到八): a range closing a clause has a word
// to count (3-5天), and a team's 我们2-1 and a match's 决赛他3-1 are scores.
std::optional<SpokenForm> read_game_record(const std::vector<CodePoint>& text, std::size_t start,
                                           const WrittenNumber& first) {
    constexpr std::size_t kMostParts = 3;
    constexpr std::size_t kMostDigits = 2;
    if (first.has_point || first.has_separators || first.whole.size() > kMostDigits) return std::nullopt;
    const std::string before = text_before(text, start, true);
    const bool names_record = contains_any(before, {"战绩", "戰績", "KDA"});
    const bool after_player =
        start > 0 && is_one_of(text[start - 1].value, U"我你他她") && !contains_any(before, {"赛", "賽"});
    if (!names_record && !after_player) return std::nullopt;
    SpokenForm form;
    form.words = cardinal_words(first.whole, false);
    auto i = first.end;
    std::size_t parts = 1;
    // The parts are set off by dashes, or by slashes where all three stand (KDA 12/3/5 十二杠三杠五; session
    // 22: 五分之十二; 3/5 stays a fraction).
    const bool slashed = value_at(text, first.end) == '/';
    const auto is_part_mark = [&](std::size_t k) {
        return slashed ? value_at(text, k) == '/' : is_dash(value_at(text, k));
    };
    while (parts < kMostParts && is_part_mark(i) && is_digit_at(text, i + 1)) {
        auto k = i + 1;
        const auto part = digits_from(text, k);
        if (part.size() > kMostDigits || value_at(text, k) == '.') break;
        form.words += "杠" + cardinal_words(part, false);
        i = k;
        ++parts;
    }
    if (parts < (slashed ? kMostParts : 2) || is_digit_at(text, i) || is_part_mark(i)) return std::nullopt;
    if (!names_record && !(i >= text.size() || is_one_of(text[i].value, U"，,。.！!？?；;～~…\n ")))
        return std::nullopt;
    // A season's record of wins and losses (湖人目前战绩30-12，排名西部第2; 本赛季战绩45-37) is said
    // 三十胜十二负, as newsreaders say it (session 17: 三十杠十二): two parts where the sentence speaks
    // of a season or a table (赛季 常规赛 季后赛 排名 联盟 东部 西部 胜率 积分榜).
    if (parts == 2 && speaks_of_season(text, start, i)) {
        auto k = first.end + 1;
        form.words = cardinal_words(first.whole, false) + "胜" + cardinal_words(digits_from(text, k), false) + "负";
    }
    form.end = i;
    return form;
}

// The second end of a range of versions joined by a word (Python 3.8到3.11 三点八到三点十一): a version
// as the first is (session 16, seen in dev6's held-out part: 三点一一). A mark between them (3.8~3.11)
// makes one form, read with the first's context.
bool ends_range_of_versions(const std::vector<CodePoint>& text, std::size_t start) {
    if (start < 2 || !is_one_of(text[start - 1].value, U"到至")) return false;
    auto k = start - 1;
    bool has_point = false;
    while (k > 0 && (is_digit_at(text, k - 1) || value_at(text, k - 1) == '.')) {
        has_point = has_point || value_at(text, k - 1) == '.';
        --k;
    }
    return has_point && k < start - 1 && is_digit_at(text, k) && follows_software_name(text, k);
}

// A result between two teams' names (曼城2-1阿森纳, 上海海港3-3北京国安, 皇马3-0巴萨): a range is written
// from its low end up, so two whole numbers that fall or stay level between two names are a score
// (session 16; they were a range, 二到一). Not after 第, nor before a measure word or a word of a
// date, a time, a floor or a degree (3-1日, 5-3楼).
bool is_result_between_names(const std::vector<CodePoint>& text, std::size_t start, const WrittenNumber& first,
                             const WrittenNumber& second) {
    if (first.has_point || first.has_separators || second.has_point || second.has_separators || start == 0) return false;
    const auto before = text[start - 1].value;
    const auto after = value_at(text, second.end);
    if (!is_han(before) || before == U'第' || !is_han(after) || takes_liang(after) ||
        is_one_of(after, U"年月日号號时時点點分秒度楼樓层層室栋棟届屆期")) {
        return false;
    }
    const auto first_value = first.whole.size() <= kMostCardinalDigits ? std::stoull(first.whole) : 0;
    const auto second_value = second.whole.size() <= kMostCardinalDigits ? std::stoull(second.whole) : 1;
    return first.whole.size() <= kMostCardinalDigits && second.whole.size() <= kMostCardinalDigits &&
           first_value >= second_value;
}

// A + between a word and a number where the clause before it holds a number of its own: it joins two
// quantities, 加, as a spec sheet lists its parts (5000万像素主摄+1200万超广角, 16GB内存+1TB硬盘; session 20:
// 正一千二百). A sign alone in its clause keeps its reading (温差+12 正十二), and a change in percent is a
// rise (Q3净利润同比增长+15.2%: the Q3 is no quantity added to).
bool adds_to_quantity(const std::vector<CodePoint>& text, std::size_t start) {
    if (start == 0 || value_at(text, start) != '+' || !is_han(text[start - 1].value)) return false;
    const std::string before = text_before(text, start, true);
    return before.find_first_of("0123456789") != std::string::npos;
}

// Right after a + that follows 第 and a number (第90+2分钟, stoppage time's minute): the added number is the
// ordinal's too, 第九十加二分钟 (session 28: 两分钟, a count of minutes).
bool adds_to_ordinal(const std::vector<CodePoint>& text, std::size_t start) {
    if (start == 0 || value_at(text, start - 1) != '+') return false;
    auto k = start - 1;
    while (k > 0 && is_digit_at(text, k - 1)) --k;
    return k + 1 < start && k > 0 && text[k - 1].value == U'第';
}

// A generation, two digits right before 后 (90后 九零后), or the first of a list of them joined by 、 that
// ends before 后 (80、90后 八零、九零后, 70、80、90后; session 29: 八十、九零后, the first counted).
bool names_generation(const std::vector<CodePoint>& text, const WrittenNumber& number) {
    constexpr std::size_t kGenerationDigits = 2;
    if (number.has_point || number.has_separators || number.whole.size() != kGenerationDigits) return false;
    const auto last_start = last_listed_start(text, number, kGenerationDigits);
    const auto end = last_start == 0 ? number.end : parse_number(text, last_start).end;
    return is_one_of(value_at(text, end), U"后後");
}

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
    bool names_place = false;  // a room's or building's name after it (302会议室), a city's before (台北101)
    bool names_day = false;     // a day named by its date's digits (618大促, 今天是520)
    bool names_type = false;    // before 型 or 式, a type's number (737型, 99式)
    bool is_generation = false;  // two digits right before 后 (90后, 00后), or a list of them (80、90后)
    bool is_house_number = false;  // a street's (路 街 道 段 巷 弄) before 号: 文化路一段100號 一百號
    bool is_stake_metres = false;  // the metres after a motorway's stake and its +: K15+200路段 二百
    bool is_hundredths = false;  // right after the seconds of a time (9秒83) or a jump's metres (8米22)
    bool is_grade = false;       // a respirator's filter grade (N95)
    bool is_span_of_years = false;  // four digits before 年 that count years, not name one (距今约5000年)
    bool is_code = false;        // a stock's code, an index's or a programme's number (（600519）, 日经225, 985高校)
    bool is_version = false;     // after a software's name or a v (Python 3.12, v2.15): a version
    bool names_year = false;     // a year before a word it names (2025财年, 2026款)
    bool after_laugh = false;    // right after a laugh's character (哈哈233)
    bool is_whole_clause = false;  // the number alone between clause marks (88，下次再聊)
    bool measures_degrees = false;  // before a 度 of a temperature or an angle (2度左右 两度)
    bool is_frequency = false;   // a station's frequency after FM, AM or 调频 (FM103.9 一零三点九)
    bool is_count_over = false;  // a + after it and no term after that (99+ 九十九加; 666+1 is a sum)
    bool after_times = false;  // right after a times sign, a count of items (金币×888 乘八百八十八)
    bool names_schedule =
        false;  // a work schedule by its hours and days (996, 955), not after a price (售价996)
};

struct SaidNumber {
    std::string words;
    bool is_year = false;
    bool is_dialled = false;  // a phone's or a service's number, 1 said 幺
    std::string warning;
};

// A number with a point (number.has_point) said as a station's frequency, a version or a decimal.
SaidNumber say_decimal(const WrittenNumber& number, const NumberContext& context) {
    SaidNumber said;
    const auto& whole = number.whole;
    // A station's frequency is said as stations name themselves, digit by digit before the point
    // too (FM103.9 一零三点九, 调频97.4 九七点四; session 17: 一百零三点九).
    if (context.is_frequency && whole.size() <= 3) {
        said.words = digit_words(whole) + "点" + digit_words(number.fraction);
        return said;
    }
    // A version's part after the point is a number (Python 3.12 三点十二, as 10.15.7 is 十点十五点七);
    // a decimal's digits are said one by one (3.12 三点一二).
    // 下 after a version is the setting it runs under (在Python 3.12下运行), no count of strokes: a
    // count of strokes is whole (session 28: 三点一二).
    const bool counts =
        context.has_unit || (takes_liang(context.next) && context.next != U'下') || context.next == '%';
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

// Whether a chat's number (`whole`, written without separators) names rather than counts, said digit
// by digit: a goodbye, a vow, an agreement, a cheer, a laugh. `counts` where a unit, a measure word or a
// % follows it.
bool is_chat_number(const std::string& whole, const NumberContext& context, bool counts) {
    // A chat's goodbye, 88 or 886 (拜拜, 拜拜了) as a clause of its own (88，下次再聊), is said digit by
    // digit, 八八 (session 14); a bare 88 after a colon or in a clause counts (得分：88, 考了88分).
    if ((whole == "88" || whole == "886") && context.is_whole_clause) return true;
    const bool names_nothing = !counts && !context.has_currency && !context.is_ordinal;
    // A chat's vow, 1314 (一生一世) and 5201314, counting nothing, is said digit by digit (我爱你1314
    // 一三一四; session 14), as 520 is where it names its day.
    // So is a work schedule, 996 or 955 (又是996的一周 九九六; session 30: 九百九十六), where it counts
    // nothing.
    if ((whole == "1314" || whole == "5201314" || context.names_schedule) && names_nothing) return true;
    // A pair of digits written twice over as a clause of its own (9494，我也是这么想的: 就是就是, a
    // chat's agreement), digit by digit as 88 is (session 20: 九千四百九十四); a year standing so reads
    // alike.
    const bool is_pair_over =
        whole.size() == 4 && whole[0] != whole[1] && whole.compare(0, 2, whole, 2, 2) == 0;
    if (is_pair_over && context.is_whole_clause) return true;
    // One digit said three or more times over, as a chat cheers (666 六六六, 888); a count shown as "or
    // more" counts (999+条消息 九百九十九加).
    const bool is_one_digit_over = whole.size() >= 3 &&
                                   whole.find_first_not_of(whole.front()) == std::string::npos &&
                                   !context.is_count_over;
    // A chat's laugh, 2333 (a 2 and three or more 3s: 二三三三, after an emoticon's number), and 233 right
    // after a laugh's character (哈哈哈233, 笑死233; session 14); elsewhere it counts (233人).
    const bool is_laugh = whole.front() == '2' && whole.find_first_not_of('3', 1) == std::string::npos &&
                          (whole.size() >= 4 || (whole.size() == 3 && context.after_laugh));
    return (is_one_digit_over || is_laugh) && names_nothing;
}

// Whether the words around a number (`whole`, written without separators) make it a name, said digit by
// digit: a generation (90后 九零后), the hundredths of a sprint (9秒83 九秒八三), a code, a model's number
// of three or more digits (C919 C九一九, A380) and a type's of two or more (99式 九九式, 737型), a day
// named by its date (618 六一八), a filter grade, a year before the word it names (2026款). `counts` as
// is_chat_number's.
bool is_named_by_context(const std::string& whole, const NumberContext& context, bool counts) {
    // A filter grade is a name before any word (N95口罩: 口 is no measure word there). A round
    // thousand after capitals is a tier, not a model (WTA 1000 一千, RTX 5000 五千), and so is a round
    // hundred of three digits but in a train's or a flight's number (HDR400 四百, A100 一百, C200 二百;
    // session 26: 四零零).
    const bool is_round_tier = (whole.size() >= 4 && whole.compare(whole.size() - 3, 3, "000") == 0) ||
                               (whole.size() == 3 && whole.compare(1, 2, "00") == 0 && !context.is_train);
    // A code is one whatever character follows (创业板300059成交额: 成 begins a word there, no tenths):
    // names_by_its_digits has looked at what follows it.
    return context.is_grade || context.names_year || (context.is_code && !context.has_unit) ||
           (!counts && (context.is_generation || context.is_hundredths ||
                        (context.is_model && whole.size() >= 3 && !is_round_tier) ||
                        (context.names_type && whole.size() >= 2) || context.names_day));
}

// A whole number written without separators (`whole`) said as it names rather than counts, digit by
// digit (a phone's, a train's, a model's, a code's, a chat's 666 and 88) or as a year; nullopt where
// it counts.
std::optional<SaidNumber> say_as_name(const std::string& whole, const NumberContext& context) {
    SaidNumber said;
    const bool is_mobile = whole.size() == 11 && whole.front() == '1';
    // A phone word earlier in the sentence does not make an amount a phone number (这款手机售价5999元).
    const bool counts = !context.is_train && (context.has_unit || takes_liang(context.next) ||
                                              context.next == '%' || context.after_times);
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
    if (is_chat_number(whole, context, counts) || is_named_by_context(whole, context, counts)) {
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
    if (whole.size() >= 3 &&
        ((names_by_digits(context.next) && !context.is_house_number && !context.is_stake_metres) ||
         context.is_named || (context.names_place && !counts))) {
        said.words = digit_words(whole);
        return said;
    }
    return std::nullopt;
}

SaidNumber say_number(const WrittenNumber& number, const NumberContext& context) {
    if (number.has_point) return say_decimal(number, context);
    SaidNumber said;
    const auto& whole = number.whole;
    if (whole.size() > kMostCardinalDigits) {
        said.words = digit_words(whole);
        said.warning = kTooLongWarning;
        return said;
    }
    if (!number.has_separators)
        if (auto named = say_as_name(whole, context)) return *named;
    // A discount of two digits is said digit by digit (95折 九五折, 75折 七五折), as shops call it; one digit
    // or one with a point counts (8折, 3.8折 三点八折).
    if (whole.size() == 2 && !number.has_point && context.next == U'折' && whole[0] != '0' &&
        whole[1] != '0') {
        said.words = digit_words(whole);
        return said;
    }
    if (whole == "2" && !context.is_ordinal && !context.is_model &&
        (context.has_unit || takes_liang(context.next) || context.measures_degrees)) {
        said.words = "两";
        return said;
    }
    said.words = cardinal_words(whole, !context.is_ordinal);
    return said;
}

// A charger's or a port's rating, its volts, a slash and the current or the power it gives at them (5V/2A
// 五伏两安, 20V/3.25A, 9V/2A两档), said as the pair it is, the slash unsaid: no quantity is per a current.
// `divisor` is the number after the slash at text[end]: its words and its unit's, `end` moved past them;
// nullopt where no volt's V stands before the slash or no current's or power's unit follows the number.
std::optional<std::string> rated_current_words(const std::vector<CodePoint>& text, std::size_t& end,
                                               const WrittenNumber& divisor) {
    if (end == 0 || text[end - 1].value != 'V' || divisor.has_separators) return std::nullopt;
    auto k = divisor.end;
    std::string unit_words;
    for (const auto& [written, said] :
         {std::pair{"mA", "毫安"}, std::pair{"A", "安"}, std::pair{"W", "瓦"}}) {
        const std::string_view symbol = written;
        if (text_between(text, k, k + symbol.size()) != symbol) continue;
        k += symbol.size();
        unit_words = said;
        break;
    }
    if (unit_words.empty() || is_ascii_letter(value_at(text, k)) || is_digit_at(text, k)) return std::nullopt;
    NumberContext quantity;
    quantity.has_unit = true;  // 2A 两安, as before any unit
    end = k;
    return say_number(divisor, quantity).words + unit_words;
}

// What a slash after a quantity's unit ending at text[end] is per, said 每 and moving `end` past it: another
// unit, with its number where it has one (7.0mmol/L 每升, 35μg/m³ 每立方米, 80mg/100ml 每一百毫升), or a
// measure word, which is read after it as the text it is (0.3g/粒 零点三克每粒, 100mg/片; session 19: the
// slash was silent). "" where none follows.
std::string per_unit_words(const std::vector<CodePoint>& text, std::size_t& end) {
    if (value_at(text, end) != '/') return "";
    auto k = end + 1;
    std::string divisor_words;
    if (is_digit_at(text, k)) {
        const auto divisor = parse_number(text, k);
        if (auto current = rated_current_words(text, end, divisor)) return *current;
        divisor_words = say_number(divisor, {}).words;
        k = divisor.end;
    }
    std::size_t per_end = k;
    const Unit* per = value_at(text, k) == ' ' ? nullptr : unit_at(text, k, per_end);
    if (per != nullptr && per->written != "%") {
        end = per_end;
        return "每" + divisor_words + per->words;
    }
    if (!divisor_words.empty() || !takes_liang(value_at(text, k))) return "";
    end = k;
    return "每";
}

// 升 at text[i] after a number is litres (2升水, 每天饮水2升为宜) but begins a verb before 到 至 级
// (显卡从RTX 2060升到了3060): the number measures nothing there (session 28: 两千零六十, a card's digits
// counted).
bool begins_rise(const std::vector<CodePoint>& text, std::size_t i) {
    return is_one_of(value_at(text, i), U"升昇") && is_one_of(value_at(text, i + 1), U"到至级級");
}

// A relation sign after text[end] (spaces allowed): the numbers before it are a lesson's terms.
bool relation_follows(const std::vector<CodePoint>& text, std::size_t end) {
    while (value_at(text, end) == ' ') ++end;
    return is_relation_sign(value_at(text, end));
}

// A number's sign or currency before its digits at text[start] and where its digits start: the sign
// said (正, 负, 加, 减; ± 正负, ↑ 涨, ↓ 跌) or "" where none is said or a dash is no sign; nullopt where no
// digit follows.
struct LeadingSign {
    const Currency* currency = nullptr;
    std::string words;
    std::size_t digits = 0;
};

std::optional<LeadingSign> read_leading_sign(const std::vector<CodePoint>& text, std::size_t start) {
    auto i = start;
    const Currency* currency = currency_at(text, i, i);
    std::string sign_words;
    const auto first = value_at(text, i);
    // After a term (a digit, a letter, a square: x²+2x) a + or a - joins it to the next, a sign no more.
    const bool after_word = start > 0 && (is_digit_at(text, start - 1) || is_ascii_letter(value_at(text, start - 1)) ||
                                          is_one_of(text[start - 1].value, U"\u00B2\u00B3"));
    // A subtitle's dash before a speaker's turn (-12号，周五。) is no sign either (session 25: 负十二), nor
    // is the second half of the Chinese dash, two em dashes (——3年后, a script's time skip; session 31: 负).
    const bool ends_chinese_dash = first == 0x2014 && start > 0 && text[start - 1].value == 0x2014;
    if (currency == nullptr && is_dash(first) && is_digit_at(text, i + 1) &&
        (follows_designation(text, start) || follows_element(text, start) || opens_turn(text, start) ||
         ends_chinese_dash)) {
        ++i;
    } else if (currency == nullptr && is_one_of(first, U"\u00B1\u2191\u2193") && is_digit_at(text, i + 1)) {
        // ± is 正负, as a tolerance is read (误差±0.5mm); an arrow before a change is the rise or the fall
        // it draws, 涨 and 跌, as market reports read ↑3.2% and ↓1.5% (session 20: skipped with a warning).
        sign_words = first == 0xB1 ? "正负" : first == 0x2191 ? "涨" : "跌";
        ++i;
    } else if (currency == nullptr && (is_dash(first) || first == '+') && is_digit_at(text, i + 1) &&
               !after_word) {
        sign_words = first == '+' ? "正" : "负";
        // A game's buff and debuff: after an attribute the sign adds or takes away (攻击力+15 加十五,
        // 移速-15% 减百分之十五; session 30: 负, and 跌 before a percentage, a market's fall). A - after a
        // word in 值 stays a value's sign (净值-2%, 差值-3).
        const bool takes_away = is_dash(first) && start > 0 && text[start - 1].value != U'值';
        if ((follows_game_attribute(text, start) || follows_gauge(text, start)) &&
            (first == '+' || takes_away))
            sign_words = first == '+' ? "加" : "减";
        ++i;
    }
    if (!is_digit_at(text, i)) return std::nullopt;
    return LeadingSign{currency, std::move(sign_words), i};
}

// How the text about `number` (its digits at text[i], its sign or currency from text[start]) says it
// is said; what follows its last digits and unit (NumberContext::next, has_unit, measures_degrees,
// is_count_over) read_quantity sets.
NumberContext context_of_number(const std::vector<CodePoint>& text, std::size_t start, std::size_t i,
                                const WrittenNumber& number, const std::string& sign_words,
                                const Currency* currency) {
    NumberContext context;
    std::size_t previous = start;
    while (previous > 0 && text[previous - 1].value == ' ') --previous;
    context.is_ordinal = (previous > 0 && text[previous - 1].value == U'第') || adds_to_ordinal(text, start);
    context.is_phone = follows_phone_word(text, start);

    context.is_named = follows_name_word(text, start);
    // A house's number right after its street (文化路一段100號, 中山路128号) counts, as addresses are read
    // out (session 15: 一零零號); a room's or a building's (1203号, 305室) is a name, digit by digit.
    context.is_house_number = previous > 0 && is_one_of(text[previous - 1].value, U"路街道段巷弄") &&
                              is_one_of(value_at(text, number.end), U"号號");
    // A count after a times sign is none (金币x100: the x is said 乘).
    const bool after_times = start > 0 && said_math_sign(text, start - 1) == "乘";
    context.after_times = after_times;
    // A motorway's stake, K and its kilometres, a + and the metres past them (K1234+500), counts, as
    // traffic reports read it: K 一千二百三十四加五百 (session 24: a model's digits, 一二三四).
    const auto follows_stake_letter = [&](std::size_t digits) {
        return digits > 0 && value_at(text, digits - 1) == 'K' &&
               (digits == 1 || !is_ascii_letter(value_at(text, digits - 2)));
    };
    const bool is_stake =
        follows_stake_letter(start) && value_at(text, number.end) == '+' && is_digit_at(text, number.end + 1);
    // The metres past it count wherever they stand, before a road section's 路段 too (K15+200路段 二百;
    // session 31: a bus route's digits, 二零零路).
    auto kilometres = start > 0 && value_at(text, start - 1) == '+' ? start - 1 : 0;
    while (kilometres > 0 && is_digit_at(text, kilometres - 1)) --kilometres;
    context.is_stake_metres = kilometres + 1 < start && follows_stake_letter(kilometres);
    context.is_model = sign_words.empty() && currency == nullptr && !after_times && !is_stake &&
                       (follows_model_name(text, start) || follows_maker_name(text, start) ||
                        follows_glued_name(text, start) || names_code_by_letters(text, start, number) ||
                        repeats_card_model(text, start, number) ||
                        // An isotope's number after a hyphen (碳-14), or of three digits or more glued to
                        // a radioactive element's name, which names its isotopes (铀235, 铯137; 钠500毫克 and
                        // 补钙2片 count).
                        (follows_element(text, start) &&
                         (is_dash(value_at(text, start)) ||
                          (number.whole.size() >= 3 && start > 0 &&
                           is_one_of(text[start - 1].value, U"铀鈾钚鈽铯銫锶鍶钴鈷碘镭鐳氡钍釷镅鋂钋釙")))));
    context.is_train = context.is_model && !number.has_point && !number.has_separators &&
                       (is_train_number(text, start, number.end) || is_flight_number(text, start, number.end));
    context.has_currency = currency != nullptr;
    context.names_place = names_room_or_building(text, number.end) ||
                          (sign_words.empty() && currency == nullptr && !context.is_ordinal &&
                           names_landmark_after_city(text, start, number));
    context.names_day = sign_words.empty() && currency == nullptr && names_a_day(text, start, number);
    context.names_type = is_one_of(value_at(text, number.end), U"型式");
    context.is_generation = names_generation(text, number);
    // 996 is nine to nine, six days a week, and 955 its opposite; after a price word (售价996, 价格：996)
    // they count.
    auto word_end = previous;
    while (word_end > 0 && is_one_of(ascii_form(text[word_end - 1].value), U": ")) --word_end;
    const bool after_price = word_end > 0 && is_one_of(text[word_end - 1].value, U"价價");
    context.names_schedule = (number.whole == "996" || number.whole == "955") && !number.has_point &&
                             !number.has_separators && !after_price;
    // The hundredths after a sprint's seconds (9秒83), and the centimetres after a jump's or a throw's
    // metres (8米22 八米二二, 1米75; session 15: 二十二), two digits and no unit of their own after them.
    const bool after_metres = text[start > 0 ? start - 1 : 0].value == U'米' && number.whole.size() == 2 &&
                              !number.has_point && !is_one_of(value_at(text, number.end), U"厘公分毫");
    context.is_hundredths = start >= 2 && (text[start - 1].value == U'秒' || after_metres) && is_digit_at(text, start - 2);
    context.is_grade = context.is_model && is_filter_grade(text, start, number.whole);
    context.is_span_of_years = counts_years(text, start, number);
    context.is_service_call = is_service_call(text, start, number.end);
    context.is_code = sign_words.empty() && currency == nullptr && names_by_its_digits(text, i, number);
    context.is_frequency = sign_words.empty() && currency == nullptr && follows_station_band(text, start);
    context.is_version = sign_words.empty() && currency == nullptr &&
                         (follows_software_name(text, i) || ends_range_of_versions(text, i));
    // A version before 后 is no generation (升级到Android 15后 十五后; session 17: 一五后).
    if (context.is_version) context.is_generation = false;
    // Or after a chat's final particle, closing its line (太离谱了吧233, 好好笑啊233; session 16: 二百三十三).
    const auto after_number = value_at(text, number.end);
    const bool closes_clause = number.end >= text.size() || is_one_of(after_number, U"，,。.！!？?～~…\n ");
    // Or closing a clause that laughs (笑死我了233; session 21: 二百三十三).
    context.after_laugh =
        sign_words.empty() && start > 0 &&
        (is_one_of(value_at(text, start - 1), U"哈呵嘿嘻笑死") ||
         (closes_clause && (is_one_of(value_at(text, start - 1), U"吧啊呀呢嘛哦啦") ||
                            text_before(text, start, true).find("笑") != std::string::npos)));
    context.is_whole_clause = sign_words.empty() && currency == nullptr && stands_alone(text, start, number.end);
    context.names_year =
        sign_words.empty() && currency == nullptr && !context.is_ordinal &&
        (names_year_before_word(text, number) || lists_year(text, number) ||
         names_short_year(text, start, number) || names_year_after_mark(text, start, number));
    return context;
}

// Two numbers said each alone with a word between, the first after its sign: a score (3:1, and 2-1
// where the clause speaks of a match: 2-1领先), a product (7×24 七乘二十四).
SpokenForm join_two(const WrittenNumber& first, const std::string& sign_words, const WrittenNumber& second,
                    const char* joiner, const NumberContext& each) {
    SpokenForm form;
    const auto first_said = say_number(first, each);
    const auto second_said = say_number(second, each);
    form.words = sign_words + first_said.words + joiner + second_said.words;
    append_warning(form, first_said.warning);
    append_warning(form, second_said.warning);
    form.end = second.end;
    return form;
}

// A number in E notation (学习率1e-3, 2.5E+8), as code and papers write it, is the number it means:
// 一乘十的负三次方, as 10^6 is 十的六次方 (session 28: its e a letter, 一 yi 三). A letter before the
// digits (0x1e5, a hex code's) or after the power (3e5x) leaves a name.
std::optional<SpokenForm> read_e_notation(const std::vector<CodePoint>& text, std::size_t start,
                                          const WrittenNumber& number, const std::string& sign_words) {
    SpokenForm form;
    if (is_one_of(value_at(text, number.end), U"eE") && !number.has_separators &&
        (start == 0 || !is_ascii_letter(value_at(text, start - 1)))) {
        auto k = number.end + 1;
        const bool negative = is_dash(value_at(text, k));
        if (negative || value_at(text, k) == '+') ++k;
        const auto power = digits_from(text, k);
        if (!power.empty() && !is_ascii_letter(value_at(text, k)) && value_at(text, k) != '.') {
            const auto mantissa = say_number(number, {});
            form.words = sign_words + mantissa.words + "乘十的" + (negative ? "负" : "") +
                         cardinal_words(power, false) + "次方";
            append_warning(form, mantissa.warning);
            form.end = k;
            return form;
        }
    }
    return std::nullopt;
}

// Two numbers about a colon (number, then text[number.end]): a race's or a clock's time where no score
// is spoken of, else a score or a ratio of two parts or more, 比 between them; nullopt where no number
// follows the colon.
std::optional<SpokenForm> read_colon_pair(const std::vector<CodePoint>& text, std::size_t start,
                                          const WrittenNumber& number, const NumberContext& context) {
    if (value_at(text, number.end) != ':' || !is_digit_at(text, number.end + 1)) return std::nullopt;
    auto second = parse_number(text, number.end + 1);
    if (!is_score(text, start, second.end)) {
        if (auto time = read_race_time(number, second)) return time;
        // The end of the time's last part (1:23处, 1:02:03处), where a place in a recording names itself.
        auto time_end = second.end;
        while (value_at(text, time_end) == ':' && is_digit_at(text, time_end + 1))
            time_end = parse_number(text, time_end + 1).end;
        const bool duration =
            speaks_of_duration(text, start) || names_place_in_recording(text, start, time_end);
        if (auto time = read_clock_time(text, number, duration)) return time;
    }
    SpokenForm form = join_two(number, "", second, "比", context);
    // A ratio of three parts or more (糖、醋、生抽按2:1:1 二比一比一; session 17: the last 比 was lost).
    while (value_at(text, form.end) == ':' && is_digit_at(text, form.end + 1)) {
        const auto part = parse_number(text, form.end + 1);
        const auto part_said = say_number(part, context);
        form.words += "比" + part_said.words;
        append_warning(form, part_said.warning);
        form.end = part.end;
    }
    return form;
}

// A small x between two numbers is a times sign typed (4x400米接力, 1920x1080), said 乘 as × is.
std::optional<SpokenForm> read_product(const std::vector<CodePoint>& text, const WrittenNumber& number) {
    if (!is_one_of(value_at(text, number.end), U"×*x") || !is_digit_at(text, number.end + 1))
        return std::nullopt;
    const auto second = parse_number(text, number.end + 1);
    // Scientific notation (3×10⁸m/s 三乘十的八次方米每秒): the power goes with it, and so does a unit
    // after the product, a pack's or a size's (6×1.5L 六乘一点五升; session 19: L was a letter), and a
    // measure word or a unit per it (12×500ml/箱 十二乘五百毫升每箱).
    auto power = read_power(text, second.end);
    std::size_t unit_end = power ? power->end : second.end;
    const Unit* unit = unit_at(text, unit_end, unit_end);
    if (unit != nullptr && unit->written == "%") unit = nullptr;
    // The quantity's 2 is 两 (12×2L 十二乘两升), as before any unit.
    NumberContext second_context;
    second_context.has_unit = unit != nullptr && !power;
    const auto first_said = say_number(number, {});
    const auto second_said = say_number(second, second_context);
    SpokenForm form;
    form.words = first_said.words + "乘" + second_said.words;
    append_warning(form, first_said.warning);
    append_warning(form, second_said.warning);
    form.end = power ? power->end : second.end;
    if (power) form.words += power->words;
    if (unit != nullptr) {
        form.words += unit->words + per_unit_words(text, unit_end);
        form.end = unit_end;
    }
    return form;
}

// The forms only a number without a sign or a currency takes (number, its digits at text[i], what is
// before it from text[start]): dates, seasons, records, heights, times, models and codes, a score or a
// difference written with a dash; nullopt where it is none of them.
std::optional<SpokenForm> read_unsigned_form(const std::vector<CodePoint>& text, std::size_t start,
                                             std::size_t i, const WrittenNumber& number,
                                             const NumberContext& context) {
    if (auto masked = read_masked_number(text, number, context.is_phone)) return masked;
    if (auto day = read_dotted_day(text, number)) return day;
    if (auto dotted = read_dotted_groups(text, i)) return dotted;
    if (auto month = read_year_and_month(text, start, number)) return month;
    if (auto floor = read_floor(text, i, number)) return floor;
    if (auto date = read_numeric_date(text, number)) return date;
    if (auto season = read_season(text, number)) return season;
    if (auto figure = read_figure_number(text, start, number)) return figure;
    if (auto record = read_game_record(text, start, number)) return record;
    if (auto height = read_feet_and_inches(text, start, number)) return height;
    if (auto time = read_primed_time(text, number)) {
        time->words += per_unit_words(text, time->end);
        return time;
    }
    if (auto minutes = read_arc_minutes(text, start, number)) return minutes;
    if (auto model = read_series_and_model(text, i, number)) return model;
    if (auto variant =
            context.is_model && !context.is_train ? read_model_variant(text, number) : std::nullopt)
        return variant;
    if (auto digits = read_dashed_digits(text, number, context.is_phone, context.is_named,
                                         follows_book_number(text, start)))
        return digits;
    if (auto code = read_code_with_dash(text, number)) return code;
    if (is_dash(value_at(text, number.end)) && is_digit_at(text, number.end + 1)) {
        auto second = parse_number(text, number.end + 1);
        // A measure word after the pair makes it a range (3-5天后获胜), whatever the clause says.
        const bool may_be_listed_score = !takes_liang(value_at(text, second.end));
        if (is_score(text, start, second.end, may_be_listed_score) ||
            is_result_between_names(text, start, number, second))
            return join_two(number, "", second, "比", {});
        if (relation_follows(text, second.end)) return join_two(number, "", second, "减", {});  // 5-3=2
    }
    if (auto date = read_month_and_day(text, start, number)) return date;
    return std::nullopt;
}

// A place in a whole after 第, a slash between them (第3/10篇 第三篇共十篇, 第27/50关, as a series' part or a
// game's stage is read out; session 31: a fraction, 第十分之三篇): the place, its measure word said with it
// too, 共 and the whole, the measure word written after the whole then read as text. nullopt where no 第
// stands before `number`, either has a point, the place is past the whole, or 决赛 follows (a knockout
// round's 1/4).
std::optional<SpokenForm> read_place_in_whole(const std::vector<CodePoint>& text, std::size_t start,
                                              const WrittenNumber& number, const WrittenNumber& whole) {
    if (start == 0 || text[start - 1].value != U'第' || number.has_point || whole.has_point ||
        text_between(text, whole.end, whole.end + 2) == "决赛" ||
        text_between(text, whole.end, whole.end + 2) == "決賽" || number.has_separators ||
        whole.has_separators || number.whole.size() > whole.whole.size() ||
        (number.whole.size() == whole.whole.size() && number.whole > whole.whole))
        return std::nullopt;
    const auto measure = value_at(text, whole.end);
    const bool has_measure = takes_liang(measure) || is_one_of(measure, U"关關题題站话話卷讲講课課");
    SpokenForm form;
    form.words = say_number(number, {}).words +
                 (has_measure ? std::string(text[whole.end].text) : std::string()) + "共" +
                 say_number(whole, {}).words;
    form.end = whole.end;
    return form;
}

// Two numbers about a slash (number, then text[number.end]): a blood pressure (blood_pressure_unit), 24/7,
// or a fraction, its denominator said first (1/3 三分之一), and a range to a second one (1/3~1/2); nullopt
// where no number follows the slash or the first has a point.
std::optional<SpokenForm> read_slashed_pair(const std::vector<CodePoint>& text, std::size_t start,
                                            const WrittenNumber& number, const std::string& sign_words,
                                            const Currency* currency) {
    if (value_at(text, number.end) != '/' || !is_digit_at(text, number.end + 1) || number.has_point)
        return std::nullopt;
    const auto denominator = parse_number(text, number.end + 1);
    if (const auto pressure = sign_words.empty() && currency == nullptr
                                  ? blood_pressure_unit(text, start, denominator.end)
                                  : std::nullopt) {
        SpokenForm form = join_two(number, sign_words, denominator, "比", {});
        form.words += pressure->words;
        form.end = pressure->end;
        return form;
    }
    // 24/7, hours a day on every day of the week (客服24/7在线), is no fraction: said as written,
    // 二十四七, as 7×24 is 七乘二十四 (session 28: 七分之二十四, a fraction no one writes so).
    if (sign_words.empty() && number.whole == "24" && denominator.whole == "7" && !denominator.has_point &&
        !denominator.has_separators) {
        SpokenForm form;
        form.words = "二十四七";
        form.end = denominator.end;
        return form;
    }
    if (auto place = read_place_in_whole(text, start, number, denominator)) return place;
    SpokenForm form;
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

// A number and, after a range mark, a second one (3-5, 3~5, -8~-3℃), each with its sign; the second only
// where it ends with a % as the first does (10%-20%), and not a model's size after its version.
struct NumberRange {
    std::vector<WrittenNumber> numbers;
    std::vector<std::string> signs;
    bool first_is_percent = false;  // 10%-20%: each end says its 百分之
    std::string first_magnitude;    // the first end's 万 or 亿 (3万-5万元 三万到五万元), or ""
};

NumberRange read_range(const std::vector<CodePoint>& text, std::size_t start, const WrittenNumber& number,
                       const std::string& sign_words) {
    NumberRange range{{number}, {sign_words}, false, ""};
    auto after_first = number.end;
    range.first_is_percent = value_at(text, after_first) == '%';
    if (range.first_is_percent) ++after_first;  // 10%-20%
    // The first end's 万 or 亿 before the range mark is said with it: 3万-5万元 三万到五万元.
    if (is_one_of(value_at(text, after_first), U"万萬亿億") && is_range_mark(value_at(text, after_first + 1)) &&
        is_digit_at(text, after_first + 2)) {
        range.first_magnitude = is_one_of(value_at(text, after_first), U"万萬") ? "万" : "亿";
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
            // A model's size in billions after its version glued or hyphened to its name (Qwen2.5-72B 二点五
            // 七十二B, Llama-3-8B 三 八B; session 27: 二点五到七十二B) is no range's end.
            const bool after_name =
                start > 0 &&
                (is_ascii_letter(value_at(text, start - 1)) ||
                 (start > 1 && is_dash(text[start - 1].value) && is_ascii_letter(value_at(text, start - 2))));
            const bool is_size_after_version = after_name && is_dash(value_at(text, after_first)) &&
                                               second_sign.empty() && value_at(text, second.end) == 'B' &&
                                               !is_ascii_letter(value_at(text, second.end + 1));
            // A memory's speed after its generation (DDR5-6400 DDR 五六千四百, DDR4-3200; session 31:
            // 五到六千四百) is a figure of its own, the dash unsaid as in a model's name (F-35).
            auto letters = start;
            while (letters > 0 && is_ascii_letter(value_at(text, letters - 1))) --letters;
            const bool is_speed_after_generation =
                is_dash(value_at(text, after_first)) && ends_with(text_between(text, letters, start), "DDR");
            if ((!range.first_is_percent || value_at(text, second.end) == '%') && !is_size_after_version &&
                !is_speed_after_generation) {
                range.numbers.push_back(std::move(second));
                range.signs.push_back(std::move(second_sign));
            }
        }
    }
    return range;
}

// The signs of a number or a range's ends (`signs`, each 正, 负 or "" as written) said as the text around
// them says: a temperature's 零下 and 零上, a quantity's 加, a change's after a comparison or an amount
// (增长, 下降), a percentage's rise and fall (涨, 跌). `unit_end` is where its unit ends.
void word_signs(const std::vector<CodePoint>& text, std::size_t start, std::size_t unit_end,
                bool is_temperature, bool is_percent, bool is_per_mille, std::vector<std::string>& signs) {
    for (auto& sign : signs) {
        if (sign == "负" && is_temperature) sign = "零下";
        if (sign == "正" && is_temperature) sign = "零上";
    }
    if (signs.front() == "正" && !is_percent && !is_per_mille && adds_to_quantity(text, start))
        signs.front() = "加";
    if (signs.size() == 1 && (signs.front() == "正" || signs.front() == "负" || signs.front().empty())) {
        const bool rise = value_at(text, start) == '+';
        if (rise || is_dash(value_at(text, start))) {
            auto change = change_after_comparison(text, start, unit_end, rise);
            if (change.empty() && is_percent) change = change_of_amount(text, start, rise);
            if (!change.empty()) signs.front() = std::move(change);
        }
    }
    // A + before a percentage is a rise, said 涨 as market reports read it (腾讯+2.35% 腾讯涨百分之
    // 二点三五); not said where the clause already names the change (涨幅+2.35%, 同比增长+5%) or
    // after the first end of a range. A - stays 负 (增速-6.8% 增速负百分之六点八: 负增长).
    // After 涨跌幅, which names both ways, the sign says which: 涨跌幅+2.35% 正百分之二点三五.
    if (is_percent || is_per_mille) {
        const bool names_both_ways = ends_with_any(text_before(text, start, true), kBothWaysWords);
        for (std::size_t k = 0; k < signs.size(); ++k)
            if (signs[k] == "正" && !names_both_ways)
                signs[k] = k == 0 && !names_change(text, start) ? "涨" : "";
        if (signs.front() == "负" && is_fall_of_what_moves(text, start)) signs.front() = "跌";
    }
}

// Whether a number ending at text[end] with `unit` after it (or none) and `currency` before it (or none)
// is a price, whose trailing zeros are written, not said: ¥1,299.00 一千二百九十九元, $3.50 三点五美元, and
// where a currency's word follows (报15.60元 十五点六元; session 17: 十五点六零元).
bool names_price(const std::vector<CodePoint>& text, std::size_t end, const Unit* unit,
                 const Currency* currency) {
    if (currency != nullptr) return true;
    if (unit != nullptr) return false;
    return starts_with_any(text_between(text, end, end + 2), {"元", "圆", "圓", "块", "塊", "美元", "港元",
                                                              "欧元", "歐元", "日元", "英镑", "英鎊"});
}

// A count shown as "or more" at text[end], 99+ (a chat's unread messages, 18+ of an age rating), said 加 as
// it is read out (session 16: the + was skipped with a warning), and so after the count's 万 or 亿
// (已售10万+件 十万加件; session 18: the + was skipped): its words, `end` moved past it. Not before a term
// (1+1 is a sum):
// "" there and where no + follows.
std::string count_over_words(const std::vector<CodePoint>& text, std::size_t& end) {
    const bool plus_after_magnitude =
        is_one_of(value_at(text, end), U"万萬亿億") && value_at(text, end + 1) == '+';
    const auto plus = plus_after_magnitude ? end + 1 : end;
    const auto after_plus = value_at(text, plus + 1);
    if (value_at(text, plus) != '+' || is_digit_at(text, plus + 1) || is_ascii_letter(after_plus) ||
        is_one_of(after_plus, U" +(（"))
        return "";
    std::string words = plus_after_magnitude ? std::string(text[end].text) + "加" : "加";
    end = plus + 1;
    return words;
}

// The words of a range's numbers (one, or two joined by 到), each with its sign, a currency's word before
// it, a percentage's 百分之 or a per mille's 千分之 and a year's 年; `end` moved past the 年 that ends the
// range.
void say_range(const NumberRange& range, const NumberContext& context, const Currency* currency,
               bool is_percent, bool is_per_mille, SpokenForm& form, std::size_t& end) {
    for (std::size_t k = 0; k < range.numbers.size(); ++k) {
        const auto said = say_number(range.numbers[k], context);
        if (k > 0) form.words += "到";
        form.words += range.signs[k];
        if (currency != nullptr) form.words += currency->before;
        // The sign written on each end is said on each (10%-20% 百分之十到百分之二十), once where only the
        // last carries it (3-5% 百分之三到五, as newsreaders say it; session 20: 百分之三到百分之五).
        if (is_percent && (k == 0 || range.first_is_percent)) form.words += "百分之";
        if (is_per_mille && k == 0) form.words += "千分之";
        // 100% is 百分之百, as it is said (百分之百的把握), not 百分之一百.
        const auto& whole = range.numbers[k].whole;
        form.words += is_percent && whole == "100" && !range.numbers[k].has_point ? "百" : said.words;
        if (k == 0 && range.numbers.size() > 1) form.words += range.first_magnitude;
        if (said.is_year) {
            form.words += "年";
            // The 年 of a year belongs to the form; after a range, only the last takes it.
            if (k + 1 < range.numbers.size())
                form.words.erase(form.words.size() - std::string_view("年").size());
        }
        append_warning(form, said.warning);
        form.is_dialled = form.is_dialled || said.is_dialled;
        if (said.is_year && k + 1 == range.numbers.size()) end += 1;
    }
}

// What closes a quantity, `end` moved past it: a strength's ratio after its unit, a currency's magnitude
// and name after the number, or the + of a count "or more" where neither a unit nor a currency follows.
void append_closing_words(const std::vector<CodePoint>& text, const Unit* unit, const Currency* currency,
                          SpokenForm& form, std::size_t& end) {
    // A colon after a quantity and before a number is a strength's ratio (注射液2ml:0.1g 两毫升比零点一克;
    // session 18: the colon was a pause and its 比 lost); the number after it is read as its own form.
    if (unit != nullptr && unit->written != "%" && value_at(text, end) == ':' && is_digit_at(text, end + 1)) {
        form.words += "比";
        ++end;
    }
    if (currency != nullptr) {
        // $5万 is 五万美元: the magnitude comes before the currency's name.
        if (is_one_of(value_at(text, end), U"万萬亿億千")) {
            form.words += text[end].text;
            ++end;
        }
        form.words += currency->after;
    }
    if (currency == nullptr && unit == nullptr) form.words += count_over_words(text, end);
}

// One number, or a range of two (3-5, 3~5), said with what follows the last of them: its power, its
// magnitude, its unit or its currency's word, the + of a count "or more"; its signs said as a temperature's,
// a change's or a rise's where the text says so.
SpokenForm read_quantity(const std::vector<CodePoint>& text, std::size_t start, const WrittenNumber& number,
                         const std::string& sign_words, const Currency* currency, NumberContext context) {
    SpokenForm form;
    NumberRange range = read_range(text, start, number, sign_words);
    std::vector<WrittenNumber>& numbers = range.numbers;
    std::vector<std::string>& signs = range.signs;
    auto end = numbers.back().end;
    if (context.is_code && numbers.size() == 1) end = past_exchange_suffix(text, end);
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
    const auto chat_letter =
        numbers.size() == 1 && unit == nullptr && currency == nullptr && power_words.empty()
            ? chat_magnitude(text, end)
            : std::string_view{};
    context.next = begins_rise(text, numbers.back().end) ? 0
                   : chat_letter.empty()                 ? value_at(text, numbers.back().end)
                   : chat_letter == "万"                 ? U'万'
                   : chat_letter == "公里"               ? U'公'
                                                         : U'千';
    context.is_count_over = chat_letter.empty() && context.next == '+' &&
                            !is_digit_at(text, numbers.back().end + 1) &&
                            !is_ascii_letter(value_at(text, numbers.back().end + 1));
    // A Latin unit after the number's 万 or 亿 (1.6万km² 一点六万平方公里) is said after it.
    std::string magnitude_words;
    if (unit == nullptr && currency == nullptr && is_one_of(context.next, U"万萬亿億")) {
        const Unit* after_magnitude = unit_at(text, end + 1, unit_end);
        if (after_magnitude != nullptr && after_magnitude->written != "%") {
            unit = after_magnitude;
            magnitude_words = is_one_of(context.next, U"万萬") ? "万" : "亿";
        }
    }
    if (!chat_letter.empty()) {
        magnitude_words = chat_letter;
        ++end;
    }
    context.has_unit = power_words.empty() && ((unit != nullptr && unit->written != "%") || is_byte_unit_at(text, end));
    context.measures_degrees = unit == nullptr && power_words.empty() && measures_degrees(text, start, end);
    std::string unit_words = unit == nullptr ? "" : unit->words;
    const bool is_percent = unit != nullptr && unit->written == "%";
    const bool is_per_mille = end < text.size() && text[end].value == 0x2030 /*‰*/;
    // A temperature's sign is said 零下 or 零上 (-3℃ 零下三摄氏度, +5℃ 零上五摄氏度), before 度 too where the
    // sentence speaks of a temperature (气温降至-2.5度 零下二点五度; session 15: it was 负).
    const bool is_temperature =
        is_temperature_reading(text, start, unit, context.next) ||
        (unit == nullptr && numbers.size() == 1 && range_word_before_temperature(text, start, end));
    word_signs(text, start, unit_end, is_temperature, is_percent, is_per_mille, signs);
    // A price's trailing zeros are written, not said (¥1,299.00 一千二百九十九元).
    const bool is_price = names_price(text, end, unit, currency);
    for (auto& price : numbers) {
        if (!is_price || !price.has_point) continue;
        price.fraction.erase(price.fraction.find_last_not_of('0') + 1);
        price.has_point = !price.fraction.empty();
    }

    say_range(range, context, currency, is_percent, is_per_mille, form, end);
    if (unit != nullptr) end = unit_end;
    // A unit per another (7.0mmol/L 七点零毫摩尔每升, 35μg/m³ 三十五微克每立方米, 80mg/100ml 八十毫克每
    // 一百毫升): 每 and the second unit, with its number where it has one (km/h and m/s are units of
    // their own above).
    if (unit != nullptr && unit->written != "%") unit_words += per_unit_words(text, end);
    if (is_per_mille) end += 1;
    form.words += power_words + magnitude_words + unit_words;
    append_closing_words(text, unit, currency, form, end);
    form.end = end;
    return form;
}

// The dot and the digit of a storage slot's form factor after its capital, M.2 and U.2 (M.2 M 点二, as spec
// sheets are read; session 31: the dot ended the sentence and went unsaid): M or U standing alone, a dot and
// one digit that no further dot follows. Another capital there is a choice's or an initial's
// (答案是A.2后来改了), and more dots a lineage's name (B.1.1.7); nullopt there.
std::optional<SpokenForm> read_form_factor_digit(const std::vector<CodePoint>& text, std::size_t start) {
    if (value_at(text, start) != '.' || start == 0 || !is_one_of(text[start - 1].value, U"MU") ||
        (start >= 2 && (is_ascii_letter(text[start - 2].value) || is_digit_at(text, start - 2))) ||
        !is_digit_at(text, start + 1))
        return std::nullopt;
    const auto digit = parse_number(text, start + 1);
    if (digit.whole.size() != 1 || digit.has_point || digit.has_separators ||
        value_at(text, digit.end) == '.' || is_ascii_letter(value_at(text, digit.end)))
        return std::nullopt;
    SpokenForm form;
    form.words = "点" + cardinal_words(digit.whole, false);
    form.end = digit.end;
    return form;
}

}  // namespace

std::optional<SpokenForm> read_number_form(const std::vector<CodePoint>& text, std::size_t start) {
    if ((is_range_mark(value_at(text, start)) && is_digit_at(text, start + 1) &&
         follows_date_or_time(text, start)) ||
        joins_quantities(text, start)) {
        auto second = read_number_form(text, start + 1);
        if (second) second->words = "到" + second->words;
        return second;
    }
    if (auto code = read_calling_code(text, start)) return code;
    if (auto form_factor = read_form_factor_digit(text, start)) return form_factor;
    auto sign = read_leading_sign(text, start);
    if (!sign) return std::nullopt;
    const Currency* currency = sign->currency;
    std::string& sign_words = sign->words;
    const auto i = sign->digits;
    const auto number = parse_number(text, i);
    // A chat's +1 as a clause of its own (+1，我也觉得), "me too", is 加一 (session 14; it was 正一).
    if (sign_words == "正" && number.whole == "1" && !number.has_point &&
        (stands_alone(text, start, number.end) || agrees_after_person(text, start, number.end)))
        sign_words = "加";
    const NumberContext context = context_of_number(text, start, i, number, sign_words, currency);
    if (sign_words.empty() && currency == nullptr && !context.is_ordinal) {
        // The 、 goes with the low end: the two are run together, with no pause between.
        if (auto low_end = approximate_low_end(text, start, number)) {
            SpokenForm form;
            form.words = *low_end;
            form.end = number.end + 1;
            return form;
        }
    }
    if (auto e_notation = read_e_notation(text, start, number, sign_words)) return e_notation;
    const bool is_bare = sign_words.empty() && currency == nullptr;
    if (is_bare)
        if (auto standard = read_standard_code(text, start, number)) return standard;
    if (is_bare)
        if (auto pair = read_colon_pair(text, start, number, context)) return pair;
    if (currency == nullptr)
        if (auto product = read_product(text, number)) return product;
    if (is_bare)
        if (auto form = read_unsigned_form(text, start, i, number, context)) return form;
    if (auto pair = read_slashed_pair(text, start, number, sign_words, currency)) return pair;
    return read_quantity(text, start, number, sign_words, currency, context);
}

}  // namespace talkface::detail

#include "text/units_and_money.hpp"

#include <string>

#include "text/digit_codes.hpp"
#include "text/quantities_and_ranges.hpp"
#include "text/script_variant.hpp"
#include "text/written_number_scan.hpp"

namespace talkface::detail {

namespace {

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
    // Session 18: a blood pressure's unit, as a doctor reads it (140/90mmHg 毫米汞柱), and a game's or a
    // screen's frame rate (60fps 六十帧每秒; it was spelled, F P S). Session 30: a battery's energy in
    // watt-hours (160Wh/kg 一百六十瓦时每公斤), beside kWh and MWh.
    {"mmHg", "毫米汞柱"}, {"fps", "帧每秒"}, {"Wh", "瓦时"},
    // Session 31: a lab report's levels by their names, as a doctor reads them: the nanogram and the small
    // amounts a vitamin or a hormone is measured in (18ng/mL 十八纳克每毫升, 86μmol/L 微摩尔每升; they were
    // spelled, en ji ai mu ai le), the micromole's μ as the Greek mu or the micro sign, and an enzyme's
    // activity in units (ALT 68U/L 六十八单位每升; is_lone_capital_unit_at).
    {"ng", "纳克"}, {"pg", "皮克"}, {"nmol", "纳摩尔"}, {"μmol", "微摩尔"}, {"µmol", "微摩尔"},
    {"pmol", "皮摩尔"}, {"U", "单位"},
    // Session 32: a torque's newton-metres (700N·m 七百牛米, 700Nm; N·m left its m a letter), a screen's
    // brightness in nits (3000nits 三千尼特; the dictionary's word gave de), and a temperature's kelvin (100万K
    // 一百万开尔文, is_kelvin_at).
    {"N·m", "牛米"}, {"N⋅m", "牛米"}, {"Nm", "牛米"}, {"nits", "尼特"}, {"nit", "尼特"},
    // A length's unit in characters squared or cubed by its sign (3.5厘米² 三点五平方厘米, as cm² is said; the
    // sign after the word was skipped with a warning): the power is said before the unit it raises. 釐米 is
    // Hong Kong's Traditional spelling of 厘米 (3.5釐米²; session 43: the sign skipped).
    {"米²", "平方米"}, {"厘米²", "平方厘米"}, {"毫米²", "平方毫米"}, {"分米²", "平方分米"},
    {"千米²", "平方千米"}, {"公里²", "平方公里"}, {"米³", "立方米"}, {"厘米³", "立方厘米"},
    {"毫米³", "立方毫米"}, {"分米³", "立方分米"}, {"釐米²", "平方釐米"}, {"釐米³", "立方釐米"},
    // Session 33: a capacitor's microfarads, nanofarads and picofarads as a physics lesson names them (47μF
    // 四十七微法; μF was μ unsaid and the letter F), and bits per second written small without a prefix
    // (20bps 二十比特每秒, as kbps is 千比特每秒) where they are no rate's basis points (is_basis_points_at).
    {"μF", "微法"}, {"µF", "微法"}, {"nF", "纳法"}, {"pF", "皮法"}, {"bps", "比特每秒"},
    // Session 37: a square or a cube typed with a plain digit where the keyboard has no superscript, as
    // listings and air-quality posts write them (120m2 一百二十平方米, 115μg/m3 每立方米; the letter was
    // read as the interjection m2, 呣). Only small letters: M2 is money supply's name (M2余额 M 二).
    {"m2", "平方米"}, {"km2", "平方公里"}, {"cm2", "平方厘米"}, {"mm2", "平方毫米"}, {"m3", "立方米"},
    {"cm3", "立方厘米"},
};

// The kilogram in a physics unit per another, by the name textbooks give the SI units (GB 3102): per a
// kilogram after a force's or an energy's unit (9.8N/kg 九点八牛每千克, J/kg) and per a volume after it (a
// density, 1.0×10³kg/m³ 千克每立方米). Elsewhere kg is 公斤, as everyday speech and a doctor's dose per body
// weight say it (0.5mg/kg 毫克每公斤; session 33 kept them).
constexpr Unit kSiKilogram = {"kg", "千克"};

bool is_si_kilogram_at(const std::vector<CodePoint>& text, std::size_t start, std::size_t end) {
    const bool per_kilogram = start >= 2 && value_at(text, start - 1) == '/' &&
                              is_one_of(value_at(text, start - 2), U"NJ") &&
                              (start < 3 || !is_ascii_letter(value_at(text, start - 3)));
    const auto after = text_between(text, end, end + 4);
    const bool per_volume = starts_with_any(after, {"/m³", "/cm³", "/dm³", "/m3", "/L"});
    // A body's mass as a physics problem gives it (质量为0.5kg的水 零点五千克; session 39: 公斤), in
    // Simplified text: Taiwan's lessons say 公斤 (質量為 stays so).
    auto number = start;
    while (number > 0 && (is_digit_at(text, number - 1) || is_one_of(value_at(text, number - 1), U". ")))
        --number;
    const bool mass = contains_any(text_before(text, number, true), {"质量"});
    return per_kilogram || per_volume || mass;
}

// Taiwan's names of the metre and the centimetre, which its schools, news and shops say for m and cm
// (身高152cm 一百五十二公分, 100m 一百公尺), and of their squares and cubes, in Traditional text (session 40:
// 厘米 and 米, the mainland's). Hong Kong says 厘米 and 米 as the mainland does; the script cannot tell the
// two, so Traditional text reads as Taiwan's, the larger of them, unless it writes Cantonese
// (writes_cantonese); Hong Kong's formal text is fixed in place (152cm{一百五十二厘米}).
constexpr Unit kTaiwanUnits[] = {
    {"cm", "公分"},     {"m", "公尺"},       {"cm²", "平方公分"}, {"m²", "平方公尺"},
    {"㎡", "平方公尺"}, {"cm³", "立方公分"}, {"m³", "立方公尺"},  {"cm2", "平方公分"},
    {"m2", "平方公尺"}, {"cm3", "立方公分"}, {"m3", "立方公尺"},  {"m/s", "公尺每秒"},
};

const Unit* taiwan_unit(const Unit& unit) {
    for (const auto& taiwan : kTaiwanUnits)
        if (taiwan.written == unit.written) return &taiwan;
    return nullptr;
}

// Hours written with a capital H after a count of two or three digits, as shops and services write how
// long they open or ship (24H营业 二十四小时营业, 48H发货, 7×24H客服; session 39: letters, ai qi): one digit
// before H is a pencil's grade (2H铅笔), and H before a digit a half year's (2024H1).
constexpr Unit kCapitalHours = {"H", "小时"};

bool is_capital_hours_at(const std::vector<CodePoint>& text, std::size_t i) {
    if (value_at(text, i) != 'H' || is_ascii_letter(value_at(text, i + 1)) || is_digit_at(text, i + 1))
        return false;
    std::size_t digits = 0;
    while (digits < i && is_digit_at(text, i - digits - 1)) ++digits;
    constexpr std::size_t kFewestDigits = 2;
    constexpr std::size_t kMostDigits = 3;
    const auto before = digits < i ? value_at(text, i - digits - 1) : U' ';
    return digits >= kFewestDigits && digits <= kMostDigits && before != '.' && !is_ascii_letter(before);
}

// A kelvin's K after a number where its clause names a temperature, 温度 (日冕的温度可达100万K): elsewhere a
// capital K is a picture's (高温下看4K电视), a runner's (5K) or a model's letter, and a lamp's 色温6500K is left
// as its makers say it, K.
constexpr Unit kKelvin = {"K", "开尔文"};

bool is_kelvin_at(const std::vector<CodePoint>& text, std::size_t i) {
    if (value_at(text, i) != 'K' || is_ascii_letter(value_at(text, i + 1)) || is_digit_at(text, i + 1))
        return false;
    const std::string clause = text_before(text, i, true) + text_after(text, i);
    return contains_any(clause, {"温度", "溫度"});
}

// A unit of one capital (J N A) that a grade or a name also writes after a number: a unit only
// before 的 or anything but a Chinese character (0.5A。, 20N的力; not 5A景区), and where no seat is named
// before it (座位是32A); U, below, only before a slash.
bool is_lone_capital_unit_at(const std::vector<CodePoint>& text, const Unit& unit, std::size_t end) {
    // An enzyme's U only before the slash of a unit per another (68U/L, 5U/mL): a capital U after a number
    // elsewhere is a chip's suffix or a rack's height (7840U, 2U服务器).
    if (unit.written == "U") return value_at(text, end) == '/' && is_ascii_letter(value_at(text, end + 1));
    if (unit.written != "J" && unit.written != "N" && unit.written != "A") return true;
    const auto next = value_at(text, end);
    return (next == U'的' || next < 0x3400 || next > 0x9FFF) && !names_seat_before(text, end);
}

// A lamp's or a charger's watts written small (功率5w, 65w快充), as posts write them: the watt where the
// sentence speaks of power (功率 充电 快充 闪充 超充 瓦 输出) or the clause names a lamp (5w的台灯, 灯泡才3w,
// 吸顶灯, LED灯; session 21: 五万; not a lantern show's 灯会 灯光), and a chat's 万 elsewhere (存够5w,
// 粉丝破5w) and before a measure word, which counts what the 万 counts (吸引了5w人, 卖出5w台).
constexpr Unit kSmallWatt = {"w", "瓦"};

bool is_small_watt_at(const std::vector<CodePoint>& text, std::size_t i) {
    if (value_at(text, i) != 'w' || !is_digit_at(text, i - 1) || is_ascii_letter(value_at(text, i + 1)) ||
        is_digit_at(text, i + 1) || takes_liang(value_at(text, i + 1))) {
        return false;
    }
    const std::string clause = text_before(text, i, true) + text_after(text, i);
    if (contains_any(clause, {"台灯", "檯燈", "枱燈", "灯泡", "燈泡", "灯管", "燈管", "灯具",
                              "燈具", "灯珠", "燈珠", "顶灯", "頂燈", "路灯", "路燈", "夜灯",
                              "夜燈", "射灯", "射燈", "筒灯", "筒燈", "D灯",  "D燈"}))
        return true;
    const std::string sentence = text_before(text, i, false) + text_after(text, i, false);
    return contains_any(sentence,
                        {"功率", "充电", "充電", "快充", "闪充", "閃充", "超充", "瓦", "输出", "輸出"});
}

constexpr Currency kCurrencies[] = {
    {U"NT$", "新台币", "元"}, {U"US$", "", "美元"}, {U"HK$", "", "港元"}, {U"S$", "", "新加坡元"},
    {U"$", "", "美元"},      {U"¥", "", "元"},     {U"￥", "", "元"},     {U"€", "", "欧元"},
    {U"£", "", "英镑"},
};

// A bare $ in Traditional text is the local dollar, as Taiwan's and Hong Kong's shops, menus and fares write
// it (大杯$45 大杯四十五元, 車費$10.5; session 32: 美元); the US dollar there is US$ or 美元, and in
// Simplified text, where the yuan is ¥, $ stays the US dollar.
constexpr Currency kLocalDollar = {U"$", "", "元"};

bool is_han_at(const std::vector<CodePoint>& text, std::size_t k) {
    return k < text.size() && text[k].value >= 0x3400 && text[k].value <= 0x9FFF;
}

// Whether text[i] follows a number and one to three Chinese characters of its unit (25元/, 3次/, 72.31美元/).
bool follows_number_and_han_unit(const std::vector<CodePoint>& text, std::size_t i) {
    // A power's superscript ends the number too (3×10⁸米/秒 米每秒; session 27: 米秒).
    const auto ends_number = [&](std::size_t k) {
        return is_digit_at(text, k) ||
               is_one_of(value_at(text, k), U"\u2070\u00B9\u00B2\u00B3\u2074\u2075\u2076\u2077\u2078\u2079");
    };
    constexpr std::size_t kLongestUnit = 3;  // characters: 元, 美元, 平方米
    for (std::size_t k = 1; k <= kLongestUnit && k <= i; ++k) {
        if (!is_han_at(text, i - k)) return ends_number(i - k);
    }
    return i > kLongestUnit && ends_number(i - kLongestUnit - 1);
}

}  // namespace

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
        // between two numbers one (5V5 五 V 五, a match of five against five). A unit ending in its power's
        // digit ends the digits too (120m23 is no square metre).
        const auto last = static_cast<char32_t>(unit.written.back());
        if ((is_ascii_letter(last) || is_ascii_digit(last)) &&
            (is_ascii_letter(value_at(text, k)) || is_digit_at(text, k))) {
            continue;
        }
        if (!is_lone_capital_unit_at(text, unit, k)) continue;
        // A capital before 系列 is a series' letter, not a unit (Core Ultra 200V系列 二百 V; session 30: 伏).
        if (is_ascii_capital(static_cast<char32_t>(unit.written.back())) &&
            text_between(text, k, k + 2) == "系列")
            continue;
        if (best == nullptr || unit.written.size() > best->written.size()) {
            best = &unit;
            end = k;
        }
    }
    if (best != nullptr && best->written == "kg" && is_si_kilogram_at(text, start, end)) best = &kSiKilogram;
    if (best != nullptr && taiwan_unit(*best) != nullptr && is_traditional_text(text) &&
        !writes_cantonese(text))
        best = taiwan_unit(*best);
    if (best != nullptr && best->written == "bps" && is_basis_points_at(text, start)) best = nullptr;
    if (best == nullptr && start == i && i > 0 && is_small_watt_at(text, i)) {
        best = &kSmallWatt;
        end = i + 1;
    }
    if (best == nullptr && start == i && is_capital_hours_at(text, i)) {
        best = &kCapitalHours;
        end = i + 1;
    }
    if (best == nullptr && is_kelvin_at(text, start)) {
        best = &kKelvin;
        end = start + 1;
    }
    return best;
}

bool is_basis_points_at(const std::vector<CodePoint>& text, std::size_t i) {
    if (value_at(text, i) != 'b' || value_at(text, i + 1) != 'p') return false;
    if (!is_ascii_letter(value_at(text, i + 2))) return true;
    // bps is a rate's basis points where the sentence speaks of a rate or a bond (降息25bps,
    // 收益率下行20bps), and bits per second elsewhere (session 33: the letters B P S either way).
    if (value_at(text, i + 2) != 's' || is_ascii_letter(value_at(text, i + 3))) return false;
    const std::string sentence = text_before(text, i, false) + text_after(text, i, false);
    return contains_any(sentence, {"利率", "利差", "息差", "收益率", "基点", "基點", "降息", "加息", "LPR",
                                   "国债", "國債", "债券", "債券", "贷款", "貸款", "存款", "降准", "降準"});
}

std::optional<SpokenForm> read_named_unit(const std::vector<CodePoint>& text, std::size_t i) {
    if (!is_ascii_letter(value_at(text, i)) || (i > 0 && is_ascii_letter(value_at(text, i - 1))) ||
        !ends_with_any(text_before(text, i, true),
                       {"单位是", "單位是", "单位为", "單位為", "单位：", "單位：", "单位:", "單位:"}))
        return std::nullopt;
    std::size_t end = i;
    const Unit* unit = unit_at(text, i, end);
    if (unit == nullptr || end == i) return std::nullopt;
    SpokenForm form;
    form.words = unit->words + per_unit_words(text, end);
    form.end = end;
    return form;
}

bool is_byte_unit_at(const std::vector<CodePoint>& text, std::size_t i) {
    if (value_at(text, i) == ' ') ++i;
    if (!is_one_of(value_at(text, i), U"KMGTP")) return false;
    if (value_at(text, i + 1) == 'B') return !is_ascii_letter(value_at(text, i + 2));
    // The B left out, as chat and shops write a phone's data and memory (2G流量 两G, 4G内存; session 27:
    // 二G, a network's generation, which 2G网络 stays): the capital alone before a word of stored data.
    return starts_with_any(text_between(text, i + 1, i + 3),
                           {"流量", "內存", "内存", "运存", "運存", "显存", "顯存", "存储", "存儲", "硬盘",
                            "硬碟", "网盘", "網盤", "云盘", "雲盤", "空间", "空間"});
}

const Currency* currency_at(const std::vector<CodePoint>& text, std::size_t i, std::size_t& end) {
    for (const auto& currency : kCurrencies) {
        std::size_t k = 0;
        while (k < currency.written.size() && i + k < text.size() && text[i + k].value == currency.written[k]) ++k;
        if (k == currency.written.size() && is_digit_at(text, i + k)) {
            end = i + k;
            return currency.written == kLocalDollar.written && is_traditional_text(text) ? &kLocalDollar
                                                                                         : &currency;
        }
    }
    return nullptr;
}

std::optional<SpokenForm> read_per_unit(const std::vector<CodePoint>& text, std::size_t i) {
    if (value_at(text, i) != '/' || i < 2 || value_at(text, i + 1) == ' ') return std::nullopt;
    const bool after_byte_unit =
        i >= 3 && value_at(text, i - 1) == 'B' && is_one_of(value_at(text, i - 2), U"KMGTP") &&
        (is_digit_at(text, i - 3) || (value_at(text, i - 3) == ' ' && is_digit_at(text, i - 4)));
    // A price per a unit written in Latin letters (0.7元/W 零点七元每瓦, 1.2元/kWh), as per a Chinese one
    // (25元/公斤, slash_reads_per); a unit symbol before the slash is per_unit_words' (160Wh/kg).
    if (!after_byte_unit && !follows_number_and_han_unit(text, i)) return std::nullopt;
    std::size_t end = i + 1;
    const Unit* per = unit_at(text, i + 1, end);
    if (per == nullptr || per->written == "%") return std::nullopt;
    SpokenForm form;
    form.words = std::string("每") + per->words;
    form.end = end;
    return form;
}

bool slash_reads_per(const std::vector<CodePoint>& text, std::size_t i) {
    return value_at(text, i) == '/' && is_han_at(text, i + 1) && follows_number_and_han_unit(text, i) &&
           !names_top_schools(text, i + 1);
}

bool slash_pairs_currencies(const std::vector<CodePoint>& text, std::size_t i) {
    constexpr std::string_view kCurrencyNames[] = {
        "美元",   "欧元",   "歐元", "日元", "日圆", "日圓", "英镑",     "英鎊",   "人民币", "人民幣", "港元",
        "港币",   "港幣",   "澳元", "加元", "纽元", "紐元", "瑞郎",     "卢布",   "盧布",   "韩元",   "韓元",
        "新台币", "新台幣", "台币", "台幣", "卢比", "盧比", "新加坡元", "比特币", "比特幣", "USD",    "CNY",
        "CNH",    "EUR",    "JPY",  "GBP",  "HKD",  "AUD",  "CAD",      "CHF",    "NZD",    "TWD",    "KRW"};
    constexpr std::size_t kShortestName = 2;
    constexpr std::size_t kLongestName = 4;  // characters: 新加坡元
    // A currency's name of `length` characters from text[first]: a code whole, no letter beside it (USDT).
    const auto names_currency = [&](std::size_t first, std::size_t length) {
        return first + length <= text.size() &&
               is_any_of(text_between(text, first, first + length), kCurrencyNames) &&
               !(first > 0 && is_ascii_letter(text[first - 1].value)) &&
               !is_ascii_letter(value_at(text, first + length));
    };
    if (value_at(text, i) != '/') return false;
    bool before = false;
    bool after = false;
    for (auto length = kShortestName; length <= kLongestName; ++length) {
        // After a number the name is a price's unit (25元/公斤 is slash_reads_per's), no pair.
        before = before || (length <= i && names_currency(i - length, length) &&
                            !(i > length && is_digit_at(text, i - length - 1)));
        after = after || names_currency(i + 1, length);
    }
    return before && after;
}

bool slash_joins_sizes(const std::vector<CodePoint>& text, std::size_t i) {
    if (value_at(text, i) != '/' || i < 2 || value_at(text, i - 1) != 'B' || !is_digit_at(text, i - 2))
        return false;
    auto k = i + 1;
    while (is_digit_at(text, k) || (value_at(text, k) == '.' && is_digit_at(text, k + 1))) ++k;
    // In a list of three or more (1.5B/7B/32B) only the last slash is 和, as a list is read: the others
    // are a list's pause, unsaid.
    return k > i + 1 && value_at(text, k) == 'B' && !is_ascii_letter(value_at(text, k + 1)) &&
           !(value_at(text, k + 1) == '/' && is_digit_at(text, k + 2));
}

}  // namespace talkface::detail

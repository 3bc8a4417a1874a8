#include "text/number_signs.hpp"

#include <string_view>
#include <utility>

#include "text/digit_codes.hpp"
#include "text/formula_letters.hpp"
#include "text/script_marks.hpp"
#include "text/written_number_scan.hpp"

namespace talkface::detail {

namespace {

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
          // An item's upgrade level (装备强化+12 加十二; session 20: 正十二), and the item's own (装备+15).
          "强化", "強化", "精炼", "精煉", "装备", "裝備",
          // A skill's cooldown, which a buff cuts (冷却-20% 减百分之二十; session 34: 跌, a market's fall).
          "冷却", "冷卻"})
        if (ends_with(before, stat)) return true;
    return false;
}

// A reward a game or an app gives for an action (签到+20金币, 击杀+1, 邀请好友+50钻石, 每日登入+10鑽): the +
// is 加, as players read it (session 33: 正, a value's sign). The action ends the words before the sign, or
// the reward is named after the count (金币, 钻石, 经验, 积分, and points, 分: 答对一题+5分, 进球+1分;
// session 34: 正), what is won and not a value that rises.
bool rewards_action(const std::vector<CodePoint>& text, std::size_t start) {
    constexpr std::string_view kActions[] = {"签到", "簽到", "登录", "登錄", "登入", "击杀", "擊殺",
                                             "助攻", "推塔", "拿龙", "拿龍", "升级", "升級", "通关",
                                             "通關", "任务", "任務", "分享", "点赞", "點讚"};
    constexpr std::string_view kRewards[] = {"金币", "金幣", "钻",   "鑽", "经验",
                                             "經驗", "积分", "積分", "分"};
    if (ends_with_any(text_before(text, start, true), kActions)) return true;
    auto end = start + 1;
    while (is_digit_at(text, end)) ++end;
    return starts_with_any(text_after(text, end), kRewards);
}

// An item's upgrade level told apart from its word (装备全是+15的 加十五, 强化到+12了, 一把+12的武器; session
// 42: 正), where follows_game_attribute sees the level right after the item or the upgrade: a whole count
// after the sign, the item or the upgrade named earlier in the clause, or 的 and the item right after the
// count. A level is no value with a sign, which a lesson (电荷为+1的离子) or a report (价格+15%) writes.
bool names_item_level(const std::vector<CodePoint>& text, std::size_t start) {
    constexpr std::string_view kItemsAndUpgrades[] = {"装备", "裝備", "武器", "防具", "强化", "強化",
                                                      "精炼", "精煉", "神器", "法宝", "法寶"};
    if (start == 0 || value_at(text, start) != '+' || !is_han(text[start - 1].value)) return false;
    auto end = start + 1;
    while (is_digit_at(text, end)) ++end;
    const auto after = value_at(text, end);
    if (after == '.' || after == '%' || is_ascii_letter(after)) return false;
    if (contains_any(text_before(text, start, true), kItemsAndUpgrades)) return true;
    return after == U'的' && starts_with_any(text_after(text, end + 1), kItemsAndUpgrades);
}

// A game's gauges written in capitals (HP+500, MP-20, EXP+100), a whole word: the sign after them adds or
// takes away as after 血量 or 法力 (session 33: MP-20 was read as a model's number, ai mu pi 二十).
bool follows_stat_letters(const std::vector<CodePoint>& text, std::size_t start) {
    auto first = start;
    while (first > 0 && is_ascii_letter(text[first - 1].value)) --first;
    const auto word = text_between(text, first, start);
    return word == "HP" || word == "MP" || word == "EXP";
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

// A + between a word and a number where the clause before it holds a number of its own: it joins two
// quantities, 加, as a spec sheet lists its parts (5000万像素主摄+1200万超广角, 16GB内存+1TB硬盘; session 20:
// 正一千二百). A sign alone in its clause keeps its reading (温差+12 正十二), and a change in percent is a
// rise (Q3净利润同比增长+15.2%: the Q3 is no quantity added to).
bool adds_to_quantity(const std::vector<CodePoint>& text, std::size_t start) {
    if (start == 0 || value_at(text, start) != '+' || !is_han(text[start - 1].value)) return false;
    const std::string before = text_before(text, start, true);
    return before.find_first_of("0123456789") != std::string::npos;
}

}  // namespace

bool agrees_in_chat(const std::vector<CodePoint>& text, std::size_t start, std::size_t end) {
    // Those who answer +1, a +1 opening its clause before 的 (+1的請留言, +1的私我), as a group's organiser
    // counts them (session 41: 正一). A value's +1 follows its word (电荷为+1的离子), and a lesson asks what
    // a signed number's opposite or size is (+1的相反数, +1的绝对值).
    constexpr std::string_view kOfSignedNumber[] = {"相反数", "相反數", "绝对值", "絕對值", "倒数",
                                                    "倒數",   "平方",   "立方",   "值"};
    if (value_at(text, end) == U'的' &&
        (start == 0 || is_one_of(text[start - 1].value, U"，,。.！!？?～~…\n ")) &&
        !starts_with_any(text_after(text, end + 1), kOfSignedNumber))
        return true;
    if (start == 0 || !(end >= text.size() || is_one_of(value_at(text, end), U"，,。.！!？?～~…\n ")))
        return false;
    if (is_one_of(text[start - 1].value, U"我你他她俺咱们們")) return true;
    // The person may open the clause and say what is agreed with before the +1 (楼上说得对+1; session 34:
    // 正一): the sign ends a reply to a post, no value's.
    constexpr std::string_view kPostPeople[] = {"楼上", "樓上", "楼主", "樓主"};
    // So after a word that acknowledges or seconds what was said (收到+1, 同意+1, 附议+1, 顶+1), as a chat
    // group answers a call (session 40: 正一).
    constexpr std::string_view kAgreements[] = {"收到", "同意", "赞同", "贊同",   "附议",
                                                "附議", "支持", "赞成", "贊成",   "顶",
                                                "頂",   "好的", "可以", "没问题", "沒問題"};
    const std::string before = text_before(text, start, true);
    return contains_any(before, kPostPeople) || ends_with_any(before, kAgreements);
}

std::optional<LeadingSign> read_leading_sign(const std::vector<CodePoint>& text, std::size_t start) {
    auto i = start;
    const Currency* currency = currency_at(text, i, i);
    std::string sign_words;
    const auto first = value_at(text, i);
    // After a term (a digit, a letter, a square: x²+2x, a product's arrow: CaCO₃↓+2NaCl) a + or a - joins it
    // to the next, a sign no more.
    const bool after_stat = follows_stat_letters(text, start);
    const bool after_word =
        start > 0 && !after_stat &&
        (is_digit_at(text, start - 1) || is_ascii_letter(value_at(text, start - 1)) ||
         is_one_of(text[start - 1].value, U"\u00B2\u00B3") || marks_reaction_arrow(text, start - 1));
    // A subtitle's dash before a speaker's turn (-12号，周五。) is no sign either (session 25: 负十二), nor
    // is the second half of the Chinese dash, two em dashes (——3年后, a script's time skip; session 31: 负).
    const bool ends_chinese_dash = first == 0x2014 && start > 0 && text[start - 1].value == 0x2014;
    if (currency == nullptr && is_dash(first) && is_digit_at(text, i + 1) &&
        (follows_designation(text, start) || follows_element(text, start) || opens_turn(text, start) ||
         ends_chinese_dash)) {
        ++i;
    } else if (currency == nullptr && is_one_of(first, U"\u00B1\u2191\u2193\u25B2\u25BC") &&
               is_digit_at(text, i + 1)) {
        // ± is 正负, as a tolerance is read (误差±0.5mm); an arrow before a change is the rise or the fall
        // it draws, 涨 and 跌, as market reports read ↑3.2% and ↓1.5% (session 20: skipped with a warning),
        // and so are a ticker's triangles (沪指 3088.53 ▲0.82%, ▼1.20%; session 36: skipped with a warning).
        sign_words = first == 0xB1 ? "正负" : is_one_of(first, U"\u2191\u25B2") ? "涨" : "跌";
        ++i;
    } else if (currency == nullptr && (is_dash(first) || first == '+') && is_digit_at(text, i + 1) &&
               !after_word) {
        sign_words = first == '+' ? "正" : "负";
        // A game's buff and debuff: after an attribute the sign adds or takes away (攻击力+15 加十五,
        // 移速-15% 减百分之十五; session 30: 负, and 跌 before a percentage, a market's fall). A - after a
        // word in 值 stays a value's sign (净值-2%, 差值-3).
        const bool takes_away = is_dash(first) && start > 0 && text[start - 1].value != U'值';
        if ((follows_game_attribute(text, start) || follows_gauge(text, start) || after_stat) &&
            (first == '+' || takes_away))
            sign_words = first == '+' ? "加" : "减";
        else if (first == '+' && (rewards_action(text, start) || names_item_level(text, start)))
            sign_words = "加";
        ++i;
    }
    if (!is_digit_at(text, i)) return std::nullopt;
    return LeadingSign{currency, std::move(sign_words), i};
}

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

}  // namespace talkface::detail

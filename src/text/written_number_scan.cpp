#include "text/written_number_scan.hpp"

#include <algorithm>

namespace talkface::detail {

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

namespace {

// A full-width comma at text[comma] between a group of one to three digits (`first`) and three more
// is a thousands separator where the writing shows one: a first group of one digit (1，200人), a round
// group after it (12，500, 3，000), a further group or a decimal part (1，234，567, 1，299.50), or money
// (¥1，280, 1，299元). Elsewhere it is the comma between two clauses it is written as (他考了68，123人参加
// 六十八，一百二十三人; session 17: 六万八千一百二十三). Fix either in place.
bool full_width_comma_separates(const std::vector<CodePoint>& text, std::size_t first_start, const std::string& first,
                                std::size_t comma) {
    if (first.size() == 1) return true;
    if (value_at(text, comma + 2) == '0' && value_at(text, comma + 3) == '0') return true;
    const auto after = comma + 4;
    const auto next = value_at(text, after);
    if ((next == ',' || next == '.') && is_digit_at(text, after + 1)) return true;
    if (first_start > 0 && is_one_of(value_at(text, first_start - 1), U"$¥￥€£")) return true;
    const auto word = text_between(text, after, after + 2);
    return starts_with_any(
        word, {"元", "圆", "圓", "块", "塊", "美元", "港元", "欧元", "歐元", "日元", "万元", "萬元"});
}

}  // namespace

WrittenNumber parse_number(const std::vector<CodePoint>& text, std::size_t i) {
    WrittenNumber number;
    const auto first_start = i;
    number.whole = digits_from(text, i);
    // Thousands separators: a comma and exactly three digits (1,234,567). The ideographic comma 、
    // stays a pause (1、2、3 is a list), and so does a full-width comma where the writing does not
    // show a separator (above).
    if (number.whole.size() <= 3) {
        while (i + 3 < text.size() + 1 && text[i].value == ',' && is_digit_at(text, i + 1) &&
               is_digit_at(text, i + 2) && is_digit_at(text, i + 3) && !is_digit_at(text, i + 4) &&
               (number.has_separators || text[i].text != "，" ||
                full_width_comma_separates(text, first_start, number.whole, i))) {
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

bool is_month_and_day(const std::string& month, const std::string& day) {
    if (month.empty() || month.size() > 2 || day.empty() || day.size() > 2) return false;
    const int month_value = std::stoi(month);
    const int day_value = std::stoi(day);
    return month_value >= 1 && month_value <= 12 && day_value >= 1 && day_value <= 31;
}

bool contains_any(std::string_view text, const std::string_view* first, const std::string_view* last) {
    return std::any_of(first, last,
                       [text](std::string_view word) { return text.find(word) != std::string_view::npos; });
}

bool starts_with_any(std::string_view text, const std::string_view* first, const std::string_view* last) {
    return std::any_of(first, last, [text](std::string_view word) { return starts_with(text, word); });
}

bool ends_with_any(std::string_view text, const std::string_view* first, const std::string_view* last) {
    return std::any_of(first, last, [text](std::string_view word) { return ends_with(text, word); });
}

bool is_any_of(std::string_view text, const std::string_view* first, const std::string_view* last) {
    return std::find(first, last, text) != last;
}

bool is_one_of(char32_t c, std::u32string_view set) {
    return set.find(c) != std::u32string_view::npos;
}

bool is_han(char32_t c) {
    return (c >= 0x4E00 && c <= 0x9FFF) || (c >= 0x3400 && c <= 0x4DBF);
}

std::size_t last_listed_start(const std::vector<CodePoint>& text, const WrittenNumber& first,
                              std::size_t digits) {
    const auto is_member = [digits](const WrittenNumber& n) {
        return !n.has_point && !n.has_separators && n.whole.size() == digits;
    };
    if (!is_member(first)) return 0;
    auto last = first;
    std::size_t last_start = 0;
    while (value_at(text, last.end) == U'、' && is_digit_at(text, last.end + 1)) {
        last_start = last.end + 1;
        last = parse_number(text, last_start);
        if (!is_member(last)) return 0;
    }
    return last_start;
}

std::string text_between(const std::vector<CodePoint>& text, std::size_t first, std::size_t end) {
    std::string between;
    for (std::size_t i = first; i < std::min(end, text.size()); ++i) between += text[i].text;
    return between;
}

bool takes_liang(char32_t c) {
    return is_one_of(
        c,
        U"个個本位名只隻条條张張件次天年岁歲人种種块塊元倍台臺部辆輛家份杯碗瓶双雙对對层層场場"
        U"周週遍斤米千万萬亿億百项項篇首页頁座所间間节節门門架把支枝根片头頭匹颗顆粒趟套声聲句"
        U"样樣章口股群批排队隊段堆吨噸升克里码碼毛角点點成分秒小公届屆期美港欧歐英"
        U"步下回圈眼拳脚腳刀枪槍盒包袋箱桶罐盘盤幅集册冊封轮輪局男女"
        U"勺匙滴串束朵棵株盆锅鍋桌副顶頂艘连連"
        // A record's wins, losses and draws (3局2胜 三局两胜, 2胜1负 两胜一负; session 14).
        U"胜勝负負平"
        // A medal table's golds, silvers and bronzes (奪得2金5銅 兩金五銅; session 14).
        U"金银銀铜銅"
        // A golfer's strokes, goals, medals, votes, questions, meals, trains, doses and
        // nights (2杆优势 两杆, 进了2球, 2枚金牌, 2票, 2道题, 2顿饭, 2列, 打了2针, 住2晚; session 16).
        U"杆桿球枚票道顿頓列针針晚夜"
        // A recipe's cloves and spoons (2-3瓣蒜 两到三瓣, 2汤匙 两汤匙, 2茶匙; session 17).
        U"瓣汤湯茶"
        // Taiwan's trillion, a magnitude as 万 and 亿 are (2兆 兩兆; session 23: 二兆).
        U"兆"
        // A toll's dead and injured, counted as a record's wins are (2死5伤 两死五伤, 1死2傷 一死兩傷;
        // session 29: 二死, 二伤).
        U"死伤傷"
        // A tablet as Taiwan's drug labels count it (每次2錠 兩錠, as 2片 两片; session 35: 二錠).
        U"锭錠"
        // A case as health news counts patients (新增2例 两例) and Hong Kong's news counts cases of any kind
        // (2宗嚴重流感個案 兩宗; session 38: 二例, 二宗).
        U"例宗"
        // A play, as 一出戏 counts it, and a baseball inning's outs (2出局 兩出局; session 44: 二出局).
        U"出"
        // A round or a shot, as a game's lines and war news count them (就剩2发子弹了 两发, 2發炮彈;
        // session 46: 二发).
        U"发發");
}

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

std::string text_after(const std::vector<CodePoint>& text, std::size_t end, bool clause_only) {
    std::string after;
    for (auto i = end; i < text.size(); ++i) {
        const auto c = ascii_form(text[i].value);
        if (c == '.' || c == '!' || c == '?' || c == ';' || c == 0x3002 || c == '\n') break;
        if (clause_only && c == ',') break;
        after += text[i].text;
    }
    return after;
}

void append_warning(SpokenForm& form, const std::string& warning) {
    if (warning.empty()) return;
    if (!form.warning.empty()) form.warning += "; ";
    form.warning += warning;
}

bool is_dash(char32_t c) {
    return c == '-' || c == 0x2013 /*–*/ || c == 0x2014 /*—*/ || c == 0x2212 /*−*/;
}

bool is_relation_sign(char32_t c) {
    return is_one_of(c, U"=<>\u2248\u2260\u2264\u2265");
}

bool is_range_mark(char32_t c) {
    return is_dash(c) || c == '~' || c == 0x301C /*〜*/;
}

}  // namespace talkface::detail

#include "text/dates_and_times.hpp"

#include <utility>

#include "text/number_words.hpp"
#include "text/script_variant.hpp"

namespace talkface::detail {

namespace {

// Whether c is the mark that joins a pair's two numbers: a colon in a pair joined by one (23:25),
// else a dash (6-4).
bool is_pair_mark(char32_t c, bool is_colon_pair) {
    return is_colon_pair ? c == ':' : is_dash(c);
}

// A pair of whole numbers joined by a dash (a colon where is_colon_pair) that ends right before
// text[end] (the 6-4 of 6-4、): where it starts, or nullopt.
std::optional<std::size_t> pair_before(const std::vector<CodePoint>& text, std::size_t end,
                                       bool is_colon_pair) {
    auto first = end;
    while (first > 0 && is_digit_at(text, first - 1)) --first;
    if (first == end || first < 2 || !is_pair_mark(value_at(text, first - 1), is_colon_pair) ||
        !is_digit_at(text, first - 2))
        return std::nullopt;
    first -= 1;
    while (first > 0 && is_digit_at(text, first - 1)) --first;
    return first;
}

// A pair of whole numbers joined by a dash (a colon where is_colon_pair) that starts at text[start]
// (the 3-6 of 、3-6): where it ends, or nullopt.
std::optional<std::size_t> pair_from(const std::vector<CodePoint>& text, std::size_t start,
                                     bool is_colon_pair) {
    auto end = start;
    if (digits_from(text, end).empty() || !is_pair_mark(value_at(text, end), is_colon_pair))
        return std::nullopt;
    ++end;
    if (digits_from(text, end).empty()) return std::nullopt;
    return end;
}

// Whether the clause names the pair text[start, end) a score by itself, without the pairs listed beside it.
bool names_score(const std::vector<CodePoint>& text, std::size_t start, std::size_t end, bool dashed) {
    const std::string before = text_before(text, start, true);
    // A tie-break (抢七7-5) and a set or a game named right before the pair (第2盘6-4, 首局11-9, 决胜局,
    // not 结局 or 布局) name a score too (session 17: 七到五).
    if (contains_any(
            before, {"比分", "比數", "比数", "战成", "戰成", "打成", "踢成", "抢七", "搶七", "抢十", "搶十"}))
        return true;
    if (start >= 2 && is_one_of(text[start - 1].value, U"盘盤局") &&
        (is_digit_at(text, start - 2) || is_one_of(text[start - 2].value, U"首次胜勝")) && !takes_liang(value_at(text, end))) {
        return true;
    }
    // A player's or a side's result in a clause naming a match (决赛他3-1， 决赛他们3-1， 三比一; session 24:
    // 三到一): a pronoun right before the pair, which closes its clause. Outside a match one player's pair
    // is a game's record (这把我0-8， 零杠八).
    const auto pronoun_at = [&](std::size_t k) { return is_one_of(text[k].value, U"我你他她"); };
    const bool after_pronoun = start > 0 && pronoun_at(start - 1);
    const bool after_plural_pronoun =
        start > 1 && is_one_of(text[start - 1].value, U"们們") && pronoun_at(start - 2);
    const bool closes_clause = end >= text.size() || is_one_of(text[end].value, U"，,。.！!？?；;～~…\n ");
    if ((after_pronoun || after_plural_pronoun) && contains_any(before, {"赛", "賽"}) && closes_clause)
        return true;
    const std::string after = text_between(text, end, end + 2);
    constexpr std::string_view kResults[] = {
        "战胜", "戰勝", "击败", "擊敗", "获胜", "獲勝", "取胜", "取勝", "领先", "領先", "落后", "落後",
        "险胜", "險勝", "大胜", "大勝", "完胜", "完勝", "逆转", "逆轉", "告负", "告負", "战平", "戰平",
        "打平", "逼平", "胜", "勝", "负", "負", "赢", "贏", "输", "輸",
        // Session 15: a loss said by the loser's side (1-2不敌, 惜败; it was a range).
        "不敌", "不敵", "惜败", "惜敗", "憾负", "憾負", "力克",
        // Session 25: the score a game opens with (这把0-3开局; it was a range).
        "开局", "開局"};
    for (const auto word : kResults)
        if (starts_with(after, word)) return true;
    if (!dashed) return false;
    const std::string clause = text_after(text, end);
    for (const auto word : kResults)
        if (word.size() > std::string_view("胜").size() && clause.find(word) != std::string::npos) return true;
    return false;
}

}  // namespace

bool is_score(const std::vector<CodePoint>& text, std::size_t start, std::size_t end, bool dashed) {
    if (names_score(text, start, end, dashed)) return true;
    // A pair listed with a score, 、 between them, is one too: after it (比分为25-18、25-20: the clause named
    // the first; session 22: 二十五到二十), or before it, as a list of sets ends with its result (他以6-4、
    // 3-6、7-5赢下比赛; session 24: 六到四、三到六). A measure word after a later pair makes it a range.
    // The pairs listed are joined as this one is: a volleyball match's sets with colons (比分为23:25、
    // 25:20、22:25; session 26: the sets that could be clock times were read so, 二十二点二十五分).
    constexpr char32_t kListMark = 0x3001;  // 、
    bool is_colon_pair = false;
    for (auto k = start; k < end; ++k) is_colon_pair = is_colon_pair || value_at(text, k) == ':';
    for (auto at = start; at > 0 && value_at(text, at - 1) == kListMark;) {
        const auto first = pair_before(text, at - 1, is_colon_pair);
        if (!first) break;
        if (names_score(text, *first, at - 1, dashed)) return true;
        at = *first;
    }
    for (auto at = end; value_at(text, at) == kListMark;) {
        const auto last = pair_from(text, at + 1, is_colon_pair);
        if (!last) break;
        if (names_score(text, at + 1, *last, dashed && !takes_liang(value_at(text, *last)))) return true;
        at = *last;
    }
    return false;
}

bool speaks_of_duration(const std::vector<CodePoint>& text, std::size_t start) {
    const std::string before = text_before(text, start, true);
    if (contains_any(before, {"成绩", "成績", "用时", "用時", "耗时", "耗時", "历时", "歷時", "跑出", "游出",
                              "完赛", "完賽", "时长", "時長",
                              // The time left on a game's clock (第4节还剩2:35; session 17: 两点三十五分).
                              "还剩", "還剩", "剩余", "剩餘", "倒计时", "倒計時",
                              // A game's clear time (通关时间：02:35; session 21: 两点三十五分).
                              "通关", "通關"}))
        return true;
    // A queue's wait as its screen shows it, minutes written with two digits (预计等待时间05:20 五分二十秒,
    // 00:45 四十五秒; session 21: 五点二十分): a wait to a time of day is written without the zero
    // (等待时间：12:30开始).
    if (value_at(text, start) != '0') return false;
    return contains_any(before, {"等待", "等候", "排队", "排隊"});
}

namespace {

// Whether a line of `text` opens with the recording's start, 0:00 or 00:00, a space and a title in
// Chinese (00:00 开场): the first of a video's or a podcast's chapters.
bool opens_chapter_list(const std::vector<CodePoint>& text) {
    for (std::size_t line = 0; line < text.size();) {
        auto k = line;
        while (value_at(text, k) == ' ') ++k;
        const auto after_zero = value_at(text, k) == '0' && value_at(text, k + 1) == '0' ? k + 1 : k;
        if (value_at(text, after_zero) == '0' && value_at(text, after_zero + 1) == ':' &&
            value_at(text, after_zero + 2) == '0' && value_at(text, after_zero + 3) == '0' &&
            value_at(text, after_zero + 4) == ' ') {
            auto title = after_zero + 4;
            while (value_at(text, title) == ' ') ++title;
            if (is_han(value_at(text, title))) return true;
        }
        while (line < text.size() && text[line].value != '\n') ++line;
        ++line;
    }
    return false;
}

}  // namespace

bool names_place_in_recording(const std::vector<CodePoint>& text, std::size_t start, std::size_t end) {
    if (is_one_of(value_at(text, end), U"处處")) return true;
    const std::string before = text_before(text, start, true);
    // A chat points at a moment of a video as at a place (视频0:45那里笑死我了, 这集12:30那段; session 33:
    // 零点四十五分); without the video named it may be the time to meet (今晚12:30那里见).
    if (starts_with_any(text_between(text, end, end + 2), {"那里", "那裡", "那儿", "那兒", "那段"}) &&
        contains_any(before, {"视频", "視頻", "影片", "录像", "錄像", "音频", "音頻", "录音", "錄音", "回放",
                              "这集", "這集", "这期", "這期"}))
        return true;
    if (contains_any(before, {"进度条", "進度條", "时间轴", "時間軸", "时间线", "時間線", "拖到", "拉到",
                              "跳到", "快进到", "快轉到"}))
        return true;
    // A podcast's or a video's notes list its chapters, each a time opening its line, a space and the title
    // (03:15 为什么要做播客 三分十五秒; session 40: 三点十五分): where the transcript names a show or an
    // episode, or its list opens at the recording's start (00:00 开场, as a video's chapters must; session
    // 43: 45:10 总结 read 四十五比十, a score), such a time is a place in it. A schedule's line (09:00 开幕)
    // in other text stays a time of day.
    auto line_start = start;
    while (line_start > 0 && text[line_start - 1].value == ' ') --line_start;
    if (line_start > 0 && text[line_start - 1].value != '\n') return false;
    auto title = end;
    if (value_at(text, title) != ' ') return false;
    while (value_at(text, title) == ' ') ++title;
    if (!is_han(value_at(text, title))) return false;
    return opens_chapter_list(text) ||
           contains_any(text_between(text, 0, text.size()),
                        {"播客", "节目", "節目", "本期", "本集", "单集", "單集", "章节", "章節", "Podcast",
                         "podcast", "Shownotes", "shownotes", "show notes"});
}

namespace {

// A range mark right after `form` and a second form of its kind (`read_last` of the number after the mark):
// 到 and the second said after the first, as a range is (113/09/01~113/09/30, 10AM-8PM).
template <typename ReadLast>
void join_range_end(const std::vector<CodePoint>& text, SpokenForm& form, ReadLast read_last) {
    if (!is_range_mark(value_at(text, form.end)) || !is_digit_at(text, form.end + 1)) return;
    if (auto last = read_last(parse_number(text, form.end + 1))) {
        form.words += "到" + last->words;
        form.end = last->end;
    }
}

// A count of hours, minutes, feet or inches before its word (两点, 两分, 两英寸), with 两 for 2 as
// before a measure word (两本书).
std::string count_words(const std::string& digits) {
    return digits == "2" ? std::string("两") : cardinal_words(digits, false);
}

// hh:mm:ss,mmm or hh:mm:ss.mmm (SRT, WebVTT) at text[i]; where it ends, or i.
std::size_t past_cue_time(const std::vector<CodePoint>& text, std::size_t i) {
    auto k = i;
    for (int part = 0; part < 3; ++part) {
        if (part > 0 && value_at(text, k++) != ':') return i;
        if (digits_from(text, k).size() != 2) return i;
    }
    if (!is_one_of(value_at(text, k), U",.")) return i;
    ++k;
    return digits_from(text, k).size() == 3 ? k : i;
}

}  // namespace

std::optional<std::size_t> past_subtitle_timing(const std::vector<CodePoint>& text, std::size_t start) {
    // A lyric's time tag, [mm:ss] or [mm:ss.xx], in its brackets at the start of a line or after
    // another tag ([00:12.00][01:30.00]); elsewhere a time in brackets is said (会议[12:30]开始).
    const bool opens_line = start == 1 || (start >= 2 && is_one_of(value_at(text, start - 2), U"\n]"));
    if (start > 0 && value_at(text, start - 1) == '[' && opens_line) {
        auto k = start;
        if (digits_from(text, k).size() == 2 && value_at(text, k) == ':') {
            ++k;
            if (digits_from(text, k).size() == 2) {
                if (value_at(text, k) == '.') {
                    ++k;
                    const auto fraction = digits_from(text, k);
                    if (fraction.empty() || fraction.size() > 3) return std::nullopt;
                }
                if (value_at(text, k) == ']') return k;
            }
        }
        return std::nullopt;
    }
    // A cue's times, with the arrow and the second time where they follow.
    auto end = past_cue_time(text, start);
    if (end == start) return std::nullopt;
    auto k = end;
    while (value_at(text, k) == ' ') ++k;
    if (text_between(text, k, k + 3) == "-->") {
        k += 3;
        while (value_at(text, k) == ' ') ++k;
        if (const auto second = past_cue_time(text, k); second != k) end = second;
    }
    return end;
}

bool names_a_day(const std::vector<CodePoint>& text, std::size_t start, const WrittenNumber& number) {
    const auto& digits = number.whole;
    if (number.has_point || number.has_separators || digits.size() < 3 || digits.size() > 4) return false;
    const auto month_length = digits.size() - 2;
    if (!is_month_and_day(digits.substr(0, month_length), digits.substr(month_length))) return false;
    const std::string after = text_between(text, number.end, number.end + 3);
    if (starts_with_any(after,
                        {"节", "節", "大促", "促销", "促銷", "购物", "購物", "晚会", "晚會", "活动", "活動",
                         "当天", "當天", "这天", "這天", "那天", "快乐", "快樂", "狂欢", "狂歡", "表白",
                         // A disaster named by its day (921大地震 九二一, 512地震; session 17).
                         "大地震", "地震", "事件"}))
        return true;
    const std::string before = text_before(text, start, true);
    if (ends_with_any(
            before, {"今天是", "明天是", "昨天是", "后天是", "後天是", "今天就是", "又到了", "迎来", "迎來"}))
        return true;
    // A day's word right before the digits, where they close their clause, names the day too, as chat
    // writes it without 是 (今天520，你送礼物了吗 五二零; session 31: 五百二十): with nothing after them
    // they count nothing.
    const auto next = value_at(text, number.end);
    return ends_with_any(before, {"今天", "明天", "昨天", "后天", "後天"}) &&
           (next == 0 || is_one_of(next, U",.!?;\u3002\u3001\n"));
}

bool counts_years(const std::vector<CodePoint>& text, std::size_t start, const WrittenNumber& number) {
    constexpr int kLatestYearNamed = 2100;
    if (number.has_point || number.has_separators || number.whole.size() != 4 || value_at(text, number.end) != U'年')
        return false;
    if (std::stoi(number.whole) > kLatestYearNamed || ends_with(text_before(text, start, true), "公元前")) return true;
    const std::string after = text_between(text, number.end + 1, number.end + 4);
    return starts_with_any(after, {"历史", "歷史", "的历史", "的歷史", "之久"});
}

bool names_year_before_word(const std::vector<CodePoint>& text, const WrittenNumber& number) {
    if (number.has_point || number.has_separators) return false;
    // A release or a quarter named by its year's last two digits and the half or quarter (Windows 11 24H2
    // 二四 H 二, 22H2, 25Q1 二五 Q 一; session 27: 二十四), as the year is said digit by digit.
    const auto period = value_at(text, number.end);
    const auto part = value_at(text, number.end + 1);
    if (number.whole.size() == 2 &&
        ((period == 'H' && is_one_of(part, U"12")) || (period == 'Q' && is_one_of(part, U"1234"))) &&
        !is_digit_at(text, number.end + 2) && !is_ascii_letter(value_at(text, number.end + 2)))
        return true;
    if (number.whole.size() != 4 || !starts_with_any(number.whole, {"19", "20"})) return false;
    // The first end of a range of such years, the second no earlier (2024-2026届 二零二四到二零二六届, as
    // 2020-2025年 is said; session 31: counted, 两千零二十四到两千零二十六届).
    if (is_range_mark(value_at(text, number.end)) && is_digit_at(text, number.end + 1)) {
        const auto second = parse_number(text, number.end + 1);
        return second.whole.size() == 4 && second.whole >= number.whole &&
               names_year_before_word(text, second);
    }
    const std::string after = text_between(text, number.end, number.end + 3);
    // A year's quarter or half (2024Q4 二零二四 Q 四, 2025H1; session 17: 两千零二十四).
    if (after.size() >= 2 && is_one_of(value_at(text, number.end), U"QH") && is_digit_at(text, number.end + 1) &&
        !is_digit_at(text, number.end + 2))
        return true;
    const auto names_year_from = [&](std::size_t at) {
        return starts_with_any(
            text_between(text, at, at + 3),
            {"财年", "財年", "赛季", "賽季", "款", "届", "屆", "级", "級", "版", "春晚", "世界杯", "世界盃",
             "奥运", "奧運", "冬奥", "冬奧", "亚运", "亞運", "全运", "全運",
             // An exam's year (#2024高考#, 2025考研, 2026国考; session 17).
             "高考", "中考", "考研", "国考", "國考", "学测", "學測"});
    };
    if (names_year_from(number.end)) return true;
    // A listing's or a league's new or season's one between the year and its word (2024新款, 2024秋冬新款,
    // 2025新赛季, 2024新版; session 41: counted, 两千零二十四新款), as a shop titles this year's model.
    auto word = number.end;
    while (word < number.end + 3 && is_one_of(value_at(text, word), U"新春夏秋冬季")) ++word;
    return word > number.end && names_year_from(word);
}

bool names_era_year(const std::vector<CodePoint>& text, std::size_t start, const WrittenNumber& number) {
    return !number.has_point && !number.has_separators && number.whole.size() == 3 &&
           value_at(text, number.end) == U'年' &&
           ends_with_any(text_before(text, start, true), {"公元", "公元前"});
}

bool names_year_in_title(const std::vector<CodePoint>& text, std::size_t start, const WrittenNumber& number) {
    if (number.has_point || number.has_separators || number.whole.size() != 4 ||
        !starts_with_any(number.whole, {"19", "20"}) || !is_one_of(value_at(text, number.end), U"》〉」"))
        return false;
    if (start == 0) return false;
    const auto before = text[start - 1].value;
    return !is_one_of(before, U"《〈「") && !is_ascii_letter(before) && !is_digit_at(text, start - 1);
}

bool names_year_after_mark(const std::vector<CodePoint>& text, std::size_t start,
                           const WrittenNumber& number) {
    const auto& digits = number.whole;
    if (number.has_point || number.has_separators || is_ascii_letter(value_at(text, number.end)) ||
        takes_liang(value_at(text, number.end)) ||
        !(digits.size() == 2 || (digits.size() == 4 && starts_with_any(digits, {"19", "20"}))))
        return false;
    if (start >= 2 && text_between(text, start - 2, start) == "FY")
        return !is_ascii_letter(value_at(text, start - 3));
    if (digits.size() != 4 || start < 3 || value_at(text, start - 1) != ' ' ||
        is_ascii_letter(value_at(text, start - 4)))
        return false;
    const auto period = value_at(text, start - 3);
    const auto part = value_at(text, start - 2);
    return (period == 'Q' && is_one_of(part, U"1234")) || (period == 'H' && is_one_of(part, U"12"));
}

bool joins_periods(const std::vector<CodePoint>& text, std::size_t i) {
    const auto names_period = [&](std::size_t letter) {
        const auto part = value_at(text, letter + 1);
        return ((value_at(text, letter) == 'Q' && is_one_of(part, U"1234")) ||
                (value_at(text, letter) == 'H' && is_one_of(part, U"12"))) &&
               !is_digit_at(text, letter + 2) && !is_ascii_letter(value_at(text, letter + 2));
    };
    return i >= 2 && is_range_mark(value_at(text, i)) && names_period(i - 2) &&
           !is_ascii_letter(value_at(text, i - 3)) && names_period(i + 1);
}

bool names_short_year(const std::vector<CodePoint>& text, std::size_t start, const WrittenNumber& number) {
    if (number.has_point || number.has_separators || number.whole.size() != 2 ||
        value_at(text, number.end) != U'年')
        return false;
    auto i = number.end + 1;
    const auto month = digits_from(text, i);
    if (month.empty() || month.size() > 2 || value_at(text, i) != U'月' || !is_month_and_day(month, "1"))
        return false;
    return !is_traditional_text(text) && !ends_with_any(text_before(text, start, true), {"民国", "民國"});
}

bool lists_year(const std::vector<CodePoint>& text, const WrittenNumber& number) {
    constexpr std::size_t kYearDigits = 4;
    const auto last_start = last_listed_start(text, number, kYearDigits);
    if (last_start == 0) return false;
    const auto last = parse_number(text, last_start);
    if (value_at(text, last.end) == U'年') return !counts_years(text, last_start, last);
    return names_year_before_word(text, last);
}

std::optional<SpokenForm> read_clock_time(const std::vector<CodePoint>& text, const WrittenNumber& hour,
                                          bool duration) {
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
    // A 24-hour clock's leading zero is not said (02:00 两点, as 2:00 is; session 15: it was 二点).
    const auto hour_digits = hour.whole.size() == 2 && hour.whole.front() == '0' ? hour.whole.substr(1) : hour.whole;
    const auto first = count_words(hour_digits);
    const bool has_seconds = value_at(text, i) == ':' && is_digit_at(text, i + 1) && is_digit_at(text, i + 2) &&
                             !is_digit_at(text, i + 3);
    if (duration) {
        // No minutes are not said (00:45 四十五秒), as a countdown reads; hours and minutes keep theirs.
        const bool no_minutes = !has_seconds && hour_digits == "0" && minutes != "00";
        form.words = (no_minutes ? "" : first + (has_seconds ? "小时" : "分")) +
                     say_part(minutes, has_seconds ? "分" : "秒");
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

bool is_republic_year(const std::string& digits) {
    return digits.size() == 3 && digits.front() == '1';
}

std::string said_year(const std::string& digits) {
    return (is_republic_year(digits) ? cardinal_words(digits, false) : digit_words(digits)) + "年";
}

std::optional<SpokenForm> read_numeric_date(const std::vector<CodePoint>& text, const WrittenNumber& year) {
    const auto separator = value_at(text, year.end);
    // A two-digit year of the Republic with slashes (99/12/31, 88/9/21), as Taiwan dates its papers,
    // in a Traditional transcript (below); elsewhere two digits and slashes are left to the fractions.
    const bool may_be_short_republic_year = year.whole.size() == 2 && year.whole.front() != '0' && separator == '/';
    if (year.has_point || year.has_separators ||
        !(year.whole.size() == 4 || is_republic_year(year.whole) || may_be_short_republic_year) ||
        !(separator == '-' || separator == '/')) {
        return std::nullopt;
    }
    auto i = year.end + 1;
    const auto month = digits_from(text, i);
    if (month.empty() || month.size() > 2 || value_at(text, i) != separator) return std::nullopt;
    ++i;
    const auto day = digits_from(text, i);
    if (!is_month_and_day(month, day)) return std::nullopt;
    // Counted, as 民國99年 is (session 17: 99/12/31 was 十二分之九十九 and 三十一).
    if (may_be_short_republic_year && !is_traditional_text(text)) return std::nullopt;
    SpokenForm form;
    form.words = (may_be_short_republic_year ? cardinal_words(year.whole, false) + "年" : said_year(year.whole)) +
                 cardinal_words(month, false) + "月" + cardinal_words(day, false) + "日";
    form.end = i;
    // A range of two such dates (113/09/01~113/09/30, 2026-12-01~2026-12-05): the mark is 到, as after
    // any date (session 16; the mark was left to the second date, which it made a sign or skipped).
    join_range_end(text, form, [&](const WrittenNumber& last) { return read_numeric_date(text, last); });
    return form;
}

bool follows_date_or_time(const std::vector<CodePoint>& text, std::size_t mark) {
    if (mark >= 2 && is_one_of(text[mark - 1].value, U"年月日号號点點时時分秒")) return is_digit_at(text, mark - 2);
    return mark >= 4 && is_digit_at(text, mark - 1) && is_digit_at(text, mark - 2) && value_at(text, mark - 3) == ':' &&
           is_digit_at(text, mark - 4);
}

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

namespace {

// The words of a year and a month written with a dot (2027.03 二零二七年三月), or "" where `number` is none.
std::string year_and_month_words(const std::vector<CodePoint>& text, const WrittenNumber& number) {
    constexpr std::size_t kYearDigits = 4;
    if (!number.has_point || number.has_separators || number.whole.size() != kYearDigits ||
        !(starts_with(number.whole, "19") || starts_with(number.whole, "20")) ||
        number.fraction.size() != 2 || !is_month_and_day(number.fraction, "1"))
        return "";
    const auto next = value_at(text, number.end);
    if (is_ascii_letter(next) || is_digit_at(text, number.end) || next == '.' || takes_liang(next) ||
        is_one_of(next, U"%‰元圆圓块塊万萬亿億点點倍"))
        return "";
    return said_year(number.whole) + cardinal_words(number.fraction, false) + "月";
}

}  // namespace

std::optional<SpokenForm> read_year_and_month(const std::vector<CodePoint>& text, std::size_t start,
                                              const WrittenNumber& year) {
    auto words = year_and_month_words(text, year);
    if (words.empty()) return std::nullopt;
    SpokenForm form;
    form.end = year.end;
    bool is_range = false;
    const auto mark = value_at(text, form.end);
    if ((is_range_mark(mark) || is_one_of(mark, U"至到")) && is_digit_at(text, form.end + 1)) {
        const auto last = parse_number(text, form.end + 1);
        if (auto last_words = year_and_month_words(text, last); !last_words.empty()) {
            words +=
                (is_range_mark(mark) ? std::string("到") : std::string(text[form.end].text)) + last_words;
            form.end = last.end;
            is_range = true;
        }
    }
    const bool dates =
        is_range || is_one_of(value_at(text, form.end), U"起前止") ||
        contains_any(text_before(text, start, true), {"有效期", "日期", "期限", "保质期", "保質期", "保修期",
                                                      "到期", "期间", "期間", "截止", "截至"});
    if (!dates) return std::nullopt;
    form.words = std::move(words);
    return form;
}

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

std::optional<SpokenForm> read_month_and_day(const std::vector<CodePoint>& text, std::size_t start,
                                             const WrittenNumber& month) {
    if (month.has_point || month.has_separators || value_at(text, month.end) != '/') return std::nullopt;
    auto i = month.end + 1;
    const auto day = digits_from(text, i);
    if (!is_month_and_day(month.whole, day) || value_at(text, i) == '.' || value_at(text, i) == '/') return std::nullopt;
    // A range of two days (10/1-10/7, and 12/1至12/31 since session 26: it was two fractions): the second
    // day no earlier than the first (1/3~1/2 is no range of days), and the words after the second day
    // decide for both.
    auto first_end = i;
    std::string second_day_words;
    const bool range_word = is_one_of(value_at(text, i), U"至到");
    if ((is_range_mark(value_at(text, i)) || range_word) && is_digit_at(text, i + 1)) {
        auto k = i + 1;
        const auto second_month = digits_from(text, k);
        if (value_at(text, k) == '/' && is_digit_at(text, k + 1)) {
            ++k;
            const auto second_day = digits_from(text, k);
            if (is_month_and_day(second_month, second_day) && value_at(text, k) != '/' && value_at(text, k) != '.' &&
                std::make_pair(std::stoi(second_month), std::stoi(second_day)) >=
                    std::make_pair(std::stoi(month.whole), std::stoi(day))) {
                second_day_words = (range_word ? std::string(text[first_end].text) : std::string("到")) +
                                   cardinal_words(second_month, false) + "月" +
                                   cardinal_words(second_day, false) + "日";
                i = k;
            }
        }
    }
    const std::string after = text_between(text, i, i + 2);
    bool in_time = starts_with_any(
        after, {"起",   "前",   "后", "後", "晚",   "早", "上午", "下午", "中午", "凌晨", "夜",
                "当天", "當天", "(",  "（", "星期", "周", "週",   "礼拜", "禮拜", "期间", "期間"});
    const bool is_fraction = after == "决赛" || after == "決賽" || value_at(text, i) == U'的' ||
                             (i < text.size() && takes_liang(text[i].value));
    if (!in_time && is_fraction) return std::nullopt;
    auto before = text_before(text, start, true);
    // A word of time before it names what the day is (展会时间为12/3-12/5, 日期：9/18, and a period's
    // days since session 26: 活動期間為12/1至12/31).
    auto named = before;
    while (!named.empty() && ends_with_any(named, {"为", "為", "是", "：", ":", " "}))
        named.erase(named.size() - (named.back() == ':' || named.back() == ' ' ? 1 : std::string_view("为").size()));
    in_time = in_time || ends_with_any(named, {"时间", "時間", "日期", "期间", "期間"});
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

std::optional<SpokenForm> read_padded_month_and_day(const std::vector<CodePoint>& text, std::size_t start,
                                                    const WrittenNumber& month) {
    constexpr std::size_t kDigits = 2;
    if (month.has_point || month.has_separators || month.whole.size() != kDigits ||
        value_at(text, month.end) != '-' ||
        (start > 0 && (is_ascii_letter(text[start - 1].value) || is_digit_at(text, start - 1) ||
                       is_dash(text[start - 1].value))))
        return std::nullopt;
    auto i = month.end + 1;
    const auto day = digits_from(text, i);
    const auto next = value_at(text, i);
    if (day.size() != kDigits || !is_month_and_day(month.whole, day) ||
        !(month.whole.front() == '0' || day.front() == '0') || is_dash(next) || is_ascii_letter(next) ||
        next == '.')
        return std::nullopt;
    SpokenForm form;
    form.words = cardinal_words(month.whole, false) + "月" + cardinal_words(day, false) + "日";
    form.end = i;
    return form;
}

namespace {

// Whole minutes and seconds of two digits as a race's clock is read: 两分, 零五秒 for 05.
std::string minutes_and_seconds_words(const WrittenNumber& minutes, const WrittenNumber& seconds) {
    return count_words(minutes.whole) + "分" +
           (seconds.whole.front() == '0' ? "零" + digit_words(seconds.whole.substr(1))
                                         : cardinal_words(seconds.whole, false)) +
           "秒";
}

}  // namespace

std::optional<SpokenForm> read_race_time(const WrittenNumber& minutes, const WrittenNumber& seconds) {
    constexpr std::size_t kLongestMinutes = 2;
    // A lap timed to the thousandth, as motor racing and speed skating print it (1:27.123 一分二十七秒一二三;
    // session 35: a clock time and a count); a subtitle's thousandths follow minutes with a leading zero.
    constexpr std::size_t kLongestFraction = 3;
    if (minutes.has_point || minutes.has_separators || minutes.whole.size() > kLongestMinutes ||
        (minutes.whole.size() > 1 && minutes.whole.front() == '0') || !seconds.has_point || seconds.whole.size() != 2 ||
        seconds.whole > "59" || seconds.fraction.size() > kLongestFraction) {
        return std::nullopt;
    }
    SpokenForm form;
    form.words = minutes_and_seconds_words(minutes, seconds) + digit_words(seconds.fraction);
    form.end = seconds.end;
    return form;
}

std::optional<SpokenForm> read_primed_time(const std::vector<CodePoint>& text, const WrittenNumber& minutes) {
    constexpr std::size_t kLongestMinutes = 2;
    if (minutes.has_point || minutes.has_separators || minutes.whole.size() > kLongestMinutes ||
        !is_one_of(value_at(text, minutes.end), U"'\u2032") || !is_digit_at(text, minutes.end + 1)) {
        return std::nullopt;
    }
    const auto seconds = parse_number(text, minutes.end + 1);
    if (seconds.has_point || seconds.has_separators || seconds.whole.size() != 2 || seconds.whole > "59" ||
        !is_one_of(value_at(text, seconds.end), U"\"\u2033")) {
        return std::nullopt;
    }
    SpokenForm form;
    form.words = minutes_and_seconds_words(minutes, seconds);
    form.end = seconds.end + 1;
    return form;
}

std::optional<SpokenForm> read_arc_minutes(const std::vector<CodePoint>& text, std::size_t start,
                                           const WrittenNumber& minutes) {
    constexpr std::size_t kLongestMinutes = 2;
    if (start == 0 || value_at(text, start - 1) != 0xB0 /*°*/ || minutes.has_separators ||
        minutes.whole.size() > kLongestMinutes || (minutes.whole.size() == 2 && minutes.whole > "59") ||
        !is_one_of(value_at(text, minutes.end), U"'\u2032")) {
        return std::nullopt;
    }
    SpokenForm form;
    form.words =
        count_words(minutes.whole) + (minutes.has_point ? "点" + digit_words(minutes.fraction) : "") + "分";
    form.end = minutes.end + 1;
    return form;
}

std::optional<SpokenForm> read_feet_and_inches(const std::vector<CodePoint>& text, std::size_t start,
                                               const WrittenNumber& feet) {
    if (feet.has_point || feet.has_separators || feet.whole.size() != 1 || feet.whole == "0" ||
        !is_one_of(value_at(text, feet.end), U"'\u2032") || !is_digit_at(text, feet.end + 1)) {
        return std::nullopt;
    }
    const auto inches = parse_number(text, feet.end + 1);
    if (inches.has_point || inches.has_separators || !is_one_of(value_at(text, inches.end), U"\"\u2033")) {
        return std::nullopt;
    }
    const bool speaks_of_height =
        contains_any(text_before(text, start, true), {"身高", "个子", "個子", "身材", "个头", "個頭"});
    if (inches.whole.size() != 1 && !((inches.whole == "10" || inches.whole == "11") && speaks_of_height))
        return std::nullopt;
    SpokenForm form;
    form.words = count_words(feet.whole) + "英尺" + count_words(inches.whole) + "英寸";
    form.end = inches.end + 1;
    return form;
}

std::optional<SpokenForm> read_twelve_hour_time(const std::vector<CodePoint>& text,
                                                const WrittenNumber& hour) {
    constexpr int kLastHour = 12;
    if (hour.has_point || hour.has_separators || hour.whole.size() > 2 || hour.whole.front() == '0' ||
        std::stoi(hour.whole) > kLastHour) {
        return std::nullopt;
    }
    auto i = hour.end;
    std::string minutes;
    if (value_at(text, i) == ':' && is_digit_at(text, i + 1)) {
        auto k = i + 1;
        minutes = digits_from(text, k);
        if (minutes.size() != 2 || minutes > "59") return std::nullopt;
        i = k;
    }
    if (value_at(text, i) == ' ') ++i;
    const auto letter = value_at(text, i) | 0x20;  // small
    if (letter != 'a' && letter != 'p') return std::nullopt;
    auto end = i + 1;
    if (value_at(text, end) == '.') ++end;
    if ((value_at(text, end) | 0x20) != 'm') return std::nullopt;
    ++end;
    if (value_at(text, end) == '.' && value_at(text, i + 1) == '.') ++end;
    if (is_ascii_letter(value_at(text, end)) || is_digit_at(text, end)) return std::nullopt;
    const int number = std::stoi(hour.whole);
    constexpr int kNoon = 12;
    constexpr int kEvening = 6;
    const char* part = "上午";
    if (letter == 'a' && number == kNoon) part = "凌晨";
    if (letter == 'p') part = number == kNoon ? "中午" : number < kEvening ? "下午" : "晚上";
    SpokenForm form;
    form.words = std::string(part) + count_words(hour.whole) + "点";
    if (!minutes.empty() && minutes != "00")
        form.words += (minutes.front() == '0' ? "零" + digit_words(minutes.substr(1))
                                              : cardinal_words(minutes, false)) +
                      "分";
    form.end = end;
    // Opening hours' range (10AM-8PM, 9am~6pm): the mark is 到, as between two clock times.
    join_range_end(text, form, [&](const WrittenNumber& last) { return read_twelve_hour_time(text, last); });
    return form;
}

std::optional<SpokenForm> read_weekday_bracket(const std::vector<CodePoint>& text, std::size_t start) {
    if (start == 0 || value_at(text, start) != '(' || value_at(text, start + 2) != ')') return std::nullopt;
    const auto before = value_at(text, start - 1);
    if (!is_digit_at(text, start - 1) && !is_one_of(before, U"日号號")) return std::nullopt;
    if (!is_one_of(value_at(text, start + 1), U"一二三四五六日天")) return std::nullopt;
    SpokenForm form;
    form.words = "星期" + std::string(text[start + 1].text);
    form.end = start + 3;
    return form;
}

}  // namespace talkface::detail

#include "text/number_pairs.hpp"

#include "text/dates_and_times.hpp"
#include "text/number_words.hpp"
#include "text/quantities_and_ranges.hpp"

namespace talkface::detail {

namespace {

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

// Whether the sentence around text[start, end) speaks of a sports season or a league's table.
bool speaks_of_season(const std::vector<CodePoint>& text, std::size_t start, std::size_t end) {
    std::string sentence = text_before(text, start, false);
    for (auto i = end; i < text.size() && !is_one_of(value_at(text, i), U"\u3002.!?;\n"); ++i)
        sentence += text[i].text;
    return contains_any(
        sentence, {"赛季", "賽季", "常规赛", "常規賽", "例行赛", "例行賽", "季后赛", "季後賽", "排名", "联盟",
                   "聯盟", "东部", "東部", "西部", "胜率", "勝率", "积分榜", "積分榜"});
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

}  // namespace

std::optional<SpokenForm> read_game_record(const std::vector<CodePoint>& text, std::size_t start,
                                           const WrittenNumber& first) {
    constexpr std::size_t kMostParts = 3;
    constexpr std::size_t kMostDigits = 2;
    if (first.has_point || first.has_separators || first.whole.size() > kMostDigits) return std::nullopt;
    const std::string before = text_before(text, start, true);
    const bool names_record = contains_any(before, {"战绩", "戰績", "KDA"});
    const bool after_player =
        start > 0 && is_one_of(text[start - 1].value, U"我你他她") && !contains_any(before, {"赛", "賽"});
    // A player named by the role played (中单1-4了, 打野0-5了, 辅助0-7还在送) is a player as 我 is (session
    // 33: 零到五, a range).
    constexpr std::string_view kRoles[] = {"打野", "中单", "中單", "上单", "上單",   "辅助",
                                           "輔助", "射手", "ADC",  "下路", "对抗路", "對抗路"};
    const bool after_role = ends_with_any(before, kRoles) && !contains_any(before, {"赛", "賽"});
    if (!names_record && !after_player && !after_role) return std::nullopt;
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
    // A role's record is said with what the player does after it (了, 还在送).
    const bool closes = i >= text.size() || is_one_of(text[i].value, U"，,。.！!？?；;～~…\n ") ||
                        (after_role && is_one_of(text[i].value, U"了还還"));
    if (!names_record && !closes) return std::nullopt;
    // A season's record of wins and losses (湖人目前战绩30-12，排名西部第2; 本赛季战绩45-37) is said
    // 三十胜十二负, as newsreaders say it (session 17: 三十杠十二): two parts where the sentence speaks
    // of a season or a table (赛季 常规赛 季后赛 排名 联盟 东部 西部 胜率 积分榜).
    if (parts == 2 && speaks_of_season(text, start, i)) {
        auto k = first.end + 1;
        form.words =
            cardinal_words(first.whole, false) + "胜" + cardinal_words(digits_from(text, k), false) + "负";
    }
    form.end = i;
    return form;
}

namespace {

// Two whole numbers that fall or stay level, which no range is: a range is written from its low end up.
bool fall_or_stay_level(const WrittenNumber& first, const WrittenNumber& second) {
    if (first.has_point || first.has_separators || second.has_point || second.has_separators ||
        first.whole.size() > kMostCardinalDigits || second.whole.size() > kMostCardinalDigits)
        return false;
    return std::stoull(first.whole) >= std::stoull(second.whole);
}

}  // namespace

bool is_result_between_names(const std::vector<CodePoint>& text, std::size_t start,
                             const WrittenNumber& first, const WrittenNumber& second) {
    if (start == 0 || !fall_or_stay_level(first, second)) return false;
    // A results list sets the score off from both names with a space (曼城 2-2 利物浦, as sports pages and
    // feeds print it; it was 二到二): one on each side, or none.
    const bool spaced = start >= 2 && text[start - 1].value == ' ' && value_at(text, second.end) == ' ';
    const auto before = text[start - 1 - (spaced ? 1 : 0)].value;
    const auto after = value_at(text, second.end + (spaced ? 1 : 0));
    return is_han(before) && before != U'第' && is_han(after) && !takes_liang(after) &&
           !is_one_of(after, U"年月日号號时時点點分秒度楼樓层層室栋棟届屆期");
}

bool is_result_standing_alone(const std::vector<CodePoint>& text, std::size_t start,
                              const WrittenNumber& first, const WrittenNumber& second) {
    return fall_or_stay_level(first, second) && stands_alone(text, start, second.end);
}

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

std::optional<SpokenForm> read_interval(const std::vector<CodePoint>& text, std::size_t start,
                                        const WrittenNumber& number, const std::string& sign_words) {
    if (start == 0 || number.has_separators || ascii_form(value_at(text, number.end)) != ',')
        return std::nullopt;
    const auto opening = ascii_form(value_at(text, start - 1));
    if (opening != '[' && opening != '(') return std::nullopt;
    auto k = number.end + 1;
    if (value_at(text, k) == ' ') ++k;
    std::string second_sign;
    if (is_dash(value_at(text, k)) || value_at(text, k) == '+') {
        second_sign = is_dash(value_at(text, k)) ? "负" : "正";
        ++k;
    }
    std::string second_words;
    if (value_at(text, k) == 0x221E /*∞*/) {
        second_words = (second_sign.empty() ? "正" : second_sign) + "无穷";
        ++k;
    } else if (is_digit_at(text, k)) {
        const auto second = parse_number(text, k);
        if (second.has_separators) return std::nullopt;
        second_words = (second_sign == "负" ? second_sign : "") + say_number(second, {}).words;
        k = second.end;
    } else {
        return std::nullopt;
    }
    const auto closing = ascii_form(value_at(text, k));
    if (closing != ']' && closing != ')') return std::nullopt;
    const bool has_square = opening == '[' || closing == ']';
    if (!has_square && !ends_with_any(text_before(text, start - 1, true), {"区间", "區間"}))
        return std::nullopt;
    SpokenForm form;
    form.words = sign_words + say_number(number, {}).words + "到" + second_words;
    form.end = k;
    return form;
}

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

std::optional<SpokenForm> read_slashed_models(const std::vector<CodePoint>& text, const WrittenNumber& first,
                                              const NumberContext& context) {
    constexpr std::size_t kFewestModelDigits = 3;
    if (!context.is_model || context.is_train || first.has_point || first.has_separators ||
        first.whole.size() < kFewestModelDigits || value_at(text, first.end) != '/' ||
        !is_digit_at(text, first.end + 1))
        return std::nullopt;
    auto end = first.end + 1;
    const auto second = digits_from(text, end);
    if (second.size() != first.whole.size() || is_one_of(value_at(text, end), U"./")) return std::nullopt;
    return SpokenForm{end, digit_words(first.whole) + digit_words(second), "", false};
}

std::optional<SpokenForm> read_dimensions(const std::vector<CodePoint>& text, std::size_t start,
                                          const WrittenNumber& first) {
    if (value_at(text, first.end) != '/' || !is_digit_at(text, first.end + 1)) return std::nullopt;
    if (!contains_any(text_before(text, start, true), {"长宽高", "長寬高", "长×宽×高", "長×寬×高"}))
        return std::nullopt;
    std::vector<WrittenNumber> parts{first};
    while (value_at(text, parts.back().end) == '/' && is_digit_at(text, parts.back().end + 1))
        parts.push_back(parse_number(text, parts.back().end + 1));
    constexpr std::size_t kDimensions = 3;
    if (parts.size() != kDimensions) return std::nullopt;
    SpokenForm form;
    for (const auto& part : parts) {
        const auto said = say_number(part, {});
        form.words += said.words;
        append_warning(form, said.warning);
    }
    form.end = parts.back().end;
    std::size_t unit_end = form.end;
    if (const Unit* unit = unit_at(text, form.end, unit_end)) {
        form.words += unit->words;
        form.end = unit_end;
    }
    return form;
}

namespace {

bool is_power_of_ten(const WrittenNumber& number) {
    return !number.has_point && !number.has_separators && number.whole.front() == '1' &&
           number.whole.find_first_not_of('0', 1) == std::string::npos;
}

// A power of ten from 100 before 分之 drops its 一, as a rate or a fraction of it is said (千分之五,
// 百万分之一, 万分之三; 1/1000 千分之一, 1/100 百分之一: session 34 read the fraction 一千分之一, which
// a reader says only to stress the count). 十 has no 一 to drop.
SaidNumber said_denominator_of(const WrittenNumber& denominator) {
    auto said = say_number(denominator, {});
    constexpr std::string_view kOne = "一";
    constexpr std::size_t kFewestDigits = 3;
    if (is_power_of_ten(denominator) && denominator.whole.size() >= kFewestDigits &&
        said.words.rfind(kOne, 0) == 0)
        said.words.erase(0, kOne.size());
    return said;
}

// A rate per a power of ten, as health and population news write it (发病率为3.2/10万 十万分之三点二,
// 1/100万 百万分之一, 死亡率5.6/1000 千分之五点六): the denominator first, its 万 or 亿 with it, then 分之
// and the rate, which may have a point where the power is 100 or more, or has its 万 or 亿 (session 34:
// 三点二十万, the slash unsaid, and 十分之一万). Other denominators keep a fraction's whole numerator
// (评分4.5/5, 9.5/10 are marks out of a whole, no rate).
std::optional<SpokenForm> read_rate_per_power_of_ten(const WrittenNumber& number,
                                                     const std::string& sign_words,
                                                     const WrittenNumber& denominator, char32_t after) {
    const bool has_magnitude = is_one_of(after, U"万萬亿億");
    if (!is_power_of_ten(denominator) ||
        !(has_magnitude || (number.has_point && denominator.whole.size() > 2)))
        return std::nullopt;
    // 10 before 万 or 亿 drops its 一 too (十万分之三点二).
    auto said_denominator = say_number(denominator, {});
    constexpr std::string_view kOne = "一";
    if (said_denominator.words.rfind(kOne, 0) == 0) said_denominator.words.erase(0, kOne.size());
    const auto said_rate = say_number(number, {});
    SpokenForm form;
    form.words = sign_words + said_denominator.words +
                 (!has_magnitude              ? ""
                  : is_one_of(after, U"万萬") ? "万"
                                              : "亿") +
                 "分之" + said_rate.words;
    append_warning(form, said_denominator.warning);
    append_warning(form, said_rate.warning);
    form.end = denominator.end + (has_magnitude ? 1 : 0);
    return form;
}

}  // namespace

std::optional<SpokenForm> read_slashed_pair(const std::vector<CodePoint>& text, std::size_t start,
                                            const WrittenNumber& number, const std::string& sign_words,
                                            const Currency* currency) {
    if (value_at(text, number.end) != '/' || !is_digit_at(text, number.end + 1)) return std::nullopt;
    const auto denominator = parse_number(text, number.end + 1);
    if (currency == nullptr)
        if (auto rate =
                read_rate_per_power_of_ten(number, sign_words, denominator, value_at(text, denominator.end)))
            return rate;
    if (number.has_point) return std::nullopt;
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
    const auto said_denominator = said_denominator_of(denominator);
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
            const auto said_upper_denominator = said_denominator_of(upper_denominator);
            form.words += "到" + said_upper_denominator.words + "分之" + said_upper.words;
            append_warning(form, said_upper_denominator.warning);
            append_warning(form, said_upper.warning);
            form.end = upper_denominator.end;
        }
    }
    return form;
}

}  // namespace talkface::detail

#include "text/quantities_and_ranges.hpp"

#include <algorithm>
#include <iterator>
#include <optional>
#include <string_view>
#include <utility>

#include "text/digit_codes.hpp"
#include "text/number_signs.hpp"

namespace talkface::detail {

namespace {

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

// A unit in characters whose prefix is no measure word (2毫米 两毫米, 2厘米, 2微克, 2纳米, Taiwan's 2奈米
// 兩奈米, as 2米 and 2公里 are 两; session 38: 二): a unit, as the symbol it spells is (2mm 两毫米).
bool is_small_unit_word_at(const std::vector<CodePoint>& text, std::size_t end) {
    const auto word = text_between(text, end, end + 2);
    for (const std::string_view unit :
         {"毫米", "毫升", "毫克", "毫安", "毫秒", "厘米", "釐米", "微米", "微克", "微秒", "纳米", "納米",
          "奈米", "纳秒", "納秒", "奈秒", "皮米"})
        if (word == unit) return true;
    return false;
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

// A range's second end joined by 至 or 到 at text[end] (-3至5度, -5到3℃) and a temperature after it: the
// first end's sign is a temperature's too (零下三至五度; session 19: 负三).
bool range_word_before_temperature(const std::vector<CodePoint>& text, std::size_t start, std::size_t end) {
    if (!is_one_of(value_at(text, end), U"至到") || !is_digit_at(text, end + 1)) return false;
    const auto second = parse_number(text, end + 1);
    std::size_t unit_end = second.end;
    const Unit* unit = unit_at(text, second.end, unit_end);
    return is_temperature_reading(text, start, unit, value_at(text, second.end));
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

// A currency's amount with K, M or B right after it, as English finance copy writes thousands, millions and
// billions ($90K 九万美元, $1.2M 一百二十万美元, $94.9B 九百四十九亿美元): the amount times the magnitude,
// said in 万 and 亿 as Chinese counts it (session 34: the letter after the amount, 九十美元 K). `number` is
// scaled and its end moved past the letter; false where no such letter stands (not before another letter:
// $5MB).
bool scale_by_magnitude_letter(const std::vector<CodePoint>& text, WrittenNumber& number) {
    const auto letter = value_at(text, number.end);
    const std::size_t shift = is_one_of(letter, U"Kk") ? 3 : letter == 'M' ? 6 : letter == 'B' ? 9 : 0;
    if (shift == 0 || is_ascii_letter(value_at(text, number.end + 1)) || is_digit_at(text, number.end + 1))
        return false;
    std::string fraction = number.fraction;
    fraction.resize(std::max(fraction.size(), shift), '0');
    std::string whole = number.whole + fraction.substr(0, shift);
    whole.erase(0, std::min(whole.find_first_not_of('0'), whole.size() - 1));
    number.whole = whole;
    number.fraction = fraction.substr(shift);
    number.fraction.erase(number.fraction.find_last_not_of('0') + 1);
    number.has_point = !number.fraction.empty();
    number.has_separators = false;
    ++number.end;
    return true;
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

// 升 at text[i] after a number is litres (2升水, 每天饮水2升为宜) but begins a verb before 到 至 级
// (显卡从RTX 2060升到了3060): the number measures nothing there (session 28: 两千零六十, a card's digits
// counted).
bool begins_rise(const std::vector<CodePoint>& text, std::size_t i) {
    return is_one_of(value_at(text, i), U"升昇") && is_one_of(value_at(text, i + 1), U"到至级級");
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
    if (is_one_of(value_at(text, after_first), U"万萬亿億") &&
        is_range_mark(value_at(text, after_first + 1)) && is_digit_at(text, after_first + 2)) {
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

// The money words a writer may put after a currency sign's amount as well: the plain ones (¥23.5元, ¥100块)
// first, then a currency's own name (NT$150新台币, $5 美元).
constexpr std::string_view kMoneyWords[] = {"元",     "块",     "塊",     "圆",   "圓",   "美元",
                                            "美金",   "港元",   "港币",   "港幣", "欧元", "歐元",
                                            "英镑",   "英鎊",   "日元",   "日圆", "日圓", "人民币",
                                            "人民幣", "新台币", "新台幣", "台币", "台幣", "新加坡元"};
constexpr std::size_t kPlainMoneyWords = 5;

// Which of kMoneyWords the text writes right after an amount at text[end], past a magnitude (NT$3万新台币)
// and one space ($5 美元); nullptr where none.
const std::string_view* money_word_after(const std::vector<CodePoint>& text, std::size_t end) {
    if (is_one_of(value_at(text, end), U"万萬亿億千")) ++end;
    if (value_at(text, end) == ' ') ++end;
    const auto after = text_after(text, end);
    for (const auto& word : kMoneyWords)
        if (starts_with(after, word)) return &word;
    return nullptr;
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
        // A writer may name the money after the sign's amount as well (¥23.5元, NT$150元, $5美元, ¥100块):
        // it is said once, the word the text has (session 42: 二十三点五元元).
        if (money_word_after(text, end) == nullptr) form.words += currency->after;
    }
    if (currency == nullptr && unit == nullptr) form.words += count_over_words(text, end);
}

}  // namespace

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

SpokenForm read_quantity(const std::vector<CodePoint>& text, std::size_t start, const WrittenNumber& number,
                         const std::string& sign_words, const Currency* currency, NumberContext context) {
    SpokenForm form;
    NumberRange range = read_range(text, start, number, sign_words);
    std::vector<WrittenNumber>& numbers = range.numbers;
    std::vector<std::string>& signs = range.signs;
    if (currency != nullptr && numbers.size() == 1) scale_by_magnitude_letter(text, numbers.front());
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
    context.has_unit =
        power_words.empty() && ((unit != nullptr && unit->written != "%") || is_byte_unit_at(text, end) ||
                                is_basis_points_at(text, end) || is_small_unit_word_at(text, end));
    context.measures_degrees = unit == nullptr && power_words.empty() && measures_degrees(text, start, end);
    // A shop's threshold after 满, its money unnamed (满200减30 满两百减三十; session 40: 二百), is counted
    // as a shop assistant counts it, as 200块 is; with 元 after it, a notice's, it keeps 二百.
    const bool shop_threshold =
        start > 0 && is_one_of(text[start - 1].value, U"满滿") && !is_one_of(value_at(text, end), U"元圆圓");
    context.counts_kuai = unit == nullptr && currency == nullptr && power_words.empty() &&
                          (is_one_of(value_at(text, end), U"块塊") || shop_threshold ||
                           (value_at(text, end) == U'多' && is_one_of(value_at(text, end + 1), U"块塊")));
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

    // A currency's name written after the amount is said there alone (NT$150新台币 一百五十新台币; session
    // 42: 新台币一百五十新台币), where the sign's word before the amount would say it twice.
    Currency named_after{};
    if (const auto* word = currency == nullptr ? nullptr : money_word_after(text, end);
        word != nullptr && word >= std::begin(kMoneyWords) + kPlainMoneyWords) {
        named_after = *currency;
        named_after.before = "";
        currency = &named_after;
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

}  // namespace talkface::detail

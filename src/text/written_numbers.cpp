#include "text/written_numbers.hpp"

#include "text/approximate_counts.hpp"
#include "text/dates_and_times.hpp"
#include "text/digit_codes.hpp"
#include "text/figure_numbers.hpp"
#include "text/number_context.hpp"
#include "text/number_pairs.hpp"
#include "text/number_signs.hpp"
#include "text/number_words.hpp"
#include "text/quantities_and_ranges.hpp"
#include "text/units_and_money.hpp"
#include "text/written_number_scan.hpp"

namespace talkface::detail {

namespace {

// A relation sign after text[end] (spaces allowed): the numbers before it are a lesson's terms.
bool relation_follows(const std::vector<CodePoint>& text, std::size_t end) {
    while (value_at(text, end) == ' ') ++end;
    return is_relation_sign(value_at(text, end));
}

// A number in E notation (学习率1e-3, 2.5E+8), as code and papers write it, is the number it means:
// 一乘十的负三次方, as 10^6 is 十的六次方 (session 28: its e a letter, 一 yi 三). A letter before the
// digits (0x1e5, a hex code's) or after the power (3e5x) leaves a name. A power of more digits than a
// cardinal is said in is no E notation: its digits are read one by one, with the warning a long number
// gets (2e followed by 17 digits threw an internal error, found by fuzz_transcript).
std::optional<SpokenForm> read_e_notation(const std::vector<CodePoint>& text, std::size_t start,
                                          const WrittenNumber& number, const std::string& sign_words) {
    SpokenForm form;
    if (is_one_of(value_at(text, number.end), U"eE") && !number.has_separators &&
        (start == 0 || !is_ascii_letter(value_at(text, start - 1)))) {
        auto k = number.end + 1;
        const bool negative = is_dash(value_at(text, k));
        if (negative || value_at(text, k) == '+') ++k;
        const auto power = digits_from(text, k);
        if (!power.empty() && power.size() <= kMostCardinalDigits && !is_ascii_letter(value_at(text, k)) &&
            value_at(text, k) != '.') {
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
    // A game's record before a date: Taiwan's dates are written with a year of the Republic of two digits
    // too (KDA 12/3/5 十二杠三杠五; session 43: 十二年三月五日 in a Traditional transcript).
    if (auto record = read_game_record(text, start, number)) return record;
    if (auto date = read_numeric_date(text, number)) return date;
    if (auto season = read_season(text, number)) return season;
    if (auto figure = read_figure_number(text, start, number)) return figure;
    if (auto height = read_feet_and_inches(text, start, number)) return height;
    if (auto time = read_primed_time(text, number)) {
        time->words += per_unit_words(text, time->end);
        return time;
    }
    if (auto minutes = read_arc_minutes(text, start, number)) return minutes;
    if (auto model = read_series_and_model(text, i, number)) return model;
    if (auto variant =
            context.is_model && !context.is_train ? read_model_variant(text, i, number) : std::nullopt)
        return variant;
    if (auto date = read_padded_month_and_day(text, start, number)) return date;
    if (auto digits = read_dashed_digits(text, number, context.is_phone, context.is_named,
                                         follows_book_number(text, start)))
        return digits;
    if (auto code = read_code_with_dash(text, number)) return code;
    if (is_dash(value_at(text, number.end)) && is_digit_at(text, number.end + 1)) {
        auto second = parse_number(text, number.end + 1);
        // A measure word after the pair makes it a range (3-5天后获胜), whatever the clause says.
        const bool may_be_listed_score = !takes_liang(value_at(text, second.end));
        if (is_score(text, start, second.end, may_be_listed_score) ||
            is_result_between_names(text, start, number, second) ||
            is_result_standing_alone(text, start, number, second))
            return join_two(number, "", second, "比", {});
        if (relation_follows(text, second.end)) return join_two(number, "", second, "减", {});  // 5-3=2
    }
    if (auto date = read_month_and_day(text, start, number)) return date;
    return std::nullopt;
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
    if (auto tail = read_masked_tail(text, start)) return tail;
    if (auto form_factor = read_form_factor_digit(text, start)) return form_factor;
    auto sign = read_leading_sign(text, start);
    if (!sign) return std::nullopt;
    const Currency* currency = sign->currency;
    std::string& sign_words = sign->words;
    const auto i = sign->digits;
    const auto number = parse_number(text, i);
    // A chat's +1 as a clause of its own (+1，我也觉得), "me too", is 加一 (session 14; it was 正一).
    if (sign_words == "正" && number.whole == "1" && !number.has_point &&
        (stands_alone(text, start, number.end) || agrees_in_chat(text, start, number.end)))
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
    if (auto repeating = read_repeating_decimal(text, number, sign_words)) return repeating;
    if (currency == nullptr)
        if (auto interval = read_interval(text, start, number, sign_words)) return interval;
    const bool is_bare = sign_words.empty() && currency == nullptr;
    if (is_bare)
        if (auto standard = read_standard_code(text, start, number)) return standard;
    if (is_bare)
        if (auto time = read_twelve_hour_time(text, number)) return time;
    if (is_bare)
        if (auto pair = read_colon_pair(text, start, number, context)) return pair;
    if (currency == nullptr)
        if (auto product = read_product(text, number)) return product;
    if (is_bare)
        if (auto models = read_slashed_models(text, number, context)) return models;
    if (is_bare)
        if (auto dimensions = read_dimensions(text, start, number)) return dimensions;
    if (is_bare)
        if (auto form = read_unsigned_form(text, start, i, number, context)) return form;
    // A code's slash lists the next code (985/211高校), no fraction's.
    if (!context.is_code)
        if (auto pair = read_slashed_pair(text, start, number, sign_words, currency)) return pair;
    return read_quantity(text, start, number, sign_words, currency, context);
}

}  // namespace talkface::detail

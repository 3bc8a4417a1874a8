#include "text/number_context.hpp"

#include <optional>

#include "text/counted_buildings.hpp"
#include "text/counted_parts.hpp"
#include "text/dates_and_times.hpp"
#include "text/digit_codes.hpp"
#include "text/figure_numbers.hpp"
#include "text/number_words.hpp"
#include "text/written_numbers.hpp"

namespace talkface::detail {

namespace {

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

// Right after a + that follows 第 and a number (第90+2分钟, stoppage time's minute): the added number is the
// ordinal's too, 第九十加二分钟 (session 28: 两分钟, a count of minutes).
bool adds_to_ordinal(const std::vector<CodePoint>& text, std::size_t start) {
    if (start == 0 || value_at(text, start - 1) != '+') return false;
    auto k = start - 1;
    while (k > 0 && is_digit_at(text, k - 1)) --k;
    return k + 1 < start && k > 0 && text[k - 1].value == U'第';
}

// A number listed after an ordinal, 、 between them, is an ordinal too (第1、2项 第一、二项, 第3、4、5条;
// session 35: 两项, a count before the measure word): 第 is written once for the list.
bool lists_after_ordinal(const std::vector<CodePoint>& text, std::size_t start) {
    auto k = start;
    while (k > 0 && value_at(text, k - 1) == 0x3001 /*、*/) {
        auto digits = k - 1;
        while (digits > 0 && is_digit_at(text, digits - 1)) --digits;
        if (digits + 1 == k) return false;
        if (digits > 0 && text[digits - 1].value == U'第') return true;
        k = digits;
    }
    return false;
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
    // digit, 八八 (session 14); a bare 88 after a colon or in a clause counts (得分：88, 考了88分). So is one
    // closing its clause after a final particle (明天见啦88～; session 34: 八十八): a count of what the
    // clause said would come before the particle (他今年88了吧).
    if ((whole == "88" || whole == "886") && (context.is_whole_clause || context.after_final_particle))
        return true;
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
    const bool counts =
        !context.is_train &&
        (context.has_unit || (takes_liang(context.next) && !context.next_heads_word && !context.is_dialled) ||
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
    // A flight's 1 is the local one, as a phone's is (Taiwan's 長榮BR189 一八九; session 34: 幺): a flight
    // is announced where the reader is. A train's keeps 幺: a lettered train runs on the mainland's lines
    // (複興號G1次 G幺次) whatever script writes of it; a train without a class's capital (區間車2101次) is
    // Taiwan's railway's in a Traditional transcript, 一 as its announcements say it (session 35: counted,
    // 兩千一百零一次), and the mainland's oldest in a Simplified one (普快1461次 幺四六幺次).
    if (context.is_train) {
        said.words = digit_words(whole, true);
        said.is_dialled = context.is_flight || context.is_unlettered_train;
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
    // A draw numbered by its year and its place in the year (双色球第2026140期 第二零二六一四零期, as a
    // lottery's announcer reads it; session 36: 二百零二万六千一百四十): seven digits from 19 or 20 before
    // 期. A count of issues has no year in it (第10000期 counts).
    constexpr std::size_t kYearAndPlaceDigits = 7;
    if (whole.size() == kYearAndPlaceDigits && context.next == U'期' &&
        (starts_with(whole, "19") || starts_with(whole, "20"))) {
        said.words = digit_words(whole);
        return said;
    }
    // After 第 a number before 号 counts its place (国务院令第752号 第七百五十二号; session 35: 七五二, a
    // room's).
    if (whole.size() >= 3 && ((names_by_digits(context.next) && !context.is_house_number &&
                               !context.is_stake_metres && !context.is_ordinal) ||
                              context.is_named || (context.names_place && !counts))) {
        said.words = digit_words(whole);
        return said;
    }
    return std::nullopt;
}

}  // namespace

bool stands_alone(const std::vector<CodePoint>& text, std::size_t start, std::size_t end) {
    constexpr std::u32string_view kClauseMarks = U"，,。.！!？?～~…\n";
    auto before = start;
    while (before > 0 && text[before - 1].value == ' ') --before;
    auto after = end;
    while (after < text.size() && text[after].value == ' ') ++after;
    return (before == 0 || kClauseMarks.find(text[before - 1].value) != std::u32string_view::npos) &&
           (after == text.size() || kClauseMarks.find(text[after].value) != std::u32string_view::npos);
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
    // A currency sign before it is the money's unit said after it ($2 两美元, HK$2 两港元, ¥2 两元), as
    // 2美元 and 2元 are said (session 32: 二, read as a bare number).
    if (whole == "2" && !context.is_ordinal && !context.is_model && !context.follows_ratio &&
        (context.has_unit || context.has_currency || takes_liang(context.next) || context.measures_degrees ||
         context.counts_in_layout || context.counts_buildings)) {
        said.words = "两";
        return said;
    }
    said.words = cardinal_words(whole, !context.is_ordinal);
    // Casual speech, which counts money in 块, says a 2 at the head of the hundreds 两 (200块 两百块, 250块
    // 两百五十块), as the Xiandai Hanyu Cidian allows both before 百; news and notices, which count in 元,
    // keep 二百 (罚款200元; session 31 left 200块 二百).
    constexpr std::string_view kTwoHundred = "二百";
    constexpr std::size_t kHundredsDigits = 3;
    if (context.counts_kuai && whole.size() == kHundredsDigits && said.words.rfind(kTwoHundred, 0) == 0)
        said.words.replace(0, std::string_view("二").size(), "两");
    return said;
}

NumberContext context_of_number(const std::vector<CodePoint>& text, std::size_t start, std::size_t i,
                                const WrittenNumber& number, const std::string& sign_words,
                                const Currency* currency) {
    NumberContext context;
    std::size_t previous = start;
    while (previous > 0 && text[previous - 1].value == ' ') --previous;
    context.is_ordinal = (previous > 0 && text[previous - 1].value == U'第') ||
                         adds_to_ordinal(text, start) || lists_after_ordinal(text, start) ||
                         numbers_labelled_item(text, start);
    context.is_phone = follows_phone_word(text, start) || precedes_hotline_word(text, number.end);
    // Right after the verb the number is what is dialled, though a word that opens as a measure word follows
    // it (撥打1999臺北市民當家熱線 一九九九, the city's name after the hotline's; session 38: counted, 臺 a
    // machine's); a unit or a currency still counts it.
    const auto verb = text_between(text, previous >= 2 ? previous - 2 : 0, previous);
    context.is_dialled = verb == "拨打" || verb == "撥打" || verb == "致电" || verb == "致電";

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
    const bool is_sensitivity =
        !number.has_point && !number.has_separators && is_camera_sensitivity(text, start, number.whole);
    context.is_model =
        sign_words.empty() && currency == nullptr && !after_times && !is_stake && !is_sensitivity &&
        (follows_model_name(text, start) || follows_maker_name(text, start) ||
         follows_model_name_and_number(text, start, number.end) || follows_glued_name(text, start) ||
         names_code_by_letters(text, start, number) || repeats_card_model(text, start, number) ||
         // An isotope's number after a hyphen (碳-14), or of three digits or more glued to
         // a radioactive element's name, which names its isotopes (铀235, 铯137; 钠500毫克 and
         // 补钙2片 count).
         (follows_element(text, start) &&
          (is_dash(value_at(text, start)) ||
           (number.whole.size() >= 3 && start > 0 &&
            is_one_of(text[start - 1].value, U"铀鈾钚鈽铯銫锶鍶钴鈷碘镭鐳氡钍釷镅鋂钋釙")))));
    context.is_flight = sign_words.empty() && currency == nullptr && !number.has_point &&
                        !number.has_separators && is_flight_number(text, start, number.end);
    // After 第 such a number counts, as dev8 says Taiwan's high-speed 第803車次 (第八百零三車次).
    context.is_unlettered_train = sign_words.empty() && currency == nullptr && !number.has_point &&
                                  !number.has_separators && !context.is_ordinal &&
                                  is_unlettered_train_number(text, start, number.end);
    context.is_train = context.is_flight || context.is_unlettered_train ||
                       (context.is_model && !number.has_point && !number.has_separators &&
                        is_train_number(text, start, number.end));
    context.has_currency = currency != nullptr;
    context.names_place =
        names_room_or_building(text, number.end) ||
        (sign_words.empty() && currency == nullptr && !context.is_ordinal &&
         (names_landmark_after_city(text, start, number) || names_meeting_place(text, start, number)));
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
    context.is_hundredths =
        start >= 2 && (text[start - 1].value == U'秒' || after_metres) && is_digit_at(text, start - 2);
    // 男 and 女 count people (2男3女 两男三女) where they stand alone; a character after them other than a
    // numeral makes a word of them (男子 女单 男篮), which the number does not count: 9秒58男子100米 is a
    // sprint's hundredths and the men's race (session 34: 五十八, a count of men). A pair counts
    // (3男2女组合).
    const auto sex = value_at(text, number.end);
    const auto after_sex = value_at(text, number.end + 1);
    // A measure word that opens a word of rank (排在 排名 排第 名列 位列 位居) is the verb there, counting
    // nothing: 1分29秒876排在第2位 is a lap's thousandths, 八七六 (session 36: 八百七十六, 排 a row's count).
    const bool opens_rank = is_any_of(text_between(text, number.end, number.end + 2),
                                      {"排在", "排名", "排第", "排行", "名列", "位列", "位居"});
    context.next_heads_word = opens_rank || (is_one_of(sex, U"男女") && is_han(after_sex) &&
                                             !is_one_of(after_sex, U"一二两兩三四五六七八九十男女") &&
                                             !(start > 0 && is_one_of(text[start - 1].value, U"男女")));
    context.counts_in_layout =
        sign_words.empty() && currency == nullptr && counts_in_layout(text, start, number);
    context.counts_buildings = sign_words.empty() && currency == nullptr && counts_buildings(text, number);
    // A number and 比 before it make it a score's or a ratio's second term, said bare whatever follows it
    // (2比2平 二比二平), though 平 after a number alone is square metres (100平), which 两 counts.
    context.follows_ratio =
        sign_words.empty() && start >= 2 && text[start - 1].value == U'比' && is_digit_at(text, start - 2);
    context.is_grade = context.is_model && is_filter_grade(text, start, number.whole);
    context.is_span_of_years = counts_years(text, start, number);
    context.is_service_call = is_service_call(text, start, number.end);
    // A code keeps its minus, as after a code's word (错误代码：-1009 负一零零九): a status an app shows in
    // brackets (网络不可用(-1009); session 43: 负一千零九) is looked at from its sign.
    context.is_code = (sign_words.empty() || sign_words == "负") && currency == nullptr &&
                      names_by_its_digits(text, start, number);
    context.is_frequency = sign_words.empty() && currency == nullptr && follows_station_band(text, start);
    context.is_version = sign_words.empty() && currency == nullptr &&
                         (follows_software_name(text, i) || ends_range_of_versions(text, i));
    // A version before 后 is no generation (升级到Android 15后 十五后; session 17: 一五后).
    if (context.is_version) context.is_generation = false;
    const auto after_number = value_at(text, number.end);
    const bool closes_clause = number.end >= text.size() || is_one_of(after_number, U"，,。.！!？?～~…\n ");
    context.after_final_particle = sign_words.empty() && start > 0 && closes_clause &&
                                   is_one_of(value_at(text, start - 1), U"吧啊呀呢嘛哦啦");
    // A laugh's number after a laugh's character; or after a chat's final particle, closing its line
    // (太离谱了吧233, 好好笑啊233; session 16: 二百三十三); or closing a clause that laughs (笑死我了233;
    // session 21: 二百三十三).
    context.after_laugh =
        sign_words.empty() && start > 0 &&
        (is_one_of(value_at(text, start - 1), U"哈呵嘿嘻笑死") || context.after_final_particle ||
         (closes_clause && text_before(text, start, true).find("笑") != std::string::npos));
    context.is_whole_clause =
        sign_words.empty() && currency == nullptr && stands_alone(text, start, number.end);
    context.names_year =
        sign_words.empty() && currency == nullptr && !context.is_ordinal &&
        (names_year_before_word(text, number) || lists_year(text, number) ||
         names_short_year(text, start, number) || names_year_after_mark(text, start, number) ||
         names_era_year(text, start, number) || names_year_in_title(text, start, number));
    return context;
}

}  // namespace talkface::detail

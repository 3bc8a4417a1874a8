#include "text/digit_codes.hpp"

#include <algorithm>
#include <array>
#include <string_view>

#include "text/dates_and_times.hpp"
#include "text/latin_words.hpp"
#include "text/number_words.hpp"
#include "text/web_addresses.hpp"

namespace talkface::detail {

namespace {

// Names of a service, said with its number: before it (客服热线10086) or after it (110报警).
constexpr std::string_view kServiceWords[] = {"报警", "報警", "急救", "火警", "查号", "查號", "热线", "熱線", "电话",
                                              "電話", "服务", "服務", "客服", "求助", "救护", "救護", "平台", "平臺",
                                              "专线", "專線", "中心", "号码", "號碼"};

// The letters after a graphics card's four digits, NVIDIA's (GT, GTS, GTX, Ti) and AMD's (XT, XTX),
// that name the digits a card's model (9800 GT 九八零零, 4090 Ti, 7900 XTX; session 27), in small
// letters: a suffix is matched whatever its case (is_card_suffix_at).
constexpr std::string_view kGraphicsCardSuffixes[] = {"gt", "gts", "gtx", "ti", "xt", "xtx"};

// A phone number's groups of digits, each said digit by digit with 幺 for 1; a group too long to be
// read as a number carries the warning (once).
void append_phone_groups(SpokenForm& form, const std::vector<std::string>& groups) {
    form.is_dialled = true;
    for (const auto& group : groups) {
        form.words += digit_words(group, true);
        if (group.size() > kMostCardinalDigits && form.warning.empty()) form.warning = kTooLongWarning;
    }
}

// Whether text[i] is inside a licence plate's letters and digits, after its province's character, a capital
// and the middle dot (沪A·8K321): the digits after a letter there are the plate's too, said one by one
// (八 K 三二一; session 21: 三百二十一).
bool in_licence_plate(const std::vector<CodePoint>& text, std::size_t i) {
    while (i > 0 && (is_ascii_letter(value_at(text, i - 1)) || is_digit_at(text, i - 1))) --i;
    return i >= 3 && is_one_of(text[i - 1].value, U"\u00B7\u30FB") && is_ascii_capital(text[i - 2].value) &&
           text[i - 3].value >= 0x4E00 && text[i - 3].value <= 0x9FFF;
}

// The capitals of a model's name right before text[start], with nothing, a hyphen or a space
// between (C919, A380, B-52, RTX 4090), or the middle dot of a licence plate (京A·12345, where the
// digits are a name as a model's are): one to three capitals that start a word and are spelled
// (TOP in TOP 10 is the word top, a rank: latin_words.hpp), not after a digit (4K 120帧: the 4K is
// a quantity, and 120 counts) but inside a licence plate (沪A·8K321). Empty where there are none.
std::string model_name_before(const std::vector<CodePoint>& text, std::size_t start) {
    auto i = start;
    if (i > 0 && is_one_of(text[i - 1].value, U"- \u00B7\u30FB")) --i;
    std::string capitals;
    while (i > 0 && is_ascii_capital(value_at(text, i - 1))) {
        --i;
        capitals.insert(capitals.begin(), static_cast<char>(ascii_form(text[i].value)));
    }
    constexpr std::size_t kMostCapitals = 3;
    const bool starts_word = i == 0 ||
                             !(is_ascii_letter(value_at(text, i - 1)) || is_digit_at(text, i - 1)) ||
                             in_licence_plate(text, i);
    if (capitals.size() > kMostCapitals || is_said_as_word(capitals) || !starts_word) return {};
    // An index's name, whose number is its value (AQI 152 一百五十二, CPI 102; session 17: 一五二).
    for (const std::string_view index : {"AQI", "CPI", "PPI", "PMI", "BMI"})
        if (capitals == index) return {};
    return capitals;
}

}  // namespace

bool names_by_digits(char32_t c) {
    return is_one_of(c, U"室房路号號");
}

bool names_room_or_building(const std::vector<CodePoint>& text, std::size_t end) {
    constexpr std::size_t kLongestWord = 3;  // characters: 会议室, 办公室
    if (end >= text.size() || takes_liang(text[end].value)) return false;
    for (std::size_t k = end; k < std::min(text.size(), end + kLongestWord); ++k)
        if (is_one_of(text[k].value, U"室")) return true;
    const auto word = text_between(text, end, end + 2);
    return word == "大楼" || word == "大樓" || word == "大厦" || word == "大廈";
}

bool names_landmark_after_city(const std::vector<CodePoint>& text, std::size_t start,
                               const WrittenNumber& number) {
    constexpr std::size_t kFewestDigits = 3;
    constexpr std::size_t kMostDigits = 4;
    // A round thousand counts, as after a model's capitals (上海3000 三千).
    if (number.has_point || number.has_separators || number.whole.size() < kFewestDigits ||
        number.whole.size() > kMostDigits || ends_with(number.whole, "000")) {
        return false;
    }
    const auto next = value_at(text, number.end);
    if (takes_liang(next) || is_one_of(next, U"多余餘来來几幾强強以%") || is_ascii_letter(next)) return false;
    // A city the country's news and its posts name landmarks after; its 市 may be written too.
    auto before = text_between(text, start >= 4 ? start - 4 : 0, start);
    if (ends_with(before, "市")) before.erase(before.size() - std::string_view("市").size());
    return ends_with_any(
        before, {"北京", "上海", "天津", "重庆", "重慶", "广州", "廣州", "深圳", "杭州", "南京", "武汉",
                 "武漢", "成都", "西安", "长沙", "長沙", "苏州", "蘇州", "郑州", "鄭州", "青岛", "青島",
                 "厦门", "廈門", "大连", "大連", "沈阳", "瀋陽", "济南", "濟南", "香港", "澳门", "澳門",
                 "台北", "臺北", "新北", "台中", "臺中", "台南", "臺南", "高雄", "桃园", "桃園", "新竹",
                 "东京", "東京", "首尔", "首爾", "纽约", "紐約", "伦敦", "倫敦", "巴黎"});
}

bool names_meeting_place(const std::vector<CodePoint>& text, std::size_t start, const WrittenNumber& number) {
    constexpr std::size_t kFewestDigits = 3;
    constexpr std::size_t kMostDigits = 4;
    const auto& whole = number.whole;
    if (number.has_point || number.has_separators || whole.size() < kFewestDigits ||
        whole.size() > kMostDigits || ends_with(whole, "00") ||
        (whole.size() == kMostDigits && starts_with_any(whole, {"19", "20"})) || start == 0 ||
        !is_one_of(text[start - 1].value, U"在"))
        return false;
    return starts_with_any(text_between(text, number.end, number.end + 2),
                           {"见", "見", "碰面", "碰頭", "碰头", "会合", "會合", "等你", "等妳", "等我"});
}

bool is_service_number(const std::string& digits) {
    for (const std::string_view number : {"110", "112", "114", "119", "120", "122", "999", "12110", "12117", "12121",
                                          "12123", "12306", "12308", "12309", "12315", "12318", "12320", "12328", "12333",
                                          "12338", "12345", "12348", "12355", "12358", "12365", "12366", "12369", "12378",
                                          "12380", "12388", "12393", "12395", "10000", "10010", "10086"})
        if (digits == number) return true;
    return digits.size() == 5 && starts_with_any(digits, {"95", "96"});
}

bool is_named_anywhere(const std::string& digits) {
    return digits.size() == 5 && digits != "12345" && digits != "10000";
}

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
    // The service answering names itself (您好，这里是110; session 40: 一百一十), as its operator does.
    if (ends_with_any(before, {"这里是", "這裡是", "這裏是", "这边是", "這邊是"})) return true;
    const std::string after = text_between(text, end, end + 2);
    for (const std::string_view word : kServiceWords)
        if (starts_with(after, word)) return true;
    return false;
}

bool follows_name_word(const std::vector<CodePoint>& text, std::size_t start) {
    std::size_t i = start;
    // A card's number in groups of three or more digits with a space between (会员卡号：6228 4800 1234 5678)
    // is named by the word before its first group (session 19: the groups after it counted).
    constexpr std::size_t kFewestGroupDigits = 3;
    while (i > 0 && text[i - 1].value == ' ') {
        auto k = i - 1;
        while (k > 0 && is_digit_at(text, k - 1)) --k;
        if (i - 1 - k < kFewestGroupDigits) break;
        i = k;
    }
    for (int skipped = 0; skipped < 2 && i > 0 && is_one_of(text[i - 1].value, U" 是为為：:\u3000"); ++skipped) --i;
    if (i > 0 && is_one_of(text[i - 1].value, U"号號室房码碼")) return true;
    if (follows_book_number(text, start)) return true;
    // A postcode after 邮编 (邮编100080 一零零零八零; session 14: it counted), as 邮政编码 is after 码.
    if (const auto word = text_between(text, i >= 2 ? i - 2 : 0, i); word == "邮编" || word == "郵編") return true;
    // The building's number may carry its 号 (5号楼1201 五号楼一二零一; session 19: 一千二百零一).
    if (start >= 2 && is_one_of(text[start - 1].value, U"楼樓栋棟层層")) {
        const auto number_end = is_one_of(text[start - 2].value, U"号號") ? start - 2 : start - 1;
        if (number_end >= 1 && is_digit_at(text, number_end - 1)) return true;
    }
    const auto staircase = text_between(text, start >= 2 ? start - 2 : 0, start);
    if ((staircase == "单元" || staircase == "單元") && start >= 3 && is_digit_at(text, start - 3))
        return true;
    // A room's number after its wing's, block's or area's letter (A座803 ei 座八零三, C座2107, A区305;
    // session 31: counted, 八百零三), as after a building's number; a round hundred there counts
    // (C区200个车位).
    // So after a building named by a word in 楼 (东楼408 东楼四零八, 教学楼203; session 32: counted), where
    // no measure word, unit or 多 余 after the number counts it (大楼632米).
    const bool after_lettered_wing = start >= 2 && is_one_of(text[start - 1].value, U"座区區栋棟楼樓") &&
                                     is_ascii_capital(text[start - 2].value) &&
                                     (start == 2 || !is_ascii_letter(value_at(text, start - 3)));
    const bool after_named_building =
        start >= 2 && is_one_of(text[start - 1].value, U"楼樓") && is_han(text[start - 2].value);
    if (!after_lettered_wing && !after_named_building) return false;
    auto end = start;
    const auto digits = digits_from(text, end);
    constexpr std::size_t kFewestRoomDigits = 3;
    constexpr std::size_t kMostRoomDigits = 4;
    const auto next = value_at(text, end);
    return digits.size() >= kFewestRoomDigits && digits.size() <= kMostRoomDigits &&
           !ends_with(digits, "00") && next != '.' &&
           (after_lettered_wing || !(takes_liang(next) || is_one_of(next, U"多余餘")));
}

bool precedes_hotline_word(const std::vector<CodePoint>& text, std::size_t end) {
    return starts_with_any(text_between(text, end, end + 2), {"热线", "熱線", "专线", "專線"});
}

bool follows_phone_word(const std::vector<CodePoint>& text, std::size_t start) {
    const std::string before = text_before(text, start, false);
    if (contains_any(before, {"电话", "電話", "手机", "手機", "热线", "熱線", "拨打", "撥打", "致电", "致電",
                              "分机", "分機", "传真", "傳真", "座机", "座機", "固话", "固話"}))
        return true;
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

bool follows_book_number(const std::vector<CodePoint>& text, std::size_t start) {
    auto i = start;
    for (int skipped = 0; skipped < 2 && i > 0 && is_one_of(text[i - 1].value, U" ：:"); ++skipped) --i;
    constexpr std::size_t kNameLetters = 4;
    if (i < kNameLetters || (i > kNameLetters && is_ascii_letter(value_at(text, i - kNameLetters - 1))))
        return false;
    const auto name = text_between(text, i - kNameLetters, i);
    return name == "ISBN" || name == "ISSN";
}

std::optional<SpokenForm> read_dashed_digits(const std::vector<CodePoint>& text, const WrittenNumber& first,
                                             bool is_phone, bool is_named, bool is_book) {
    if (first.has_point || first.has_separators) return std::nullopt;
    std::vector<std::string> groups{first.whole};
    auto i = first.end;
    while (is_dash(value_at(text, i)) && is_digit_at(text, i + 1)) {
        ++i;
        groups.push_back(digits_from(text, i));
    }
    // An area code and a number have seven digits or more (02-23456789, 010-12345678); 0-0 and 0-3
    // are a score's or a range's (session 15: 0-0 was said 零零).
    constexpr std::size_t kFewestPhoneDigits = 7;
    std::size_t digit_count = 0;
    for (const auto& group : groups) digit_count += group.size();
    const bool looks_like_phone =
        (first.whole.front() == '0' && digit_count >= kFewestPhoneDigits) || groups.size() >= 3 || is_phone;
    if (groups.size() < 2 || !looks_like_phone) return std::nullopt;
    SpokenForm form;
    // A code's groups after its name (取件码3-2-1108 三杠二杠一一零八, a parcel's shelf, layer and number;
    // session 19: dialled, 三二幺幺零八): no phone number starts with a group of one or two digits
    // without a leading zero, so they are read out as a code's parts are, the dash 杠.
    constexpr std::size_t kLongestShelf = 2;
    if ((is_named && !is_phone && groups.size() >= 3 && first.whole.size() <= kLongestShelf &&
         first.whole.front() != '0') ||
        is_book) {
        for (const auto& group : groups) form.words += (form.words.empty() ? "" : "杠") + digit_words(group);
        form.end = i;
        return form;
    }
    append_phone_groups(form, groups);
    form.end = i;
    return form;
}

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

namespace {

// Whether the sentence around text[start] speaks of a standard or of working by one (标准 规范 规程 导则 按
// 依据 执行 符合 参照 评定 检定): capitals outside the list name a standard only there, where elsewhere they
// may name a league or a currency before a range (CBA 2023-2024赛季, RMB 1000-2000).
bool speaks_of_standard(const std::vector<CodePoint>& text, std::size_t start) {
    const std::string sentence = text_before(text, start, false) + text_after(text, start, false);
    return contains_any(sentence,
                        {"标准", "標準", "规范", "規範", "规程", "規程", "导则", "導則", "按",   "依据",
                         "依據", "执行", "執行", "符合", "参照", "參照", "评定", "評定", "检定", "檢定"});
}

// The prefixes a standard's number is written after: China's national standards (GB, and GB/T a
// recommended one) and the international, European and national bodies news cites (ISO 9001:2015).
// Any capitals with /T or /Z after them are a Chinese standard's too (YY/T, NY/T, JT/T: an industry's
// recommended or guiding standard), so those need no list, and so are a province's local standard, DB and
// its two digits (DB11/T 1234-2015), and a body's group standard after T/ (T/CAS 115-2005; session 32: the
// year was a range's end). Two or three capitals and a space before the number are an industry's or a
// metrology code's mandatory standard (JJF 1059.1-2012, as China writes its industry codes, two capitals,
// and its metrology's, three) where the sentence speaks of a standard (`spaced_in_standard_talk`).
bool is_standard_prefix(const std::string& letters, bool spaced_in_standard_talk) {
    const auto capitals = [](std::string_view part, std::size_t fewest) {
        return part.size() >= fewest &&
               std::all_of(part.begin(), part.end(), [](char c) { return is_ascii_capital(c); });
    };
    if (ends_with(letters, "/T") || ends_with(letters, "/Z")) {
        const auto body = std::string_view(letters).substr(0, letters.size() - 2);
        const auto code = body.substr(0, body.find_last_not_of("0123456789") + 1);
        return capitals(code, code.size() < body.size() ? 2 : 1);
    }
    if (starts_with_any(letters, {"T/"})) return capitals(std::string_view(letters).substr(2), 2);
    for (const std::string_view body : {"GB", "ISO", "IEC", "ISO/IEC", "EN", "BS", "DIN", "JIS", "ANSI"})
        if (letters == body) return true;
    constexpr std::size_t kLongestCode = 3;
    return spaced_in_standard_talk && letters.size() <= kLongestCode && capitals(letters, 2);
}

}  // namespace

std::optional<SpokenForm> read_standard_code(const std::vector<CodePoint>& text, std::size_t start,
                                             const WrittenNumber& number) {
    constexpr std::size_t kFewestCodeDigits = 3;
    constexpr std::size_t kYearDigits = 4;
    constexpr std::size_t kLongestPart = 2;
    // A part's number after a point (GB/T 1.1-2020, JJF 1059.1-2012) is said after 点 as a version's is; one
    // after a dash with the year after a colon (EN 71-3:2019, IEC 62368-1:2018; session 32: 七十一到三) after
    // 杠, as the year after a dash is. A number of one part has three digits or more.
    // A part may have a part of its own (IEC 60335-2-29:2019 六零三三五杠二杠二九二零一九, a household
    // appliance's particular rules; session 33: a code's digits run together and the year a ratio's).
    constexpr std::size_t kMostParts = 2;
    std::vector<std::string> parts;
    auto part_end = number.end;
    while (parts.size() < kMostParts && is_dash(value_at(text, part_end)) &&
           is_digit_at(text, part_end + 1)) {
        auto k = part_end + 1;
        auto part = digits_from(text, k);
        if (part.size() > kLongestPart) break;
        parts.push_back(std::move(part));
        part_end = k;
    }
    if (ascii_form(value_at(text, part_end)) != ':') parts.clear();
    if (number.has_separators ||
        (!number.has_point && parts.empty() && number.whole.size() < kFewestCodeDigits))
        return std::nullopt;
    auto letters = start;
    const bool spaced = letters > 0 && text[letters - 1].value == ' ';
    if (spaced) --letters;
    const auto prefix_end = letters;
    while (letters > 0 && (is_ascii_capital(text[letters - 1].value) || text[letters - 1].value == '/' ||
                           is_digit_at(text, letters - 1)))
        --letters;
    if (letters == prefix_end || (letters > 0 && is_ascii_letter(text[letters - 1].value)))
        return std::nullopt;
    if (!is_standard_prefix(text_between(text, letters, prefix_end),
                            spaced && speaks_of_standard(text, start)))
        return std::nullopt;
    const auto year_mark = parts.empty() ? number.end : part_end;
    const auto mark = ascii_form(value_at(text, year_mark));
    if (!is_dash(mark) && mark != ':') return std::nullopt;
    auto end = year_mark + 1;
    const auto year = digits_from(text, end);
    if (year.size() != kYearDigits || !starts_with_any(year, {"19", "20"}) || value_at(text, end) == '.')
        return std::nullopt;
    // After ISO two sensitivities, the second higher, are a camera's range (ISO 100-2000 一百到两千; session
    // 33: a standard of 2000, 一零零杠二零零零).
    if (is_dash(mark) && is_camera_sensitivity(text, start, number.whole) &&
        is_camera_sensitivity(text, start, year) && std::stoul(year) > std::stoul(number.whole))
        return std::nullopt;
    SpokenForm form;
    form.words = digit_words(number.whole) + (number.has_point ? "点" + digit_words(number.fraction) : "");
    for (const auto& part : parts) form.words += "杠" + digit_words(part);
    form.words += (is_dash(mark) ? "杠" : "") + digit_words(year);
    form.end = end;
    return form;
}

std::optional<SpokenForm> read_series_and_model(const std::vector<CodePoint>& text, std::size_t start,
                                                const WrittenNumber& first) {
    constexpr std::size_t kMostSeriesCharacters = 2;
    if (first.has_point || first.has_separators || first.whole.size() > kMostSeriesCharacters ||
        !is_dash(value_at(text, first.end))) {
        return std::nullopt;
    }
    auto letters = start;
    while (letters > 0 && is_ascii_letter(value_at(text, letters - 1))) --letters;
    if (letters == start || start - letters > kMostSeriesCharacters) return std::nullopt;
    auto k = first.end + 1;
    const auto model = digits_from(text, k);
    constexpr std::size_t kFewestModelDigits = 3;
    if (model.size() < kFewestModelDigits || !is_ascii_capital(value_at(text, k))) return std::nullopt;
    SpokenForm form;
    form.words = cardinal_words(first.whole, false) + digit_words(model);
    form.end = k;
    return form;
}

std::optional<SpokenForm> read_model_variant(const std::vector<CodePoint>& text, std::size_t start,
                                             const WrittenNumber& model) {
    constexpr std::size_t kFewestModelDigits = 3;
    if (model.has_point || model.has_separators || model.whole.size() < kFewestModelDigits ||
        !is_dash(value_at(text, model.end)) || !is_digit_at(text, model.end + 1)) {
        return std::nullopt;
    }
    auto k = model.end + 1;
    const auto variant = digits_from(text, k);
    // ISO names no maker's model: after it a higher number is the top of a camera's range of sensitivities
    // (ISO 100-400 一百到四百; session 32: 一零零四百, A320-200's variant), as a lower one is a standard's
    // part.
    const bool rises = variant.size() > model.whole.size() ||
                       (variant.size() == model.whole.size() && variant > model.whole);
    if (rises && model_name_before(text, start) == "ISO") return std::nullopt;
    constexpr std::size_t kLongestVariant = 4;
    const bool is_round = variant.size() >= 3 && variant.size() <= kLongestVariant &&
                          variant.front() != '0' && variant.compare(variant.size() - 2, 2, "00") == 0;
    // Or one digit, a variant of a newer family (737-8, 777-9: 七三七八; session 21: a score between names,
    // 七百三十七比八).
    const bool is_digit_variant = variant.size() == 1 && variant != "0";
    if (!(is_round || is_digit_variant) || value_at(text, k) == '.') return std::nullopt;
    SpokenForm form;
    form.words = digit_words(model.whole) + cardinal_words(variant, false);
    form.end = k;
    return form;
}

bool follows_model_name(const std::vector<CodePoint>& text, std::size_t start) {
    return !model_name_before(text, start).empty();
}

bool follows_model_name_and_number(const std::vector<CodePoint>& text, std::size_t start, std::size_t end) {
    constexpr std::size_t kMostLineDigits = 2;
    if (start < 2 || text[start - 1].value != ' ' || is_han(value_at(text, end))) return false;
    auto line = start - 1;
    while (line > 0 && is_digit_at(text, line - 1)) --line;
    return line < start - 1 && start - 1 - line <= kMostLineDigits && follows_model_name(text, line);
}

bool is_filter_grade(const std::vector<CodePoint>& text, std::size_t start, const std::string& digits) {
    const auto capitals = model_name_before(text, start);
    const bool filter_class = capitals == "N" || capitals == "R" || capitals == "P" || capitals == "KN" || capitals == "KP";
    // An enclosure's protection rating (IP68 IP六八, IP54): its two digits rate dust (0-6) and water
    // (0-9) apart, and are said so (session 16: IP六十八).
    const bool rates_protection = capitals == "IP" && digits.size() == 2 && digits.front() <= '6';
    return rates_protection || (filter_class && (digits == "90" || digits == "95" || digits == "99"));
}

bool is_camera_sensitivity(const std::vector<CodePoint>& text, std::size_t start, const std::string& digits) {
    // ISO 12232's sensitivities, which cameras write after ISO: 100 doubled for each full stop (200 ... 3200,
    // 6400, 102400) and 125 and 160 doubled for the thirds between, written 1250 from 1280 on (2500, 5000);
    // below 100 the extended stop, 50, and its thirds, 64 and 80 (ISO 50-51200; session 33: 五一二零零).
    // The standards news cites after ISO (9001, 14001, 8601, 639, 3166) lie off that series and stay codes.
    constexpr std::array<unsigned long, 3> kSeriesStarts = {100, 125, 1250};
    constexpr std::array<unsigned long, 6> kThirdsBefore1250 = {50, 64, 80, 160, 320, 640};
    constexpr std::size_t kMostDigits = 7;
    if (digits.empty() || digits.size() > kMostDigits || digits.front() == '0' ||
        model_name_before(text, start) != "ISO")
        return false;
    const auto value = std::stoul(digits);
    if (std::find(kThirdsBefore1250.begin(), kThirdsBefore1250.end(), value) != kThirdsBefore1250.end())
        return true;
    return std::any_of(kSeriesStarts.begin(), kSeriesStarts.end(), [value](unsigned long first) {
        if (value % first != 0) return false;
        const auto doublings = value / first;
        return (doublings & (doublings - 1)) == 0;
    });
}

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

bool names_code_by_letters(const std::vector<CodePoint>& text, std::size_t start,
                           const WrittenNumber& number) {
    const auto digits = number.whole.size();
    if (number.has_point || number.has_separators || digits < 3 || digits > 4) return false;
    auto i = start;
    if (i > 0 && is_dash(value_at(text, i - 1))) --i;
    if (i < start || is_dash(value_at(text, i))) {
        bool has_capital = false;
        while (i > 0 && is_ascii_letter(value_at(text, i - 1))) {
            --i;
            has_capital = has_capital || is_ascii_capital(text[i].value);
        }
        // A memory's speed after its generation's letter (LPDDR5X-7500 七千五百, as DDR5-6400's; session 32:
        // 七五零零) counts.
        auto generation = i;
        while (generation > 0 && is_digit_at(text, generation - 1)) --generation;
        const bool after_generation =
            generation < i &&
            ends_with(text_between(text, generation >= 3 ? generation - 3 : 0, generation), "DDR");
        if (has_capital && !after_generation) return true;
    }
    if (digits != 4) return false;
    return is_card_suffix_at(text, value_at(text, number.end) == ' ' ? number.end + 1 : number.end);
}

bool is_card_suffix_at(const std::vector<CodePoint>& text, std::size_t i) {
    std::string suffix;
    for (auto k = i; is_ascii_letter(value_at(text, k)); ++k)
        suffix += static_cast<char>(ascii_form(text[k].value));
    return is_any_of(ascii_lower_case(suffix), kGraphicsCardSuffixes);
}

bool follows_card_model(const std::vector<CodePoint>& text, std::size_t start) {
    constexpr std::size_t kModelDigits = 4;
    auto k = start;
    if (k > 0 && value_at(text, k - 1) == ' ') --k;
    std::size_t digits = 0;
    while (k > 0 && is_digit_at(text, k - 1)) {
        --k;
        ++digits;
    }
    return digits == kModelDigits && (k == 0 || value_at(text, k - 1) != '.') &&
           is_card_suffix_at(text, start);
}

namespace {

// Four digits shaped as a graphics card's number, its series and its tier each followed by 0 (4090, 3060,
// 1080): a count so shaped is rare beside a card, and a round count (2000) is not one.
bool has_card_shape(const std::string& digits) {
    constexpr std::size_t kCardDigits = 4;
    return digits.size() == kCardDigits && digits[0] != '0' && digits[1] == '0' && digits[2] != '0' &&
           digits[3] == '0';
}

}  // namespace

bool repeats_card_model(const std::vector<CodePoint>& text, std::size_t start, const WrittenNumber& number) {
    if (number.has_point || number.has_separators || !has_card_shape(number.whole) ||
        (start > 0 && (is_ascii_letter(text[start - 1].value) || is_digit_at(text, start - 1))) ||
        is_one_of(value_at(text, number.end), U"元圆块塊年人个個次米分秒"))
        return false;
    for (auto k = start; k > 0 && !is_one_of(text[k - 1].value, U"。！？!?\n");) {
        auto first = k;
        while (first > 0 && is_digit_at(text, first - 1)) --first;
        if (first == k) {
            --k;
            continue;
        }
        if (k - first == number.whole.size() && !is_digit_at(text, k) && follows_model_name(text, first) &&
            has_card_shape(text_between(text, first, k)))
            return true;
        k = first;
    }
    return false;
}

bool follows_maker_name(const std::vector<CodePoint>& text, std::size_t start) {
    auto i = start;
    if (i > 0 && text[i - 1].value == ' ') --i;
    // A chip's model after its series' tier, a capital glued to its digits (Ryzen 9 9950X 九九五零 X, 锐龙5
    // 8600G; session 31: 九千九百五十): the tier's digit and its space stand between the maker and the model.
    auto model_end = start;
    while (is_digit_at(text, model_end)) ++model_end;
    if (i < start && i >= 2 && is_digit_at(text, i - 1) && !is_digit_at(text, i - 2) &&
        is_ascii_capital(value_at(text, model_end))) {
        i -= 1;
        if (text[i - 1].value == ' ') --i;
    }
    const auto before = text_between(text, i >= 2 ? i - 2 : 0, i);
    for (const std::string_view maker :
         {"波音", "空客", "麦道", "麥道", "商飞", "商飛", "天玑", "天璣", "骁龙", "驍龍", "麒麟",
          "鲲鹏", "鯤鵬", "昇腾", "昇騰", "飞腾", "飛騰", "龙芯", "龍芯", "锐龙", "銳龍"})
        if (before == maker) return true;
    // The same makers and series in Latin letters, as English copy and spec sheets write them.
    constexpr std::string_view kLatinMakers[] = {"boeing",    "airbus", "snapdragon",
                                                 "dimensity", "kirin",  "ryzen"};
    auto first = i;
    while (first > 0 && is_ascii_letter(value_at(text, first - 1))) --first;
    return first < i && is_any_of(ascii_lower_case(text_between(text, first, i)), kLatinMakers);
}

namespace {

// Three or more digits after a port's or an error's word (端口改成8080 八零八零, 错误502 五零二, 报错1001,
// HTTP 404), with 是 为 ： an opening bracket (报错(404); session 43: 四百零四) or a verb that sets it (改成
// 改为 设为) between, or an HTTP status (400 to 599) that a page or a server shows (页面显示404 四零四): a
// code read out, as a tutorial's presenter reads it.
bool names_port_or_error(const std::vector<CodePoint>& text, std::size_t start, const std::string& digits) {
    constexpr std::size_t kFewestDigits = 3;
    if (digits.size() < kFewestDigits) return false;
    auto word_end = start;
    for (int skipped = 0;
         skipped < 2 && word_end > 0 && is_one_of(text[word_end - 1].value, U" 是为為：:(\uFF08"); ++skipped)
        --word_end;
    for (const std::string_view verb : {"改成", "改为", "改為", "设为", "設為", "设置为", "設置為"}) {
        const auto characters = verb.size() / std::string_view("为").size();
        if (word_end >= characters && text_between(text, word_end - characters, word_end) == verb) {
            word_end -= characters;
            break;
        }
    }
    const auto word = text_between(text, word_end >= 4 ? word_end - 4 : 0, word_end);
    if (ends_with_any(word, {"端口", "埠", "错误", "錯誤", "代码", "代碼", "报错", "報錯", "故障", "error",
                             "Error", "HTTP"}))
        return true;
    const bool is_status = digits.size() == kFewestDigits && (digits.front() == '4' || digits.front() == '5');
    if (!is_status || !ends_with_any(word, {"显示", "顯示", "提示", "返回", "报", "報", "出现", "出現"}))
        return false;
    const auto sentence =
        text_before(text, start, false) + text_between(text, start, std::min(text.size(), start + 20));
    for (const std::string_view place :
         {"页面", "頁面", "网页", "網頁", "网站", "網站", "链接", "鏈接", "連結", "服务器", "伺服器",
          "浏览器", "瀏覽器", "接口", "请求", "請求"})
        if (sentence.find(place) != std::string::npos) return true;
    return false;
}

}  // namespace

bool names_by_its_digits(const std::vector<CodePoint>& text, std::size_t start, const WrittenNumber& number) {
    if (number.has_point || number.has_separators) return false;
    const auto& digits = number.whole;
    if (names_port_or_error(text, start, digits)) return true;
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
    // A code with its exchange's suffix, in brackets or not (港股00700.HK; session 15).
    if (digits.size() >= kShortestCode && digits.size() <= kLongestCode && past_exchange_suffix(text, number.end) != number.end)
        return true;
    const auto before = text_between(text, start >= 2 ? start - 2 : 0, start);
    if (before == "日经" || before == "日經") return true;
    // A share's code after its exchange's or its board's name (北交所920099 九二零零九九, 科创板688256,
    // 创业板300059; session 31: counted), as after 港股: five or six digits, no word counting shares, firms
    // or points after them (a measure word may begin the next word: 成交额, 盘中).
    constexpr std::size_t kShortestShareCode = 5;
    if (digits.size() >= kShortestShareCode && digits.size() <= kLongestCode &&
        !is_one_of(value_at(text, number.end), U"%万萬亿億多余餘只隻家个個股元点點") &&
        ends_with_any(text_between(text, start >= 3 ? start - 3 : 0, start),
                      {"交所", "港股", "科创板", "科創板", "创业板", "創業板", "沪市", "滬市", "深市"}))
        return true;
    constexpr std::size_t kShortestCellFormat = 4;
    constexpr std::size_t kLongestCellFormat = 5;
    if (digits.size() >= kShortestCellFormat && digits.size() <= kLongestCellFormat &&
        !ends_with(digits, "000") &&
        starts_with_any(text_between(text, number.end, number.end + 3),
                        {"电池", "電池", "电芯", "電芯", "锂电", "鋰電", "圆柱", "圓柱", "大圆柱", "大圓柱"}))
        return true;
    if (digits.size() != 3) return false;
    auto end = number.end;
    // Past the rest of a list of such numbers (985、211高校) to the word they share; a slash lists them too
    // (985/211高校 九八五二一一; session 32: 二百一十一分之九百八十五, a fraction).
    while (is_one_of(ascii_form(value_at(text, end)), U"\u3001/") && is_digit_at(text, end + 1)) {
        auto k = end + 1;
        if (digits_from(text, k).size() != 3) return false;
        end = k;
    }
    const auto after = text_between(text, end, end + 2);
    for (const std::string_view word : {"工程", "计划", "計劃", "高校", "院校", "名校", "大学", "大學"})
        if (after == word) return true;
    // Or the third such name, 双一流, which the schools of the list share with them, listed too or not
    // (985/211双一流高校, 985/211/双一流高校).
    if (is_one_of(ascii_form(value_at(text, end)), U"\u3001/")) ++end;
    return names_top_schools(text, end);
}

bool names_top_schools(const std::vector<CodePoint>& text, std::size_t k) {
    return starts_with_any(text_between(text, k, k + 3), {"双一流", "雙一流"});
}

bool follows_software_name(const std::vector<CodePoint>& text, std::size_t start) {
    if (start == 0) return false;
    // A version named as one (新版本13.24 十三点二十四, 版本号：2.3.10; session 16: 十三点二四).
    auto word_end = start;
    for (int skipped = 0; skipped < 2 && word_end > 0 && is_one_of(text[word_end - 1].value, U" 是为為：:"); ++skipped)
        --word_end;
    for (const std::string_view word : {"版本", "版本号", "版本號"})
        if (ends_with(text_between(text, word_end >= 3 ? word_end - 3 : 0, word_end), word)) return true;
    if (is_one_of(value_at(text, start - 1), U"vV")) return start == 1 || !is_ascii_letter(value_at(text, start - 2));
    // A small letter and a capital alone (pH 7.35) are a quantity's letters, spelled, whose value follows
    // (session 35: 七点三十五, a version's).
    const bool after_quantity_letters = start >= 3 && is_ascii_capital(value_at(text, start - 2)) &&
                                        is_ascii_letter(value_at(text, start - 3)) &&
                                        !is_ascii_capital(value_at(text, start - 3)) &&
                                        (start == 3 || !is_ascii_letter(value_at(text, start - 4)));
    return value_at(text, start - 1) == ' ' && start >= 2 && is_ascii_letter(value_at(text, start - 2)) &&
           follows_glued_name(text, start - 1) && !after_quantity_letters;
}

bool follows_designation(const std::vector<CodePoint>& text, std::size_t dash) {
    if (dash == 0) return false;
    if (is_one_of(text[dash - 1].value, U"歼殲运運轰轟直教")) return true;
    const auto before = text_between(text, dash >= 2 ? dash - 2 : 0, dash);
    for (const std::string_view name : {"东风", "東風", "长征", "長征", "红旗", "紅旗", "鹰击", "鷹擊", "巨浪", "空警",
                                        "霹雳", "霹靂", "快舟"})
        if (before == name) return true;
    return false;
}

bool follows_element(const std::vector<CodePoint>& text, std::size_t start) {
    // The elements whose names are one character, Simplified and Traditional, but gold, silver, copper,
    // iron, tin and lead, whose names are common words too (黄金999 is a purity, 地铁 a railway).
    constexpr std::u32string_view kElements =
        U"氢氦锂铍硼碳氮氧氟氖钠镁铝硅磷硫氯氩钾钙钪钛钒铬锰钴镍锌镓锗砷硒溴氪铷锶钇锆铌钼锝钌铑钯镉铟锑碲碘氙"
        U"铯钡镧铈镨钕钷钐铕钆铽镝钬铒铥镱镥铪钽钨铼锇铱铂汞铊铋钋砹氡钫镭锕钍镤铀镎钚镅锔锫锎锿镄钔锘铹"
        U"鋰鈹鈉鎂鋁矽鉀鈣鈧鈦釩鉻錳鈷鎳鋅鎵鍺銣鍶釔鋯鈮鉬鎝釕銠鈀鎘銦銻碲銫鋇鑭鈰鐠釹鉕釤銪釓鋱鏑鈥鉺銩鐿鎦"
        U"鉿鉭鎢錸鋨銥鉑鉈鉍釙砈鍅鐳錒釷鏷鈾錼鈽鋂鋦鉳鉲鑀鐨鍆鍩鐒";
    return start > 0 && kElements.find(text[start - 1].value) != std::u32string_view::npos;
}

bool is_train_number(const std::vector<CodePoint>& text, std::size_t start, std::size_t end) {
    if (start < 1 || !is_one_of(value_at(text, start - 1), U"GDCZTKLYS") ||
        (start >= 2 && is_ascii_letter(value_at(text, start - 2)))) {
        return false;
    }
    const std::string before = text_before(text, start, true);
    return is_one_of(value_at(text, end), U"次") || contains_any(before, {"车次", "車次"});
}

bool is_unlettered_train_number(const std::vector<CodePoint>& text, std::size_t start, std::size_t end) {
    constexpr std::size_t kLongestTrainNumber = 4;
    if (end - start > kLongestTrainNumber ||
        (start > 0 && (is_ascii_letter(value_at(text, start - 1)) || is_digit_at(text, start - 1))))
        return false;
    // A train's kind as Taiwan's railway and the mainland's timetables name it, or a train: 自強號123次,
    // 123次自強號, 區間車2101次, 普快1461次, 1461次列车. Not 火车, which follows a count of rides too
    // (坐了100次火车).
    constexpr std::string_view kKinds[] = {"自強號", "自强号", "莒光號", "莒光号", "復興號", "复兴号",
                                           "區間車", "区间车", "區間快", "区间快", "普悠瑪", "普悠玛",
                                           "太魯閣", "太鲁阁", "普快",   "列車",   "列车"};
    auto before = start;
    while (before > 0 && is_one_of(value_at(text, before - 1), U" ：:")) --before;
    const auto word_before = text_between(text, before >= 3 ? before - 3 : 0, before);
    if (ends_with_any(word_before, {"車次", "车次"})) return true;
    const auto after = text_between(text, end, end + 2);
    if (after == "車次" || after == "车次") return true;
    if (value_at(text, end) != U'次') return false;
    return ends_with_any(word_before, kKinds) ||
           starts_with_any(text_between(text, end + 1, end + 4), kKinds);
}

// An airline's code of a digit and a capital (3U 四川航空, 9C 春秋航空, 8L), standing as a word before
// text[start]: model_name_before reads capitals only (session 34: 3U8633 counted, 八千六百三十三).
bool follows_digit_airline_code(const std::vector<CodePoint>& text, std::size_t start) {
    return start >= 2 && is_ascii_capital(value_at(text, start - 1)) && is_digit_at(text, start - 2) &&
           (start == 2 || !(is_ascii_letter(value_at(text, start - 3)) || is_digit_at(text, start - 3)));
}

bool is_flight_number(const std::vector<CodePoint>& text, std::size_t start, std::size_t end) {
    const auto digit_count = end - start;
    if ((model_name_before(text, start).size() != 2 && !follows_digit_airline_code(text, start)) ||
        digit_count < 3 || digit_count > 4)
        return false;
    const std::string after = text_between(text, end, end + 3);
    const std::string before = text_before(text, start, true);
    for (const std::string_view word : {"航班", "班机", "班機"}) {
        if (starts_with(after, word) || starts_with(after, std::string("次") + std::string(word)) ||
            before.find(word) != std::string::npos) {
            return true;
        }
    }
    return false;
}

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
    // A year of the Republic (113.10.15 一百一十三年十月十五日, as Taiwan's notices date them; session 16:
    // a version, 一百一十三点十点十五), but not after a software's name (Firefox 115.3.1 is its version).
    const bool dates = groups[0].size() == 4 || (is_republic_year(groups[0]) && !follows_software_name(text, start) &&
                                                 !follows_glued_name(text, start));
    if (groups.size() == 3 && dates && is_month_and_day(groups[1], groups[2])) {
        form.words = said_year(groups[0]) + cardinal_words(groups[1], false) + "月" + cardinal_words(groups[2], false) + "日";
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
    // A port after the address and a colon (192.168.0.1:8080 冒号八零八零), digit by digit as the address is.
    constexpr std::size_t kMostPortDigits = 5;
    if (is_ip_address && value_at(text, i) == ':' && is_digit_at(text, i + 1)) {
        auto k = i + 1;
        const auto port = digits_from(text, k);
        if (port.size() <= kMostPortDigits && !is_digit_at(text, k)) {
            form.words += "冒号" + digit_words(port);
            form.end = k;
        }
    }
    return form;
}

bool is_named_service_number(const std::string& digits) {
    return is_named_anywhere(digits) && is_service_number(digits);
}

std::size_t past_exchange_suffix(const std::vector<CodePoint>& text, std::size_t end) {
    if (value_at(text, end) != '.') return end;
    auto k = end + 1;
    std::string letters;
    while (is_ascii_capital(value_at(text, k))) letters += static_cast<char>(value_at(text, k++));
    return is_exchange_suffix(letters) && !is_ascii_letter(value_at(text, k)) && !is_digit_at(text, k) ? k : end;
}

bool names_seat_before(const std::vector<CodePoint>& text, std::size_t start) {
    // A unit's reader asks after the row and its letter, the floor's reader before them.
    auto row = start;
    while (row > 0 && (is_ascii_digit(text[row - 1].value) || is_ascii_letter(text[row - 1].value))) --row;
    if (row > 0 && text[row - 1].value == U'在') --row;
    if (row > 0 && text[row - 1].value == U'坐') return true;
    return contains_any(text_before(text, start, true),
                        {"座位", "座号", "座號", "座席", "位子", "选座", "選座", "登机牌", "登機牌", "值机",
                         "值機", "靠窗", "靠过道", "靠過道", "靠走道"});
}

std::optional<SpokenForm> read_floor(const std::vector<CodePoint>& text, std::size_t start, const WrittenNumber& number) {
    constexpr std::size_t kMostFloorDigits = 3;
    // Hong Kong writes the floor with a slash, 3/F, 12/F, G/F.
    const auto letter = value_at(text, number.end) == '/' ? number.end + 1 : number.end;
    if (number.has_point || number.has_separators || number.whole.size() > kMostFloorDigits ||
        number.whole.front() == '0' || (start > 0 && is_ascii_letter(value_at(text, start - 1))) ||
        value_at(text, letter) != 'F' || is_ascii_letter(value_at(text, letter + 1)) ||
        is_digit_at(text, letter + 1)) {
        return std::nullopt;
    }
    // A seat's row and letter (您的座位是7车12F号 十二 F 号, 3号车厢12F座): 号 or 座 after it, or a
    // carriage right before it (7车, 3号车厢).
    const bool after_carriage =
        start >= 2 &&
        ((is_one_of(text[start - 1].value, U"车車") && is_digit_at(text, start - 2)) ||
         (is_one_of(text[start - 2].value, U"车車") && is_one_of(text[start - 1].value, U"厢廂")));
    if (is_one_of(value_at(text, letter + 1), U"号號座") || after_carriage || names_seat_before(text, start))
        return std::nullopt;
    SpokenForm form;
    form.words = cardinal_words(number.whole, false) + "楼";
    form.end = letter + 1;
    return form;
}

std::optional<SpokenForm> read_masked_number(const std::vector<CodePoint>& text, const WrittenNumber& number,
                                             bool is_phone) {
    const auto is_star = [&](std::size_t k) { return ascii_form(value_at(text, k)) == '*'; };
    if (number.has_point || number.has_separators || !is_star(number.end) || !is_star(number.end + 1))
        return std::nullopt;
    std::vector<std::string> groups{number.whole};
    std::size_t places = number.whole.size();
    auto end = number.end;
    while (is_star(end)) {
        std::size_t stars = 0;
        while (is_star(end)) {
            ++stars;
            ++end;
        }
        places += stars;
        groups.emplace_back(stars, '*');
        if (is_digit_at(text, end)) {
            groups.push_back(digits_from(text, end));
            places += groups.back().size();
        }
    }
    constexpr std::size_t kMobilePlaces = 11;
    const bool is_dialled = is_phone || (places == kMobilePlaces && number.whole.front() == '1');
    SpokenForm form;
    form.is_dialled = is_dialled;
    for (const auto& group : groups) {
        if (group.front() == '*') {
            for (std::size_t k = 0; k < group.size(); ++k) form.words += "星";
        } else {
            form.words += digit_words(group, is_dialled);
        }
    }
    form.end = end;
    return form;
}

std::optional<SpokenForm> read_masked_tail(const std::vector<CodePoint>& text, std::size_t start) {
    const auto is_star = [&](std::size_t k) { return ascii_form(value_at(text, k)) == '*'; };
    if (!is_star(start) || !is_star(start + 1) ||
        (start > 0 && (is_star(start - 1) || is_digit_at(text, start - 1))))
        return std::nullopt;
    auto end = start;
    while (is_star(end)) ++end;
    if (!is_digit_at(text, end)) return std::nullopt;
    SpokenForm form;
    form.is_dialled = follows_phone_word(text, start);
    form.words = digit_words(digits_from(text, end), form.is_dialled);
    form.end = end;
    return form;
}

}  // namespace talkface::detail

#include "text/measure_or_verb.hpp"

#include "text/count_words.hpp"
#include "text/written_number_scan.hpp"

namespace talkface::detail {

namespace {

// What a measure word follows: a count (count_words.hpp, and 多 多少 每 各 数 若干) or a demonstrative (这 那
// 哪 何 某 此 该).
bool ends_in_count(std::string_view word) {
    constexpr std::string_view kOtherCounts[] = {"多", "多少", "每", "各", "数", "數", "若干", "这",
                                                 "這", "那",   "哪", "何", "某", "此", "该",   "該"};
    return ends_with_count(word) || ends_with_any(word, kOtherCounts);
}

}  // namespace

std::string_view measure_or_verb_reading(const std::vector<std::string>& words, std::size_t w,
                                         bool follows_number) {
    if (w >= words.size()) return {};
    const auto& word = words[w];
    if (word == "教") return "jiao1";
    // The run's first word counts what a written number right before the run says (2只猫).
    const bool after_count = w > 0 ? ends_in_count(words[w - 1]) : follows_number;
    // A run of characters starts after what is not one: a written number may count 种 there (3种, 第3种,
    // 10多种), so there it keeps the table's measure word.
    if (word == "种" || word == "種") return after_count ? "zhong3" : w == 0 ? "" : "zhong4";
    // The list joins 只 to a noun it counts (只猫 只狗, from 一只猫), and to what the adverb zhǐ starts.
    constexpr std::string_view kOnly[] = {"只是", "只有", "只要", "只能",   "只好", "只得", "只需",
                                          "只怕", "只管", "只顾", "只不过", "只见", "只因"};
    if (after_count && starts_with_any(word, {"只"}) && !starts_with_any(word, kOnly)) return "zhi1";
    // 量 is measured, liáng, where it takes a count of times, an aspect particle or what a body is
    // measured for (量一下 量了体温 各量一次血压); the amount, liàng, is 量 ending a word (数量 大量) or
    // after 的 (这批货的量一共多少).
    constexpr std::string_view kMeasured[] = {"一",   "了",   "过",   "過",   "着",   "著",   "体温", "體溫",
                                              "血压", "血壓", "身高", "体重", "體重", "尺寸", "腰围", "腰圍"};
    const bool modified = w > 0 && ends_with_any(words[w - 1], {"的"});
    if (word == "量" && !modified && w + 1 < words.size() && starts_with_any(words[w + 1], kMeasured)) {
        return "liang2";
    }
    const std::string_view next = w + 1 < words.size() ? std::string_view(words[w + 1]) : std::string_view();
    // 切 is cut, qiē, where no word covers it (切薄片 切肉); qiè is its words' (一切 亲切 密切), the adverb's
    // before a warning (切不可 切莫 切勿 切忌 切记), and names' before 尔 (切尔西 撒切尔 切尔诺贝利).
    constexpr std::string_view kKeepsQie[] = {"不", "莫", "勿", "忌", "记", "記", "尔", "爾"};
    if (word == "切") return starts_with_any(next, kKeepsQie) ? "" : "qie1";
    // 撒 is strewn, sǎ, before how much or what a cook strews or where it lands (撒葱花 撒点盐 撒上 撒在);
    // sā, the table's, is cast or let go, in its words and names (撒网 撒手 撒谎 撒哈拉).
    constexpr std::string_view kStrewn[] = {"上",   "入",   "在",   "点",   "點",   "些", "少许", "少許",
                                            "适量", "適量", "一",   "盐",   "鹽",   "糖", "葱",   "蔥",
                                            "芝麻", "胡椒", "孜然", "面粉", "麵粉", "粉", "香菜"};
    if ((word == "撒" && starts_with_any(next, kStrewn)) || word == "撒在") return "sa3";
    return {};
}

}  // namespace talkface::detail

#include "text/must_verb.hpp"

#include "text/count_words.hpp"
#include "text/person_words.hpp"
#include "text/written_number_scan.hpp"

namespace talkface::detail {

namespace {

constexpr std::string_view kMust = "得";

// 多 or 少 before a verb and the little more or less of it (多放点 少吃些 多穿一点): what is to be
// done, which 得 "must" binds whoever does it (这道菜得多放点盐). 得 the particle after an adjective
// takes 多 of degree and no verb after it (好得多, 长得多好看), and after a verb 多 or 少 and the
// complement's 一 or 了 before 点 or 些 (放得多了些, 晒得少一些).
bool starts_more_or_less_of_verb(std::string_view rest) {
    constexpr auto kVerb = std::string_view("多").size();
    constexpr auto kVerbEnd = kVerb + std::string_view("放").size();
    if (!starts_with_any(rest, {"多", "少"}) || rest.size() <= kVerbEnd) return false;
    return !is_any_of(rest.substr(kVerb, kVerbEnd - kVerb), {"一", "了"}) &&
           starts_with_any(rest.substr(kVerbEnd), {"点", "點", "些", "一点", "一點", "一些"});
}

// A written number after 得 (他得100分): a clock's time or a span after it is when or how long what must
// be done takes (我得5点起床, 我得3天内完成: děi); anything else it counts is what is got (dé), as a count
// in characters is.
std::string_view reading_before_written_number(std::string_view written) {
    std::size_t digits = 0;
    while (digits < written.size() && written[digits] >= '0' && written[digits] <= '9') ++digits;
    if (digits == 0) return {};
    constexpr std::string_view kTimes[] = {":",    "点", "點", "时", "時", "分钟", "分鐘", "小时",
                                           "小時", "天", "号", "號", "周", "週",   "个月", "個月"};
    return starts_with_any(written.substr(digits), kTimes) ? "dei3" : "de2";
}

}  // namespace

std::string_view must_verb_reading(const std::vector<std::string>& words, std::size_t w,
                                   std::string_view written_after) {
    if (w >= words.size() || !starts_with_any(words[w], {kMust})) return {};
    std::string rest = words[w].substr(kMust.size());
    for (auto k = w + 1; k < words.size(); ++k) rest += words[k];
    if (starts_more_or_less_of_verb(rest)) return "dei3";
    if (w == 0 || words[w] != kMust || !is_person_word(words[w - 1])) return {};
    if (w + 1 == words.size()) return reading_before_written_number(written_after);
    // What dé, "get", takes: a particle, 的 of what was got, 到, 不 of 得不到, a count or a place, or a
    // prize, which is won and never done (她得冠军了, 他得金牌了).
    constexpr std::string_view kAfterGet[] = {"了",   "过",   "過",   "着",   "著",   "的",   "到",   "不",
                                              "个",   "個",   "第",   "满",   "滿",   "冠",   "亚军", "亞軍",
                                              "季军", "季軍", "金牌", "银牌", "銀牌", "铜牌", "銅牌", "奖",
                                              "獎",   "金奖", "金獎", "银奖", "銀獎", "铜奖", "銅獎"};
    return starts_with_any(words[w + 1], kAfterGet) || starts_with_count(words[w + 1]) ? "de2" : "dei3";
}

}  // namespace talkface::detail

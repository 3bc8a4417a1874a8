#include "text/quantity_copula.hpp"

#include "text/count_words.hpp"
#include "text/written_number_scan.hpp"

namespace talkface::detail {

namespace {

// A share written with its percent sign that closes its clause (45.1%, 45.1%，): a value, which nothing
// after 为 "for" is (为50%的家庭提供补贴: the share counts whom it is for).
bool is_share_closing_clause(std::string_view written) {
    std::size_t end = 0;
    while (end < written.size() && ((written[end] >= '0' && written[end] <= '9') || written[end] == '.'))
        ++end;
    if (end == 0) return false;
    const auto rest = written.substr(end);
    for (const auto sign : {std::string_view("%"), std::string_view("％")}) {
        if (rest.substr(0, sign.size()) != sign) continue;
        const auto after = rest.substr(sign.size());
        return after.empty() || starts_with_any(after, {"，", "。", "、", "；", "！", "？", ",", ";", "!",
                                                        "?", ".", " ", "）", ")", "\n"});
    }
    return false;
}

}  // namespace

std::string_view quantity_copula_reading(const std::vector<std::string>& words, std::size_t w,
                                         bool ends_clause, std::string_view written_after) {
    constexpr std::string_view kCopulas[] = {"为", "為"};
    if (w == 0 || w >= words.size() || !starts_with_any(words[w], kCopulas)) return {};
    // A share closing the clause right after 为 is its value whatever noun 为 follows (对手为45.1%).
    if (words[w].size() == kCopulas[0].size() && w + 1 == words.size() &&
        is_share_closing_clause(written_after))
        return "wei2";
    constexpr std::string_view kQuantities[] = {"率", "度", "值", "价", "價", "量", "额", "額",
                                                "温", "溫", "速", "重", "润", "潤", "入", "数",
                                                "數", "积", "積", "差", "压", "壓", "高"};
    if (!ends_with_any(words[w - 1], kQuantities)) return {};
    constexpr std::string_view kValueStarts[] = {"每", "约", "約", "负", "負", "零"};
    const auto starts_value = [&](std::string_view word) {
        return starts_with_count(word) || starts_with_any(word, kValueStarts);
    };
    // The list joins 为 to what may follow it (为每 为零): the rest of its word starts the value.
    const auto rest = std::string_view(words[w]).substr(std::string_view("为").size());
    const bool number_follows = !rest.empty()           ? starts_value(rest)
                                : w + 1 == words.size() ? !ends_clause
                                                        : starts_value(words[w + 1]);
    return number_follows ? "wei2" : "";
}

}  // namespace talkface::detail

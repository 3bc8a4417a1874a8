#include "text/take_as.hpp"

#include "text/written_number_scan.hpp"

namespace talkface::detail {

namespace {

// A verb that chooses or names someone or something as what 为 says: one of choosing, ending in 选
// (当选 评选 改选 推选 票选 遴选: the list's 选为 is wéi), or of appointing, naming or judging.
bool chooses_or_names(std::string_view word) {
    constexpr std::string_view kNaming[] = {"任命", "命名", "推举", "推舉", "提名", "聘请", "聘請", "聘任",
                                            "册封", "冊封", "追认", "追認", "认定", "認定", "评定", "評定",
                                            "鉴定", "鑒定", "判定", "界定", "核定", "选定", "選定"};
    return ends_with_any(word, {"选", "選"}) || is_any_of(word, kNaming);
}

}  // namespace

std::string_view take_as_reading(const std::vector<std::string>& words, std::size_t w) {
    if (w == 0 || w >= words.size() || !starts_with_any(words[w], {"为", "為"})) return {};
    // The list joins 为 to what may follow it (为重 为主), but 为了 为什么 为何 are "for" and "why".
    if (starts_with_any(words[w], {"为了", "為了", "为什么", "為什麼", "为何", "為何", "为着", "為著"}))
        return {};
    if (chooses_or_names(words[w - 1])) return "wei2";
    for (std::size_t before = 0; before + 1 < w; ++before)
        if (words[before] == "以") return "wei2";
    return {};
}

}  // namespace talkface::detail

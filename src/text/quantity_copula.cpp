#include "text/quantity_copula.hpp"

#include "text/count_words.hpp"
#include "text/written_number_scan.hpp"

namespace talkface::detail {

std::string_view quantity_copula_reading(const std::vector<std::string>& words, std::size_t w,
                                         bool ends_clause) {
    constexpr std::string_view kCopulas[] = {"为", "為"};
    if (w == 0 || w >= words.size() || !starts_with_any(words[w], kCopulas)) return {};
    constexpr std::string_view kQuantities[] = {"率", "度", "值", "价", "價", "量",
                                                "额", "額", "温", "溫", "速", "重"};
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

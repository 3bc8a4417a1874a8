#include "text/title_head.hpp"

#include "text/written_number_scan.hpp"

namespace talkface::detail {

std::string_view title_head_reading(const std::vector<std::string>& words, std::size_t w) {
    if (w == 0 || w >= words.size() || (words[w] != "长" && words[w] != "長")) return {};
    // A one-character word before it was cut so by the words around it (城 市 长...): not a name.
    const auto& before = words[w - 1];
    constexpr std::size_t kOneCharacter = std::string_view("市").size();
    if (before.size() <= kOneCharacter) return {};
    constexpr std::string_view kHeaded[] = {"市", "省", "县", "縣", "区", "區", "镇", "鎮", "乡", "鄉",
                                            "村", "州", "局", "部", "厅", "廳", "处", "處", "科", "院",
                                            "校", "所", "厂", "廠", "社", "团", "團", "队", "隊", "组",
                                            "組", "站", "馆", "館", "会", "會", "司"};
    return ends_with_any(before, kHeaded) ? "zhang3" : "";
}

}  // namespace talkface::detail

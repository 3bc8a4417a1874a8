#include "text/script_variant.hpp"

#include <algorithm>
#include <utility>

namespace talkface::detail {

namespace {

// Common characters written differently in the two scripts, pairwise: position k of each is one
// word. Characters both scripts use (台 后 里 只) are left out, so that neither side counts them.
constexpr std::u32string_view kSimplifiedOnly =
    U"们个这会说时国对学来为书点两万亿号电话几么还过请开门长东车见机关发经变种让钱湾气温与从体问题听欢乐买卖进华"
    U"实现业务员语线区当报纸头应该条场动汉阳红风云飞鸟鱼马龙"
    // Words of addresses, buildings and notices, so that a short line of Taiwan's or Hong Kong's
    // (台北101大樓89F觀景台, 1樓大廳見) is told by them (session 16: it had none of the above).
    U"楼观厅厦馆价际专询处码邮编统营厂层"
    // And of payments, dates and notices (繳費期限：99/12/31前; session 17: it had none of the above).
    U"缴费于预约办单证";
constexpr std::u32string_view kTraditionalOnly =
    U"們個這會說時國對學來為書點兩萬億號電話幾麼還過請開門長東車見機關發經變種讓錢灣氣溫與從體問題聽歡樂買賣進華"
    U"實現業務員語線區當報紙頭應該條場動漢陽紅風雲飛鳥魚馬龍"
    U"樓觀廳廈館價際專詢處碼郵編統營廠層"
    U"繳費於預約辦單證";

// The characters of the written forms' readings that Traditional writes otherwise.
constexpr std::pair<std::string_view, std::string_view> kReadingCharacters[] = {
    {"两", "兩"}, {"万", "萬"}, {"亿", "億"}, {"点", "點"}, {"负", "負"}, {"时", "時"}, {"钟", "鐘"},
    {"吨", "噸"}, {"摄", "攝"}, {"华", "華"}, {"兹", "茲"}, {"号", "號"}, {"欧", "歐"}, {"镑", "鎊"},
    {"币", "幣"}, {"线", "線"}, {"划", "劃"}, {"杠", "槓"},
    {"楼", "樓"},  // a floor written nF (2F 二樓; session 15)
};

}  // namespace

bool is_traditional_text(const std::vector<CodePoint>& text) {
    static_assert(kSimplifiedOnly.size() == kTraditionalOnly.size(), "the two lists are pairwise");
    std::size_t simplified = 0, traditional = 0;
    for (const CodePoint& c : text) {
        if (c.value < 0x2E80) continue;
        if (kSimplifiedOnly.find(c.value) != std::u32string_view::npos) ++simplified;
        if (kTraditionalOnly.find(c.value) != std::u32string_view::npos) ++traditional;
    }
    return traditional > simplified;
}

bool writes_cantonese(const std::vector<CodePoint>& text) {
    constexpr std::u32string_view kCantoneseOnly = U"嘅咗喺哋嘢佢冇啲嚟睇噉";
    return std::any_of(text.begin(), text.end(), [&](const CodePoint& c) {
        return kCantoneseOnly.find(c.value) != std::u32string_view::npos;
    });
}

std::string traditional_form(std::string_view character) {
    for (const auto& [simplified, traditional] : kReadingCharacters)
        if (character == simplified) return std::string(traditional);
    return std::string(character);
}

}  // namespace talkface::detail

#include "text/aspect_particle.hpp"

#include <algorithm>
#include <iterator>
#include <string>

namespace talkface::detail {

namespace {

// One-character verbs that take an object and the particle 了 right after them (看了一本书),
// Simplified and Traditional. Verbs of motion, wish and degree words (去 来 想 要 很 多 不) are not
// here: before 了解 they introduce it (去了解情况).
constexpr std::string_view kVerbsTakingParticle[] = {
    "看", "听", "聽", "读", "讀", "写", "寫", "做", "作", "画", "畫", "唱", "讲", "講", "说", "說",
    "问", "問", "答", "学", "學", "教", "吃", "喝", "买", "買", "卖", "賣", "拿", "送", "给", "給",
    "打", "找", "查", "用", "收", "发", "發", "寄", "带", "帶", "开", "開", "修", "改", "接", "拍",
    "演", "选", "選", "借", "交", "翻", "抄", "背", "念"};

bool is_verb_taking_particle(std::string_view character) {
    return std::find(std::begin(kVerbsTakingParticle), std::end(kVerbsTakingParticle), character) !=
           std::end(kVerbsTakingParticle);
}

}  // namespace

bool may_start_word_here(const std::vector<std::string_view>& characters, std::size_t start, std::size_t end,
                         const ReadingTables& tables) {
    if (end - start < 2 || characters[start] != "了" || start == 0 || end >= characters.size()) return true;
    if (!is_verb_taking_particle(characters[start - 1])) return true;
    const std::string next_word = std::string(characters[end - 1]) + std::string(characters[end]);
    return tables.words.count(next_word) == 0;
}

std::string_view reading_before_particle(std::string_view word, std::string_view next, std::string_view after_next) {
    if ((word == "还" || word == "還") && next == "了" && after_next != "得") return "huan2";
    return {};
}

}  // namespace talkface::detail

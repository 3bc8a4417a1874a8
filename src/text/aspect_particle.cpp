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

std::string joined(const std::vector<std::string_view>& characters, std::size_t start, std::size_t end) {
    std::string word;
    for (auto k = start; k < end; ++k) word += characters[k];
    return word;
}

bool is_idiom_of_outrage(std::string_view word) {
    return word == "还了得" || word == "還了得" || word == "还得了" || word == "還得了";
}

// Where the idiom of outrage that ends the clause starts in the run, or npos: 这还得了, 那还了得吗.
std::size_t idiom_at_clause_end(const std::vector<std::string_view>& characters, bool ends_clause) {
    constexpr std::size_t kLength = 3;
    if (!ends_clause) return std::string::npos;
    for (const std::size_t after : {0, 1}) {
        if (characters.size() < kLength + after) continue;
        if (after == 1 && !is_final_particle(characters.back())) continue;
        const auto start = characters.size() - kLength - after;
        if (is_idiom_of_outrage(joined(characters, start, start + kLength))) return start;
    }
    return std::string::npos;
}

}  // namespace

bool is_final_particle(std::string_view character) {
    constexpr std::string_view kParticles[] = {"吗", "嗎", "啊", "呀", "呢", "吧", "啦", "哇"};
    return std::find(std::begin(kParticles), std::end(kParticles), character) != std::end(kParticles);
}

bool may_start_word_here(const std::vector<std::string_view>& characters, std::size_t start, std::size_t end,
                         const ReadingTables& tables, bool ends_clause) {
    const auto length = end - start;
    const auto word = length == 2 || length == 3 ? joined(characters, start, end) : std::string();
    // The idiom is a word only where it ends the clause, and there no word crosses into it
    // (這還 得了: the Traditional characters alone cost more than the words across them).
    const auto idiom = idiom_at_clause_end(characters, ends_clause);
    if (is_idiom_of_outrage(word)) return start == idiom;
    if (idiom != std::string::npos && start < idiom && end > idiom) return false;
    if ((word == "还得" || word == "還得") && end < characters.size() && characters[end] == "了") return false;
    if (end - start < 2 || characters[start] != "了" || start == 0 || end >= characters.size()) return true;
    if (!is_verb_taking_particle(characters[start - 1])) return true;
    const std::string next_word = std::string(characters[end - 1]) + std::string(characters[end]);
    return !tables.word(next_word);
}

std::string_view reading_before_particle(std::string_view word, std::string_view next) {
    if ((word == "还" || word == "還") && next == "了") return "huan2";
    if (word == "得" && next == "了") return "de2";
    return {};
}

}  // namespace talkface::detail

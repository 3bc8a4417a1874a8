#include "text/aspect_particle.hpp"

#include <algorithm>
#include <iterator>
#include <string>

#include "text/person_words.hpp"

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

// One-character verbs that take the potential complement 得了 (吃得了, 走得了, 来得了吗): those
// above, and verbs of motion, of bearing and of doing that take no particle before 了解. Not those
// whose 得 makes a word meaning "gain" (赢得了冠军, 获得了: 了 the particle).
constexpr std::string_view kVerbsTakingComplement[] = {
    "来", "來", "去", "走", "跑", "搬", "飞", "飛", "爬", "跳", "过", "過", "回", "进", "進", "出", "上", "下",
    "睡", "坐", "站", "住", "活", "干", "幹", "办", "辦", "管", "治", "忍", "扛", "撑", "撐", "赶", "趕", "救",
    "帮", "幫", "抬", "提", "穿", "戴", "跟", "逃", "躲", "离", "離"};

bool is_verb_taking_complement(std::string_view character) {
    return is_verb_taking_particle(character) ||
           std::find(std::begin(kVerbsTakingComplement), std::end(kVerbsTakingComplement), character) !=
               std::end(kVerbsTakingComplement);
}

std::string joined(const std::vector<std::string_view>& characters, std::size_t start, std::size_t end) {
    std::string word;
    for (auto k = start; k < end; ++k) word += characters[k];
    return word;
}

// Adverbs that the phrase list joins to 得 as a word (还得 hai2 dei3 "still must", 又得 也得 就得 都得 总得).
bool is_adverb_with_must(std::string_view word) {
    constexpr std::string_view kWords[] = {"还得", "還得", "又得", "也得", "就得", "都得", "总得", "總得"};
    return std::find(std::begin(kWords), std::end(kWords), word) != std::end(kWords);
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
    // 得 "must" (dei3) never takes 了, so an adverb with 得 is no word before it: 他又得了第一名, 他也得了奖,
    // 我们都得了感冒 are 得了 de2 le5 (got), as 他还得了第一名 is.
    if (is_adverb_with_must(word) && end < characters.size() && characters[end] == "了") return false;
    // The list's 你得 and 我得 (ni3 de5) are a person and 得, which must_verb.hpp reads by what follows it.
    if (length == 2 && characters[end - 1] == "得" && is_person_word(characters[start])) return false;
    if (end - start < 2 || characters[start] != "了" || start == 0 || end >= characters.size()) return true;
    if (!is_verb_taking_particle(characters[start - 1])) return true;
    const std::string next_word = std::string(characters[end - 1]) + std::string(characters[end]);
    return !tables.word(next_word);
}

bool is_potential_complement(const std::vector<std::string_view>& characters, const std::vector<std::size_t>& lengths,
                             std::size_t i) {
    if (i == 0 || i + 1 >= characters.size() || characters[i] != "得" || characters[i + 1] != "了" ||
        !is_verb_taking_complement(characters[i - 1])) {
        return false;
    }
    // The words holding 得 and 了: 得 alone, 得了, or the verb with 得 (吃得); 了 alone or in 得了.
    std::size_t start = 0;
    std::size_t w = 0;
    while (start + lengths[w] <= i) start += lengths[w++];
    const bool de_alone = lengths[w] == 1;
    const bool de_le = lengths[w] == 2 && start == i;
    const bool verb_de = lengths[w] == 2 && start + 1 == i;
    if (de_le) return true;
    return (de_alone || verb_de) && w + 1 < lengths.size() && lengths[w + 1] == 1;
}

std::string_view reading_before_particle(std::string_view word, std::string_view next) {
    if ((word == "还" || word == "還") && next == "了") return "huan2";
    if (word == "得" && next == "了") return "de2";
    // 数 alone takes a particle only as the verb shǔ, "count" (数了三遍, 数过); the noun shù is in words.
    if ((word == "数" || word == "數") && (next == "了" || next == "过" || next == "過")) return "shu3";
    return {};
}

}  // namespace talkface::detail

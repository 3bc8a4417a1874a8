#include "text/latin_words.hpp"

#include <algorithm>
#include <iterator>
#include <string>
#include <string_view>
#include <utility>

#include "common/internal_error.hpp"
#include "talkface/errors.hpp"
#include "text/code_points.hpp"
#include "text/embedded_text.hpp"

namespace talkface::detail {

namespace {

// The letter names most Mandarin speakers use (docs/letter-names.md); several take more than one
// syllable (F ai fu, W da bu liu).
const char* const kLetterNames[26] = {
    "ei1",         "bi4",      "xi1",     "di4",  "yi4",  "ai2 fu5", "ji4",     "ai1 qi1", "ai4",
    "zhei4",       "kei4",     "ai2 le5", "ai2 mu5", "en1", "ou1",  "pi1",     "qiu1",    "a4 er5",
    "ai2 si5",     "ti4",      "you1",    "wei1", "da2 bu5 liu5", "ai2 ke4 si5", "wai4", "zei4",
};

// Words Mandarin speakers say their own way, where the dictionary's mapping misses it or it lacks
// them (docs/written-forms.md): email is 伊妹儿 (the mapping of its first vowel gave "e"); COVID
// and SARS, written in capitals, are said as words (扣维德, 萨斯), not spelled; NVIDIA, which the
// dictionary lacks, is said by its Chinese name, 英伟达.
constexpr std::pair<std::string_view, std::string_view> kSaidOtherwise[] = {
    {"email", "yi1 mei4 er5"},
    {"e-mail", "yi1 mei4 er5"},
    // Session 24: mail alone and in a brand (Gmail, Hotmail) as in 伊妹儿, its tones kept; the mapping gave
    // mei, and since session 25 gives mei1 er5.
    {"mail", "mei4 er5"},
    {"covid", "kou1 wei2 de5"},
    {"sars", "sa4 si1"},
    {"nvidia", "ying1 wei3 da2"},
    // Session 13: Tesla, which the 1998 dictionary lacks, is 特斯拉 as Mandarin speakers say it; an
    // app is spelled, A P P, as mainland speakers say it (the dictionary's word gave a pu).
    {"tesla", "te4 si1 la1"},
    {"app", "ei1 pi1 pi1"},
    // OPPO, a brand written in capitals, is said as a word, 欧珀 (not spelled O P P O).
    {"oppo", "ou1 po1"},
    // Session 14: Google, which the 1998 dictionary lacks (it was go + ogle, gou ou ge), is said as its
    // Chinese name 谷歌 is, gu ge, as NVIDIA is 英伟达.
    {"google", "gu3 ge1"},
    // Session 15: sin is the sine of a formula (sin30°, sin x), said by its English name 赛因 sai yin
    // as classrooms say it; the dictionary's word, sin, gave xin. cos (kou si) and tan (the pinyin tan)
    // are said as written, as they are in class.
    {"sin", "sai4 yin1"},
    // Session 26: APEC, which the dictionary has as a word (ei pai ke), is spelled as Mandarin news and its
    // speakers spell it (APEC会议, APEC蓝): unlike OPEC 欧佩克, AIDS 艾滋 and SARS 萨斯 it has no loan said
    // as a word, only its Chinese name, 亚太经合组织, and its letters.
    {"apec", "ei1 pi1 yi4 xi1"},
    // Session 27: Elon, which the dictionary lacks (the mapping gave el + on, ai er an), is 埃隆 as Mandarin
    // news writes and says Elon Musk's name (埃隆·马斯克).
    {"elon", "ai1 long2"},
    // Qwen, which the dictionary lacks (the mapping gave qiu wan), is 千问 as Mandarin news says Alibaba's
    // models (通义千问, 千问2.5).
    {"qwen", "qian1 wen4"},
    // Session 28: TikTok, whose halves the dictionary lacks (generic speech of two syllables), is said as the
    // loans write Tik and Tok, 提克 ti ke and 托克 tuo ke (托克皮辛语, Tok Pisin).
    {"tiktok", "ti2 ke4 tuo1 ke4"},
    // Session 29: software and a platform as a service, SaaS and PaaS, are said as words, 萨斯 and 帕斯, as
    // SARS is (the mapping split them, Saa and S, de ai si); the dictionary lacks both.
    {"saas", "sa4 si1"},
    {"paas", "pa4 si1"},
    // Names in the news the dictionary lacks (generic speech with a warning) or maps far from how they are
    // said, said as Mandarin news writes them, as NVIDIA is 英伟达: OpenAI's Sora 索拉, Bezos 贝索斯,
    // Ethereum 以太坊, Zeekr 极氪, Redmi 红米 (the mapping gave ai de mi), and the chips' series by their
    // Chinese names, as 天玑9400 and 骁龙8 are written too: Dimensity 天玑, Snapdragon 骁龙 (the mapping gave
    // five syllables, si na pu da gen), Kirin 麒麟 (qi ren).
    {"sora", "suo3 la1"},
    {"bezos", "bei4 suo3 si1"},
    {"ethereum", "yi3 tai4 fang1"},
    {"zeekr", "ji2 ke4"},
    {"redmi", "hong2 mi3"},
    {"dimensity", "tian1 ji1"},
    {"snapdragon", "xiao1 long2"},
    {"kirin", "qi2 lin2"},
    // Session 30: markets, funds and rates that finance copy writes in capitals, said by the names Mandarin
    // finance says them by: NASDAQ 纳斯达克 and OPEC 欧佩克 (the dictionary's na zi da ke and ou pai ke),
    // REITs 瑞茨 (its ai ci), HIBOR 海博 (hai ba) and SHIBOR 希博 (generic speech: the dictionary lacks it).
    {"nasdaq", "na4 si1 da2 ke4"},
    {"opec", "ou1 pei4 ke4"},
    {"reits", "rui4 ci2"},
    {"hibor", "hai3 bo2"},
    {"shibor", "xi1 bo2"},
    // The WHO's public health emergency of international concern, PHEIC, said as the word it spells, fake
    // (费克), as the WHO's officials and Mandarin health news say it; the dictionary lacks it.
    {"pheic", "fei4 ke4"},
    // Infrastructure as a service is said by its letters, I A A S: no word is shared for it as SaaS 萨斯 and
    // PaaS 帕斯 are (the mapping split it, de ai si).
    {"iaas", "ai4 ei1 ei1 ai2 si5"},
    // A chip's generation, Gen (骁龙8 Gen 3), said as English says gen, J's sound (zhen, as the letter J is
    // zhei); the dictionary's entry gave three syllables, jie ne e.
    {"gen", "zhen1"},
    // Names of two parts joined by &, said by the Chinese names Mandarin news gives them (S&P 500 标普500,
    // P&G 宝洁); the reader joins the parts where this table has the whole.
    {"s&p", "biao1 pu3"},
    {"p&g", "bao3 jie2"},
    // Session 31: AMD's chips, Ryzen, by the Chinese name AMD gives them, 锐龙 (generic speech: the
    // dictionary lacks it), and blocs that world news writes in capitals but says by their Chinese names:
    // BRICS 金砖 (generic speech) and ASEAN 东盟 (the dictionary's e zi en), as NASDAQ is 纳斯达克.
    {"ryzen", "rui4 long2"},
    {"brics", "jin1 zhuan1"},
    {"asean", "dong1 meng2"},
    // Session 34: CRISPR, the gene-editing system, which the dictionary lacks (spelled, seven letters), is
    // said as English says it, crisper, and as Mandarin science news writes that, 克里斯珀; the dictionary's
    // crisper maps to qi si pa.
    {"crispr", "ke4 li3 si1 po4"},
    // Session 34: control, the key Ctrl names, as Mandarin speakers say it, 肯戳: English tr is an affricate
    // Mandarin hears as ch (Trump 川普); the mapping drops the r (ken tou). Git, which the dictionary lacks
    // (generic speech), is 吉特, as Mandarin tutorials say it (GitHub ji te ha bu).
    {"control", "ken3 chuo1"},
    {"git", "ji2 te4"},
    // Session 36: names that Mandarin speakers say by their Chinese names though the Latin is written, as
    // they say Google 谷歌: Android 安卓, as tech news and its readers say the system (安卓15; the mapping
    // gave an de lao de), and McLaren 迈凯伦, as F1 commentary says the team and the maker (me ke lai ren).
    // Which Latin names are said so is usage, not spelling: no packaged source records it (CC-CEDICT, not
    // packaged here, gives Chinese names as glosses for words read in English too, Facebook 脸书, Microsoft
    // 微软), so they are listed, each fixable in place (Android{an1 de5 luo2 yi1 de5}).
    {"android", "an1 zhuo2"},
    {"mclaren", "mai4 kai3 lun2"},
    // Session 38: a well-known foreign company is said by the Chinese name Mandarin news gives it, where it
    // has one: broadcasters were told in 2010 (SARFT's notice to CCTV and the provinces' stations, reported
    // by Sohu Sports on 7 April 2010 and Caixin on 19 April 2010) not to say foreign words and abbreviations
    // on air but the Chinese names. Airbus is 空客, as its Chinese arm names itself and news says it (the
    // mapping gave ai ba si); Boeing 波音 (the mapping's bo ying, a final off).
    {"airbus", "kong1 ke4"},
    {"boeing", "bo1 yin1"},
    // Session 40: boss is 波士 bo si as Mandarin speakers and players say it (BOSS战, 打Boss), the lips'
    // rounded o; the dictionary's American vowel gave ba si, which no speaker writes or says for it.
    {"boss", "bo1 si5"},
    // Session 45: sportswear makers by the Chinese names their shops and Mandarin speakers give them, as
    // Airbus is 空客: Nike 耐克 (the mapping gave nai qi) and Adidas 阿迪达斯 (it gave e di de si).
    {"nike", "nai4 ke4"},
    {"adidas", "a1 di2 da2 si1"},
};

// English words that product names, games and rankings write in capitals and Mandarin speakers
// say as words, read by the dictionary (TOP 10 top 十, PRO MAX, BOSS战, LOGO, HarmonyOS NEXT, and a video
// site's UP主, its uploader, a pu zhu, since session 14: it was spelled, you pi). Four or fewer
// capitals are otherwise spelled: the dictionary has WHO, LED, CIA, PET, CAD, RAM as words too,
// and those are acronyms in a Mandarin text, spelled (docs/written-forms.md).
constexpr std::string_view kWordsInCapitals[] = {"top", "max", "pro", "mini", "plus", "boss", "logo", "bug", "ace",
                                                   "next", "up"};

bool is_vowel_at(const std::string& lower, std::size_t i) {
    const char c = lower[i];
    if (c == 'y') return i > 0 && (i + 1 == lower.size() || std::string_view("aeiou").find(lower[i + 1]) == std::string_view::npos);
    return std::string_view("aeiou").find(c) != std::string_view::npos;
}

// Two consonants that start an English syllable together.
bool is_usual_onset(std::string_view pair) {
    constexpr std::string_view kOnsets[] = {"bl", "br", "cl", "cr", "dr", "fl", "fr", "gl", "gr", "pl", "pr", "tr",
                                            "sc", "sk", "sl", "sm", "sn", "sp", "st", "sw", "tw", "ch", "sh", "th",
                                            "ph", "wh", "wr", "qu"};
    return std::find(std::begin(kOnsets), std::end(kOnsets), pair) != std::end(kOnsets);
}

void append_words(std::vector<std::string>& syllables, std::string_view words) {
    for (const auto word : split_words(words)) syllables.emplace_back(word);
}

}  // namespace

const SortedLines& english_lines() {
    static const SortedLines lines(english_text());
    return lines;
}

std::vector<std::string> letter_syllables(std::string_view letters) {
    std::vector<std::string> syllables;
    for (const char letter : letters) {
        const char upper = letter >= 'a' && letter <= 'z' ? static_cast<char>(letter - 'a' + 'A') : letter;
        if (upper < 'A' || upper > 'Z') {
            throw internal_error(std::string("\"") + letter +
                                                 "\" is not a Latin letter");
        }
        append_words(syllables, kLetterNames[upper - 'A']);
    }
    return syllables;
}

std::vector<std::string> english_number_syllables(std::string_view digits) {
    constexpr std::string_view kOnes[] = {"zero",    "one",     "two",       "three",    "four",
                                          "five",    "six",     "seven",     "eight",    "nine",
                                          "ten",     "eleven",  "twelve",    "thirteen", "fourteen",
                                          "fifteen", "sixteen", "seventeen", "eighteen", "nineteen"};
    constexpr std::string_view kTens[] = {"", "", "twenty", "thirty", "forty", "fifty", "sixty", "seventy", "eighty", "ninety"};
    std::vector<std::string_view> words;
    while (digits.size() > 1 && digits.front() == '0') digits.remove_prefix(1);
    if (digits.size() > 2) {
        // A longer number is read digit by digit, 0 as "oh" (one oh one), as numbers are in English.
        for (const char digit : digits) words.push_back(digit == '0' ? "oh" : kOnes[digit - '0']);
    } else {
        const int value = digits.size() == 1 ? digits[0] - '0' : (digits[0] - '0') * 10 + (digits[1] - '0');
        if (value < 20) {
            words.push_back(kOnes[value]);
        } else {
            words.push_back(kTens[value / 10]);
            if (value % 10 != 0) words.push_back(kOnes[value % 10]);
        }
    }
    std::vector<std::string> syllables;
    for (const auto word : words) {
        const auto found = english_word_syllables(word);
        if (!found) throw internal_error("the English table lacks the number word \"" + std::string(word) + "\"");
        syllables.insert(syllables.end(), found->begin(), found->end());
    }
    return syllables;
}

bool is_all_capitals(std::string_view word) {
    return !word.empty() && std::all_of(word.begin(), word.end(), [](char letter) { return is_ascii_capital(letter); });
}

bool has_inner_acronym(std::string_view word) {
    for (std::size_t i = 0; i + 2 < word.size(); ++i) {
        if (word[i] >= 'a' && word[i] <= 'z' && is_ascii_capital(word[i + 1]) && is_ascii_capital(word[i + 2])) return true;
    }
    return false;
}

bool is_said_as_word(std::string_view word) {
    const std::string key = ascii_lower_case(word);
    return std::any_of(std::begin(kSaidOtherwise), std::end(kSaidOtherwise),
                       [&](const auto& entry) { return entry.first == key; }) ||
           std::find(std::begin(kWordsInCapitals), std::end(kWordsInCapitals), key) != std::end(kWordsInCapitals);
}

std::vector<std::string> spelled_syllables(std::string_view word) {
    const std::string lower = ascii_lower_case(word);
    // Groups of vowels: [first, end) in the word.
    std::vector<std::pair<std::size_t, std::size_t>> groups;
    for (std::size_t i = 0; i < lower.size(); ++i) {
        if (!is_vowel_at(lower, i)) continue;
        if (!groups.empty() && groups.back().second == i) {
            groups.back().second = i + 1;
        } else {
            groups.emplace_back(i, i + 1);
        }
    }
    // A final e after a consonant is silent (blade), unless it makes -le a syllable (table).
    const std::size_t n = lower.size();
    if (groups.size() > 1 && groups.back().first + 1 == n && lower[n - 1] == 'e' && !is_vowel_at(lower, n - 2) &&
        !(lower[n - 2] == 'l' && n >= 3 && !is_vowel_at(lower, n - 3)))
        groups.pop_back();
    std::vector<std::string> syllables;
    std::size_t start = 0;
    for (std::size_t g = 1; g < groups.size(); ++g) {
        const std::size_t before = groups[g - 1].second;
        const std::size_t onset = groups[g].first;
        std::size_t cut = onset;
        if (onset - before == 1) cut = onset - 1;
        if (onset - before >= 2) cut = is_usual_onset(std::string_view(lower).substr(onset - 2, 2)) ? onset - 2 : onset - 1;
        syllables.emplace_back(word.substr(start, cut - start));
        start = cut;
    }
    if (!groups.empty()) syllables.emplace_back(word.substr(start));
    return syllables;
}

namespace {

// Names a number follows, which the dictionary lacks, said as their fields say them: the Cas proteins of gene
// editing (Cas9, Cas12a) 卡斯. Apart from kSaidOtherwise, whose words are words in capitals too: CAS (T/CAS
// 115, an association's standard) stays spelled.
constexpr std::pair<std::string_view, std::string_view> kNamesBeforeNumbers[] = {
    {"cas", "ka3 si1"},
};

// The syllables `table` gives the word (any case), or nullopt.
template <std::size_t N>
std::optional<std::vector<std::string>> syllables_in(
    const std::pair<std::string_view, std::string_view> (&table)[N], std::string_view word) {
    const std::string key = ascii_lower_case(word);
    for (const auto& [spelled, said] : table) {
        if (key != spelled) continue;
        std::vector<std::string> syllables;
        append_words(syllables, said);
        return syllables;
    }
    return std::nullopt;
}

}  // namespace

std::optional<std::vector<std::string>> name_before_number_syllables(std::string_view word) {
    return syllables_in(kNamesBeforeNumbers, word);
}

std::optional<std::vector<std::string>> english_word_syllables(std::string_view word) {
    if (auto said = syllables_in(kSaidOtherwise, word)) return said;
    const std::string key = ascii_lower_case(word);
    const auto found = english_lines().find(key);
    if (!found) return std::nullopt;
    std::vector<std::string> syllables;
    append_words(syllables, *found);
    return syllables;
}

bool expands_abbreviation(std::string_view word, const std::vector<std::string>& syllables) {
    return syllables.size() > word.size();
}

std::optional<std::size_t> word_after_h(std::string_view word) {
    constexpr std::size_t kShortestWord = 3;
    const std::string lower = ascii_lower_case(word);
    for (std::size_t h = 2; h + kShortestWord <= lower.size(); ++h) {
        if (lower[h] != 'h' || lower[h - 1] == 'h' || is_vowel_at(lower, h - 1)) continue;
        bool has_vowel = false;
        for (std::size_t i = 0; i < h; ++i) has_vowel = has_vowel || is_vowel_at(lower, i);
        if (has_vowel && english_word_syllables(std::string_view(lower).substr(h))) return h;
    }
    return std::nullopt;
}

std::optional<std::vector<std::string>> two_word_syllables(std::string_view word, std::size_t shortest_part) {
    std::optional<std::vector<std::string>> best;
    std::size_t best_imbalance = word.size();
    for (auto split = word.size() < shortest_part ? 0 : word.size() - shortest_part; split >= shortest_part;
         --split) {
        const auto imbalance =
            split > word.size() - split ? 2 * split - word.size() : word.size() - 2 * split;
        if (best && imbalance >= best_imbalance) continue;
        auto first = english_word_syllables(word.substr(0, split));
        if (!first) continue;
        auto second = english_word_syllables(word.substr(split));
        if (!second) continue;
        first->insert(first->end(), second->begin(), second->end());
        best = std::move(first);
        best_imbalance = imbalance;
    }
    return best;
}

std::optional<std::vector<std::string>> capitals_of_words(std::string_view word) {
    constexpr std::size_t kShortestWord = 3;
    constexpr std::size_t kShortestWordAfterLetters = 4;
    constexpr std::size_t kMostLetters = 3;
    if (auto words = two_word_syllables(word, kShortestWord)) return words;
    for (std::size_t letters = 1;
         letters <= kMostLetters && letters + kShortestWordAfterLetters <= word.size(); ++letters) {
        if (auto rest = english_word_syllables(word.substr(letters))) {
            auto syllables = letter_syllables(word.substr(0, letters));
            syllables.insert(syllables.end(), rest->begin(), rest->end());
            return syllables;
        }
    }
    return std::nullopt;
}

std::optional<std::vector<std::string>> letter_and_word_syllables(std::string_view word) {
    constexpr std::size_t kShortestWord = 3;
    // Pairs that start an English word with a silent letter (know, gnome, psalm, pneumonia, rhyme), and a
    // name's Mc (McLaren), said Mac.
    constexpr std::string_view kOtherOnsets[] = {"kn", "gn", "ps", "pn", "rh", "mc"};
    const std::string lower = ascii_lower_case(word);
    if (lower.size() < 1 + kShortestWord || is_vowel_at(lower, 0) || is_vowel_at(lower, 1) || lower[1] == 'y')
        return std::nullopt;
    const auto pair = std::string_view(lower).substr(0, 2);
    if (is_usual_onset(pair) ||
        std::find(std::begin(kOtherOnsets), std::end(kOtherOnsets), pair) != std::end(kOtherOnsets))
        return std::nullopt;
    auto rest = english_word_syllables(word.substr(1));
    if (!rest) return std::nullopt;
    auto syllables = letter_syllables(word.substr(0, 1));
    syllables.insert(syllables.end(), rest->begin(), rest->end());
    return syllables;
}

}  // namespace talkface::detail

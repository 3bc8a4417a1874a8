// Pinyin syllable -> basic mouth shapes (thesis 5.2.2 with SPEC "Mouth shapes").
//
// The thesis works on bopomofo symbols: an initial, an optional medial (ㄧ ㄨ ㄩ) and a rime. Pinyin
// hides that split (y-, w-, -iu, -ui, -un, ju = jü, in = ㄧㄣ, ing = ㄧㄥ, ong = ㄨㄥ, iong = ㄩㄥ), so
// each syllable is first rewritten into initial + medial + rime, then each part gets its shapes
// and the rules of 5.2.2 run on the sequence.
#include <algorithm>
#include <array>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include "common/internal_error.hpp"
#include "common/string_ends.hpp"
#include "talkface/errors.hpp"
#include "talkface/lip_sync.hpp"

namespace talkface {
inline namespace v0 {

namespace {

using S = MouthShape;

// Every syllable in the readings of Unihan (kMandarin, kHanyuPinlu, kHanyuPinyin, kXHC1983,
// kTGHZ2013), toneless, u-umlaut as v: what the transcript reader can produce. Checking against a
// list, not only the rules, is what tells "bo" from "bü" or "fin".
constexpr std::string_view kSyllables =
    "a ai an ang ao ba bai ban bang bao bei ben beng bi bian biang biao bie bin bing bo bu ca "
    "cai can cang cao ce cei cen ceng cha chai chan chang chao che chen cheng chi chong chou chu "
    "chua chuai chuan chuang chui chun chuo ci cong cou cu cuan cui cun cuo da dai dan dang dao "
    "de dei den deng di dia dian diao die din ding diu dong dou du duan dui dun duo e ei en eng "
    "er fa fan fang fei fen feng fiao fo fou fu ga gai gan gang gao ge gei gen geng gong gou gu "
    "gua guai guan guang gui gun guo ha hai han hang hao he hei hen heng hm hng hong hou hu hua "
    "huai huan huang hui hun huo ji jia jian jiang jiao jie jin jing jiong jiu ju juan jue jun "
    "ka kai kan kang kao ke kei ken keng kong kou ku kua kuai kuan kuang kui kun kuo la lai lan "
    "lang lao le lei len leng li lia lian liang liao lie lin ling liu lo long lou lu luan lun "
    "luo lv lve m ma mai man mang mao me mei men meng mi mian miao mie min ming miu mo mou mu n "
    "na nai nan nang nao ne nei nen neng ng ni nia nian niang niao nie nin ning niu nong nou nu "
    "nuan nun nuo nv nve o ou pa pai pan pang pao pei pen peng pi pian piao pie pin ping po pou "
    "pu qi qia qian qiang qiao qie qin qing qiong qiu qu quan que qun r ran rang rao re ren reng "
    "ri rong rou ru rua ruan rui run ruo sa sai san sang sao se sen seng sha shai shan shang "
    "shao she shei shen sheng shi shou shu shua shuai shuan shuang shui shun shuo si song sou su "
    "suan sui sun suo ta tai tan tang tao te tei teng ti tian tiao tie ting tong tou tu tuan tui "
    "tun tuo wa wai wan wang wei wen weng wo wong wu xi xia xian xiang xiao xie xin xing xiong "
    "xiu xu xuan xue xun ya yan yang yao ye yi yin ying yo yong you yu yuan yue yun za zai zan "
    "zang zao ze zei zen zeng zha zhai zhan zhang zhao zhe zhei zhen zheng zhi zhong zhou zhu "
    "zhua zhuai zhuan zhuang zhui zhun zhuo zi zong zou zu zuan zui zun zuo \xC3\xAA";

constexpr std::string_view kECircumflex = "\xC3\xAA";  // ê, the e of ie / üe said alone

std::vector<std::string> split_syllables() {
    std::vector<std::string> result;
    std::istringstream in{std::string(kSyllables)};
    for (std::string word; in >> word;) result.push_back(word);
    std::sort(result.begin(), result.end());
    return result;
}

// SPEC table "initials": the initial's class.
S initial_shape(std::string_view initial) {
    if (initial == "zh" || initial == "ch" || initial == "sh" || initial == "r") return S::r;
    switch (initial.front()) {
        case 'b':
        case 'p':
        case 'm':
            return S::m;
        case 'f':
            return S::f;
        case 'd':
        case 't':
        case 'n':
        case 'l':
        case 'j':
        case 'q':
        case 'x':
            return S::h_prime;
        case 'g':
        case 'k':
        case 'h':
            return S::h;
        default:
            return S::z;  // z c s
    }
}

// SPEC: finals and compounds. "ê" is the e of ie and üe; "v" is ü.
std::vector<S> rime_shapes(std::string_view rime) {
    static const std::array<std::pair<std::string_view, std::vector<S>>, 17> table{{
        {"a", {S::a}},
        {"o", {S::o}},
        {"e", {S::h}},
        {kECircumflex, {S::e}},
        {"i", {S::i}},
        {"u", {S::u}},
        {"v", {S::u}},
        {"er", {S::h}},
        {"ai", {S::a, S::i}},
        {"ei", {S::e, S::i}},
        {"ao", {S::a, S::u}},
        {"ou", {S::o, S::u}},
        {"an", {S::a, S::n}},
        {"en", {S::h, S::n}},
        {"ang", {S::a, S::h}},
        {"eng", {S::h}},
        {"ong", {S::u, S::h}},
    }};
    for (const auto& [name, shapes] : table) {
        if (name == rime) return shapes;
    }
    throw detail::internal_error("no shapes for rime \"" + std::string(rime) + "\"");
}

struct BopomofoFinal {
    char medial;  // 'i', 'u', 'v' (ü) or 0
    std::string rime;
};

// A pinyin final (after y-, w-, -iu, -ui, -un and ju/qu/xu are undone) as medial + rime, the way
// bopomofo writes it: in = ㄧㄣ, ing = ㄧㄥ, iong = ㄩㄥ, ün = ㄩㄣ.
BopomofoFinal split_final(const std::string& final_text) {
    static const std::array<std::pair<std::string_view, BopomofoFinal>, 19> with_medial{{
        {"ia", {'i', "a"}},     {"io", {'i', "o"}},     {"ie", {'i', std::string(kECircumflex)}},
        {"iao", {'i', "ao"}},   {"iou", {'i', "ou"}},   {"ian", {'i', "an"}},
        {"in", {'i', "en"}},    {"iang", {'i', "ang"}}, {"ing", {'i', "eng"}},
        {"iong", {'v', "eng"}}, {"ua", {'u', "a"}},     {"uo", {'u', "o"}},
        {"uai", {'u', "ai"}},   {"uei", {'u', "ei"}},   {"uan", {'u', "an"}},
        {"uen", {'u', "en"}},   {"uang", {'u', "ang"}}, {"ueng", {'u', "eng"}},
        {"van", {'v', "an"}},
    }};
    for (const auto& [name, split] : with_medial) {
        if (name == final_text) return split;
    }
    if (final_text == "ve") return {'v', std::string(kECircumflex)};
    if (final_text == "vn") return {'v', "en"};
    return {0, final_text};
}

// y- and w- spell a medial (or the vowel itself) with no initial.
std::string final_of_zero_initial(const std::string& syllable) {
    if (syllable.front() == 'y') {
        const std::string rest = syllable.substr(1);
        if (rest == "i" || rest == "in" || rest == "ing") return rest;  // yi yin ying
        if (rest == "ong") return "iong";
        if (rest.front() == 'u') return "v" + rest.substr(1);  // yu yue yuan yun
        return "i" + rest;                                     // ya yo ye yao you yan yang
    }
    if (syllable.front() == 'w') {
        const std::string rest = syllable.substr(1);
        if (rest == "u") return rest;
        if (rest == "ong") return "ueng";
        return "u" + rest;  // wa wo wai wei wan wen wang weng
    }
    return syllable;
}

// The abbreviations of pinyin after an initial: iu = iou, ui = uei, un = uen, and u = ü after j q x.
std::string final_after_initial(std::string_view initial, std::string final_text) {
    const bool is_palatal = initial == "j" || initial == "q" || initial == "x";
    if (is_palatal && final_text.front() == 'u') final_text.front() = 'v';
    if (final_text == "iu") return "iou";
    if (final_text == "ui") return "uei";
    if (final_text == "un") return "uen";
    return final_text;
}

bool is_h_followed_away(S shape, S next) {
    return (shape == S::h_prime || shape == S::h) &&
           (next == S::i || next == S::u || next == S::e || next == S::o);
}

// Lower-cases ASCII, writes ü as v, drops one tone digit. Empty if something else is in the way.
std::string normalize_pinyin(std::string_view pinyin) {
    std::string text;
    for (std::size_t k = 0; k < pinyin.size(); ++k) {
        const char c = pinyin[k];
        if (c >= 'A' && c <= 'Z') {
            text += static_cast<char>(c - 'A' + 'a');
        } else if (pinyin.substr(k, 2) == "\xC3\xBC" || pinyin.substr(k, 2) == "\xC3\x9C") {
            text += 'v';  // ü Ü
            ++k;
        } else if (pinyin.substr(k, 2) == "\xC3\x8A") {
            text += kECircumflex;  // Ê
            ++k;
        } else if (c == ':' && !text.empty() && text.back() == 'u') {
            text.back() = 'v';  // u:
        } else {
            text += c;
        }
    }
    if (!text.empty() && text.back() >= '0' && text.back() <= '5') text.pop_back();
    // lüe and nüe are often typed lue and nue; neither spelling means anything else.
    if (text == "lue" || text == "nue") text = text.substr(0, 1) + "ve";
    return text;
}

}  // namespace

const std::vector<std::string>& mandarin_syllables() {
    static const std::vector<std::string> syllables = split_syllables();
    return syllables;
}

SyllableShapes syllable_shapes(std::string_view pinyin) {
    const std::string syllable = normalize_pinyin(pinyin);
    const auto& known = mandarin_syllables();
    if (syllable.empty() || !std::binary_search(known.begin(), known.end(), syllable)) {
        throw InvalidArgument("syllable \"" + std::string(pinyin) + "\"",
                              "not a Mandarin syllable (numbered or toneless pinyin expected, "
                              "such as \"ma3\", \"lv4\" or \"zhuang\")");
    }

    // Syllabic nasals and lone vowels that have no initial / medial / rime split.
    if (syllable == "m" || syllable == "hm") return {{S::m}, false};  // lips stay closed
    if (syllable == "n") return {{S::n}, false};
    if (syllable == "ng" || syllable == "hng" || syllable == "r") return {{S::h}, false};
    if (syllable == kECircumflex) return {{S::e}, false};

    std::string initial;
    if (detail::starts_with(syllable, "zh") || detail::starts_with(syllable, "ch") ||
        detail::starts_with(syllable, "sh")) {
        initial = syllable.substr(0, 2);
    } else if (std::string_view("bpmfdtnlgkhjqxrzcs").find(syllable.front()) != std::string_view::npos) {
        initial = syllable.substr(0, 1);
    }
    const std::string final_text = initial.empty()
                                       ? final_of_zero_initial(syllable)
                                       : final_after_initial(initial, syllable.substr(initial.size()));
    const BopomofoFinal parts = split_final(final_text);

    SyllableShapes result;
    if (!initial.empty()) result.shapes.push_back(initial_shape(initial));
    if (parts.medial == 'i') result.shapes.push_back(S::i);
    if (parts.medial == 'u' || parts.medial == 'v') result.shapes.push_back(S::u);
    std::vector<S> rime = rime_shapes(parts.rime);
    // 5.2.2: ㄢ is said e n after the medials ㄧ and ㄩ (xian = i e n, yuan = u e n).
    if (parts.rime == "an" && (parts.medial == 'i' || parts.medial == 'v')) rime = {S::e, S::n};
    // ㄣ is said without the ㄜ that SPEC's en = h n carries after the medials ㄧ and ㄩ (in, ün: no
    // vowel between the i or ü and the n): thesis Table 5.6 gives ㄣ the class n alone. Else 今 jin
    // opened to h between i and n.
    if (parts.rime == "en" && (parts.medial == 'i' || parts.medial == 'v')) rime = {S::n};
    // 5.2.2: ㄛ is said u o after the closed lips of m (bo = m u o).
    if (parts.rime == "o" && parts.medial == 0 && !result.shapes.empty() && result.shapes.back() == S::m) {
        rime = {S::u, S::o};
    }
    result.shapes.insert(result.shapes.end(), rime.begin(), rime.end());

    // 5.2.2: h' and h lose their pre-posture before i, u, e, o, but not before a.
    for (std::size_t k = 0; k + 1 < result.shapes.size();) {
        if (is_h_followed_away(result.shapes[k], result.shapes[k + 1])) {
            result.shapes.erase(result.shapes.begin() + static_cast<std::ptrdiff_t>(k));
            if (k == 0) initial.clear();
        } else {
            ++k;
        }
    }
    result.has_initial_shape = !initial.empty();
    if (result.shapes.empty() || result.shapes.size() > 4) {
        throw detail::internal_error("syllable \"" + syllable +
                                             "\" gave " + std::to_string(result.shapes.size()) +
                                             " mouth shapes");
    }
    return result;
}

std::vector<MouthShape> syllable_mouth_shapes(std::string_view pinyin) {
    return syllable_shapes(pinyin).shapes;
}

}  // namespace v0
}  // namespace talkface

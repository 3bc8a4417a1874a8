// A lesson's formulas as read aloud (x=5 x等于五, a²+b², √3, ∠A, 10⁸, 2^10, ①, Ⅱ, ½): the signs, powers and
// number characters of the written-form reader (written_numbers.hpp declares them).

#include "text/written_numbers.hpp"

#include <string>

#include "text/formula_letters.hpp"
#include "text/number_context.hpp"
#include "text/number_words.hpp"
#include "text/written_number_scan.hpp"

namespace talkface::detail {

namespace {

// Greek letters a lesson writes, said by the names Mandarin readers give them (π 派).
std::string_view greek_letter_name(char32_t c) {
    switch (c) {
        case 0x3B1: return "阿尔法";        // α
        case 0x3B2: return "贝塔";          // β
        case 0x3B3: return "伽马";          // γ
        case 0x394: case 0x3B4: return "德尔塔";  // Δ δ
        case 0x3B8: return "西塔";          // θ
        case 0x3BB: return "兰姆达";        // λ
        case 0x3C0: return "派";            // π
        case 0x3A3: case 0x3C3: return "西格马";  // Σ σ
        case 0x3C6: return "斐";            // φ
        case 0x3A9: case 0x3C9: return "欧米伽";  // Ω ω
        default: return {};
    }
}

// A term of a formula: a digit, a Latin or Greek letter, a closing bracket or a square (x², (a+b)),
// a degree or a percentage.
bool is_formula_term(char32_t c) {
    // A degree or a percentage ends a term too (sin30°=1/2, 25%=1/4; session 14: the = was skipped), and so
    // does any power's last digit ((-1)¹⁰⁰=1; session 33: the = was skipped), the empty set (A∩B=∅) and
    // infinity.
    return is_ascii_digit(c) || is_ascii_letter(c) || !greek_letter_name(c).empty() || c == ')' ||
           c == 0xB2 || c == 0xB3 || c == 0xB9 || (c >= 0x2070 && c <= 0x2079) || c == 0xB0 || c == '%' ||
           c == 0x2103 /*℃*/ || c == 0x2205 /*∅*/ || c == 0x221E /*∞*/;
}

// A relation sign in the clause around text[i]: the signs in it are a formula's (a-b>0: 减).
bool clause_has_relation(const std::vector<CodePoint>& text, std::size_t i) {
    const auto ends_clause = [](char32_t c) {
        return c == ',' || c == ';' || c == '!' || c == '?' || c == 0x3001 /*、*/ || c == 0x3002 /*。*/ || c == '\n';
    };
    for (auto k = i; k < text.size() && !ends_clause(value_at(text, k)); ++k)
        if (is_relation_sign(value_at(text, k))) return true;
    for (auto k = i; k-- > 0 && !ends_clause(value_at(text, k));)
        if (is_relation_sign(value_at(text, k))) return true;
    return false;
}

// Whether a bracketed term opens at text[i] ((-5), (4+5), (√2)): an opening bracket and, spaces skipped, a
// term, a sign before one, a root or another bracket (3×(4+5), (−4)×(−5); session 40: the sign before the
// bracket was unsaid).
bool opens_bracketed_term(const std::vector<CodePoint>& text, std::size_t i) {
    if (value_at(text, i) != '(') return false;
    auto k = i + 1;
    while (value_at(text, k) == ' ') ++k;
    const auto c = value_at(text, k);
    return is_formula_term(c) || is_dash(c) || is_one_of(c, U"+(\u221A");
}

// Whether the answer's place stands at text[i], as an exercise sheet leaves it after its = (36×25=______,
// (−4)×(−5)=？, 3+5=（  ）): a blank of underscores, a question mark, or brackets holding spaces alone
// (session 40: the = was unsaid).
bool leaves_answer_place(const std::vector<CodePoint>& text, std::size_t i) {
    const auto c = value_at(text, i);
    if (c == '_' || c == '?') return true;
    if (c != '(') return false;
    auto k = i + 1;
    while (value_at(text, k) == ' ' || value_at(text, k) == 0x3000) ++k;
    return value_at(text, k) == ')';
}

// Whether a dimension's word opens at text[i] before its number (寬30公分, 高：12cm): × after a quantity and
// before it multiplies the two, as a listing gives its size (長45公分×寬30公分 長四十五公分乘寬三十公分;
// session 40: unsaid with a warning).
bool opens_dimension(const std::vector<CodePoint>& text, std::size_t i) {
    if (!is_one_of(value_at(text, i), U"长長宽寬高厚深")) return false;
    auto k = i + 1;
    if (value_at(text, k) == ':') ++k;
    return is_digit_at(text, k);
}

// Whether c is a Han character (CJK Unified Ideographs and Extension A).
bool is_han_character(char32_t c) {
    return c >= 0x3400 && c <= 0x9FFF;
}

// Whether the bar at text[i] closes an absolute value (|x|=3, |-5|): a bar opened earlier in the clause, the
// bars before it in the clause odd in number, with a formula's terms and signs between and no word.
bool closes_absolute_value(const std::vector<CodePoint>& text, std::size_t i) {
    if (value_at(text, i) != '|') return false;
    int bars_before = 0;
    bool has_term = false;
    for (auto k = i; k-- > 0;) {
        const auto c = value_at(text, k);
        if (c == '|') {
            ++bars_before;
            continue;
        }
        if (is_han_character(c) || is_one_of(c, U",;\n\u3001\u3002")) break;
        if (bars_before == 0) has_term = has_term || is_formula_term(c);
    }
    return has_term && bars_before % 2 == 1;
}

// Whether a single letter stands right before text[end) and right after text[start] (v=s/t, a:b=3:2): a
// formula's two variables, not a word's letters (km/h, and/or).
bool between_single_letters(const std::vector<CodePoint>& text, std::size_t before, std::size_t after) {
    return before >= 1 && is_ascii_letter(value_at(text, before - 1)) &&
           (before < 2 || !is_ascii_letter(value_at(text, before - 2))) &&
           is_ascii_letter(value_at(text, after)) && !is_ascii_letter(value_at(text, after + 1));
}

// A number at text[i] that measures something, a unit or a word after it (60分, 38℃, 5mg, 90%): what a bound
// written < or > holds (分数<60分). A heart's <3 and a bracket's <1> measure nothing.
bool is_measured_number(const std::vector<CodePoint>& text, std::size_t i) {
    if (!is_digit_at(text, i)) return false;
    const auto after = value_at(text, parse_number(text, i).end);
    return is_han_character(after) || is_ascii_letter(after) || after == '%' ||
           after == 0x2103 /*℃*/ || after == 0xB0 /*°*/;
}

// The digit a superscript writes (⁰ ¹ ² ³ ⁴ ... ⁹), or -1.
int superscript_digit(char32_t c) {
    switch (c) {
        case 0x2070: return 0;
        case 0xB9: return 1;
        case 0xB2: return 2;
        case 0xB3: return 3;
        default: return c >= 0x2074 && c <= 0x2079 ? static_cast<int>(c - 0x2070) : -1;
    }
}

// A clause that rates, around a single star from text[start) to text[end): a word of rating before it
// (评分 打分 评价 差评 好评), 级 or a verdict's 好评 差评 after it, or a verb giving it right before it
// (给 打了) where the star closes its clause (只能给★，; 请给☆标记的题目 marks).
bool rates(const std::vector<CodePoint>& text, std::size_t start, std::size_t end) {
    const std::string before = text_before(text, start, true);
    const bool closes_clause = end >= text.size() || is_one_of(value_at(text, end), U"，,。.！!？?；;、 \n");
    return contains_any(before, {"评分", "評分", "打分", "评价", "評價", "评级", "評級", "好评", "好評",
                                 "差评", "差評"}) ||
           starts_with_any(text_between(text, end, end + 2), {"级", "級", "好评", "好評", "差评", "差評"}) ||
           (closes_clause && ends_with_any(before, {"给", "給", "打了"}));
}

// The = at text[i] between two lone digits, nothing of a formula around them (3=1，来个人; 车队2=3): a game
// lobby's count, three waiting for one more, said 三等一 as players say it (session 28: 等于). A sum has its
// signs (1+2=3) and an equation its letters (x=5).
bool counts_a_lobby(const std::vector<CodePoint>& text, std::size_t i) {
    const auto outside = [&](std::size_t k) {
        const auto c = value_at(text, k);
        return !is_formula_term(c) && !is_dash(c) && !is_one_of(c, U"+×÷*/^.=<>(\u2212");
    };
    return i >= 1 && is_digit_at(text, i - 1) && is_digit_at(text, i + 1) && (i < 2 || outside(i - 2)) &&
           outside(i + 2);
}

// The + at text[i] said 加 between `left` and `right` (the characters beside it, spaces skipped), or "":
// between two digits (1+1), two letters (A+B), two words or in a formula (x+1=3).
std::string_view said_plus(const std::vector<CodePoint>& text, std::size_t i, char32_t left, char32_t right) {
    // A letter and a digit too: a sum of capacities (12GB+256GB 十二GB加二百五十六GB), 5G+AI.
    const auto is_alphanumeric = [](char32_t c) { return is_ascii_letter(c) || is_ascii_digit(c); };
    const bool alphanumeric = is_alphanumeric(left) && is_alphanumeric(right);
    // After a square or a cube, a sum of terms (a²+b²; session 14: said only beside a relation sign).
    const bool after_power = is_one_of(left, U"\u00B2\u00B3");
    // Between two words, a post's or a menu's "and also" (关注+转发 关注加转发, 汉堡+可乐; session
    // 22: skipped with a warning), one of them Latin or a number too, and after a word that a closing
    // quote ends, as news names a plan of "X plus" (AI+教育 AI加教育, 5G+工业互联网, “互联网+”行动;
    // session 26: skipped with a warning).
    const bool word_left = is_han_character(left) || is_alphanumeric(left);
    const bool joins_words = word_left && (is_han_character(right) || is_alphanumeric(right));
    const bool names_plan = word_left && is_one_of(right, U"\u201D\u300D\u300F\"");
    const bool between_terms = is_formula_term(left) && is_formula_term(right);
    const bool is_sum = between_terms && (alphanumeric || after_power || clause_has_relation(text, i));
    return is_sum || joins_words || names_plan ? "加" : "";
}

// The small x at text[i] typed for a times sign right after an item's name and before its count, said 乘
// (金币x100 金币乘一百, 经验卡x2; session 19: the letter x and a model's digits), or "": not after a word
// that introduces a term (两根为x1、x2, 设x2 ...: a lesson's variable). `is_unspaced`: no space on either
// side of it; `left` and `right` as said_plus's.
std::string_view said_small_x(const std::vector<CodePoint>& text, std::size_t i, bool is_unspaced,
                              char32_t left, char32_t right) {
    const bool introduces_term = is_one_of(left, U"设設令为為是和与與及或且根点點若则則当當求把将將");
    const bool counts_items = is_unspaced && is_han_character(left) && !introduces_term &&
                              is_ascii_digit(right) && !clause_has_relation(text, i);
    return counts_items ? "乘" : "";
}

// The value of the Roman numeral text[start, end) in I, V and X (1 to 39), or 0 where the letters are none.
int ascii_roman_value(const std::vector<CodePoint>& text, std::size_t start, std::size_t end) {
    const auto value_of = [](char32_t letter) { return letter == 'I' ? 1 : letter == 'V' ? 5 : 10; };
    int value = 0;
    for (auto k = start; k < end; ++k) {
        const int here = value_of(text[k].value);
        value += k + 1 < end && here < value_of(text[k + 1].value) ? -here : here;
    }
    constexpr int kLargest = 39;
    return value >= 1 && value <= kLargest ? value : 0;
}

// The end of a Roman numeral written in capital letters at text[i] (II型糖尿病, 第IV卷), or i where there is
// none: two or more of I, V and X standing apart from other letters and digits, after 第 or before a
// classifier a numeral orders (型 期 卷 类 级 章 册 代 世 部). A lone I or V is a letter or a pronoun
// (V我50); the Unicode numerals (Ⅲ期) are read above.
std::size_t ascii_roman_numeral_end(const std::vector<CodePoint>& text, std::size_t i) {
    auto end = i;
    while (is_one_of(value_at(text, end), U"IVX")) ++end;
    const auto stands_apart = [&](char32_t c) { return !is_ascii_letter(c) && !is_ascii_digit(c); };
    if (end - i < 2 || (i > 0 && !stands_apart(text[i - 1].value)) || !stands_apart(value_at(text, end)))
        return i;
    const bool ordered = (i > 0 && text[i - 1].value == U'第') ||
                         is_one_of(value_at(text, end), U"型期卷类類级級章册冊代世部");
    return ordered && ascii_roman_value(text, i, end) > 0 ? end : i;
}

}  // namespace

std::string_view said_math_sign(const std::vector<CodePoint>& text, std::size_t i) {
    const auto sign = value_at(text, i);
    if (const auto name = greek_letter_name(sign); !name.empty()) return name;
    auto before = i;
    while (before > 0 && text[before - 1].value == ' ') --before;
    // A gas's or a precipitate's arrow ends its product's term (O₂↑+, CaCO₃↓+2NaCl), unsaid.
    if (before > 0 && marks_reaction_arrow(text, before - 1)) --before;
    auto after = i + 1;
    while (value_at(text, after) == ' ') ++after;
    const char32_t left = before > 0 ? value_at(text, before - 1) : 0;
    const char32_t right = value_at(text, after);
    const bool is_han_left = is_han_character(left);
    const bool is_han_right = is_han_character(right);
    // A relation's right side may be a signed term (x=-2 x等于负二, -3<-1 负三小于负一, x=±3 x等于正负三;
    // session 28: the = before ± was unsaid): the sign is the number's, read with it.
    const bool signed_right =
        (is_dash(right) || is_one_of(right, U"+\u00B1")) && is_formula_term(value_at(text, after + 1));
    const bool right_term = is_formula_term(right) || opens_bracketed_term(text, after);
    // A set's brace too (A={1,2,3}).
    const bool relation_right = right_term || signed_right || right == '|' || right == '{';
    // An absolute value's closing bar ends a term (|x|=3 x的绝对值等于三).
    const bool left_term = is_formula_term(left) || (before > 0 && closes_absolute_value(text, before - 1));
    const bool between_terms = left_term && right_term;
    // A judgement question's answer, a tick or a cross alone in brackets (（√） 对, （×） 错), as a teacher
    // reads the key (session 33: 根号, and the cross unsaid).
    const bool marks_judgement = left == '(' && right == ')';
    // A mark to draw after 打 (打√ 打✓ 打勾, 打× 打✗ 打叉), as teachers and forms say it (session 33: √ and ×
    // warned, ✓ and ✗ unsaid as drawings).
    if (left == U'打' && is_one_of(sign, U"\u221A\u2713\u2714")) return "勾";
    if (left == U'打' && is_one_of(sign, U"\u00D7\u2717\u2718")) return "叉";
    switch (sign) {
        case '=': case 0x2248: case 0x2260: {  // = ≈ ≠, between a character and a term too (答案是x=5, 等于号)
            if (sign == '=' && counts_a_lobby(text, i)) return "等";
            const bool answer_right = left_term && leaves_answer_place(text, after);
            if (!(left_term || is_han_left) || !(relation_right || is_han_right || answer_right)) return {};
            return sign == '=' ? "等于" : sign == 0x2248 ? "约等于" : "不等于";
        }
        // ASCII < > around words are brackets: <标题>. After a word or at a clause's start and before a
        // number that measures they bound it, as ≥ ≤ do (分数<60分 分数小于六十分, <60分为不及格; session 30:
        // unsaid).
        case '>':
        case '<': {
            const bool opens_clause = before == 0 || is_one_of(ascii_form(left), U",:;(\n");
            const bool bounds = (is_han_left || opens_clause) && is_measured_number(text, after);
            if (!(is_formula_term(left) && relation_right) && !bounds) return {};
            return sign == '>' ? "大于" : "小于";
        }
        // ≥ and ≤ are never brackets: after a character too, before a term (含量≥80mg 含量大于等于八十毫克).
        case 0x2265:
            return (left_term || is_han_left) && relation_right ? "大于等于" : "";  // ≥
        case 0x2264:
            return (left_term || is_han_left) && relation_right ? "小于等于" : "";  // ≤
        // A set's signs as a lesson reads them (session 33: skipped with a warning): x∈A 属于, x∉B 不属于,
        // A∩B 交, A∪B 并, A⊆B 包含于, A⊇B 包含, ∅ 空集; ∞ 无穷, after its sign 正无穷 负无穷.
        case 0x2208:  // ∈, before an interval too (x∈[0,1))
        case 0x2209:  // ∉
            if (!left_term || !(is_formula_term(right) || is_one_of(right, U"([\u2205"))) return {};
            return sign == 0x2208 ? "属于" : "不属于";
        case 0x2229:
            return between_terms ? "交" : "";  // ∩
        case 0x222A:
            return between_terms ? "并" : "";  // ∪
        case 0x2286:
            return between_terms ? "包含于" : "";  // ⊆
        case 0x2287:
            return between_terms ? "包含" : "";  // ⊇
        case 0x2205:
            return "空集";  // ∅
        case 0x221E:
            return "无穷";  // ∞
        // A bar closing an absolute value is said after its term (|x| x的绝对值); the opening bar is silent.
        case '|':
            return closes_absolute_value(text, i) ? "的绝对值" : "";
        // A colon or a slash between two single letters in a formula is a ratio, 比 (a:b=3:2, v=s/t, I=U/R,
        // as lessons read a formula's quotient; session 33: unsaid).
        case ':':
        case '/':
            return between_single_letters(text, before, after) && clause_has_relation(text, i) ? "比" : "";
        // Geometry's signs as a lesson reads them (session 14): ∠A 角A, before a letter or a digit
        // (∠1); AB⊥CD AB垂直于CD, AB∥CD AB平行于CD, between two terms.
        case 0x2220: return is_formula_term(right) ? "角" : "";           // ∠
        case 0x25B3: return is_ascii_capital(right) ? "三角形" : "";       // △ABC 三角形ABC
        // ≌ and ∽ between two figures (△ABC≌△DEF 三角形ABC全等于三角形DEF).
        case 0x224C: case 0x2245: return is_formula_term(left) && (is_formula_term(right) || right == 0x25B3) ? "全等于" : "";  // ≌ ≅
        case 0x223D: return is_formula_term(left) && (is_formula_term(right) || right == 0x25B3) ? "相似于" : "";  // ∽
        case 0x22A5: return between_terms ? "垂直于" : "";                 // ⊥
        case 0x2225: case 0x2016: return between_terms ? "平行于" : "";    // ∥, and ‖ written for it
        // + between two digits (1+1), two letters (A+B), two words or in a formula (x+1=3); - only in a
        // formula, since a hyphen joins words and numbers elsewhere (Wi-Fi, B-52).
        case '+':
            return right == 0x221E ? "正" : said_plus(text, i, left, right);
        case '-':
        case 0x2212:
            if (right == 0x221E) return "负";
            return between_terms && clause_has_relation(text, i) ? "减" : "";
        // A * before ST marks a share at risk of delisting (*ST康美), said 星 as market news says it. Between
        // a term and a number it is a times sign typed as a keyboard has it, as a drug's pack writes its
        // strength times its count (规格：10mg*30片 十毫克乘三十片; session 35: skipped with a warning).
        case '*': {
            const bool before_st = value_at(text, after) == 'S' && value_at(text, after + 1) == 'T' &&
                                   !is_ascii_letter(value_at(text, after + 2));
            if (before_st) return "星";
            return between_terms && is_ascii_digit(right) ? "乘" : "";
        }
        // × after a character too, before a number (经验值×2 经验值乘二, a game's bonus; session 14), and
        // between two words in a formula, as ÷ is (長方形面積=長×寬 长乘宽, 底×高÷2; session 39: skipped
        // with a warning); elsewhere two names about it are a collaboration's (品牌×故宫), left unsaid.
        case 0xD7:  // ×
            if (marks_judgement) return "错";
            return between_terms || (is_han_left && is_ascii_digit(right)) ||
                           (is_han_left && is_han_right && clause_has_relation(text, i)) ||
                           ((left_term || is_han_left) && opens_dimension(text, after))
                       ? "乘"
                       : "";
        case 'x': return said_small_x(text, i, before == i && after == i + 1, left, right);
        // ÷ is never a bracket or a dash: between two words too, as a rule of thumb is written
        // (总价÷数量=单价, 体重(kg)÷身高; session 30: skipped with a warning).
        case 0xF7:  // ÷
            return (is_formula_term(left) || is_han_left) && (is_formula_term(right) || is_han_right) ? "除以"
                                                                                                      : "";
        // An arrow between two words or terms names where something goes (北京→上海 北京到上海, a route's
        // stops; session 20: skipped with a warning).
        case 0x2192:
            return (is_formula_term(left) || is_han_left) && (is_formula_term(right) || is_han_right) ? "到"
                                                                                                      : "";
        case 0x221A:  // √2, √(x+1)
            if (marks_judgement) return "对";
            return is_formula_term(right) || right == '(' ? "根号" : "";
        // A cube root and a fourth root as a lesson reads them (∛27 三次根号二十七, ∜81; session 31: unsaid).
        case 0x221B:
            return is_formula_term(right) || right == '(' ? "三次根号" : "";  // ∛
        case 0x221C:
            return is_formula_term(right) || right == '(' ? "四次根号" : "";  // ∜
        // A square or a cube after a term: x² x平方, 3² 三的平方; after a word, as a rule of thumb writes it,
        // 的 too (身高² 身高的平方, 速度²; session 31: unsaid). Not after a unit of length's character, whose
        // square is a unit said first (厘米² 平方厘米), which this sign cannot reorder. After a bracket, 的
        // too, as a teacher reads a bracket's power ((-2)³ 负二的立方, (a+b)² a加b的平方; session 33: 立方).
        case 0xB2: case 0xB3: {
            const bool after_word = is_han_left && !is_one_of(left, U"米尺寸里");
            if (!(is_formula_term(left) || after_word) || before != i) return {};
            const bool after_digit = is_ascii_digit(left) || left == ')';
            if (sign == 0xB2) return after_digit || after_word ? "的平方" : "平方";
            return after_digit || after_word ? "的立方" : "立方";
        }
        default: return {};
    }
}

std::optional<SpokenForm> read_number_character(const std::vector<CodePoint>& text, std::size_t i) {
    const auto c = value_at(text, i);
    int number = 0;
    if (c >= 0x2460 && c <= 0x2473) number = static_cast<int>(c - 0x2460) + 1;  // ① ... ⑳
    if (c >= 0x2474 && c <= 0x2487) number = static_cast<int>(c - 0x2474) + 1;  // ⑴ ... ⒇
    if (c >= 0x2488 && c <= 0x249B) number = static_cast<int>(c - 0x2488) + 1;  // ⒈ ... ⒛
    if (c >= 0x2776 && c <= 0x277F) number = static_cast<int>(c - 0x2776) + 1;  // ❶ ... ❿
    if (c >= 0x2780 && c <= 0x2793) number = static_cast<int>((c - 0x2780) % 10) + 1;  // ➀ ... ➉, ➊ ... ➓
    if (c >= 0x2160 && c <= 0x216B) number = static_cast<int>(c - 0x2160) + 1;  // Ⅰ ... Ⅻ
    if (c >= 0x2170 && c <= 0x217B) number = static_cast<int>(c - 0x2170) + 1;  // ⅰ ... ⅻ
    SpokenForm form;
    form.end = i + 1;
    if (number == 0) {
        const auto roman_end = ascii_roman_numeral_end(text, i);
        if (roman_end > i) {
            number = ascii_roman_value(text, i, roman_end);
            form.end = roman_end;
        }
    }
    if (number > 0) {
        form.words = cardinal_words(std::to_string(number), false);
        return form;
    }
    // A rating drawn in stars, two or more of ★ and ☆ in a row, is said by its filled ones, 星 (★★★★☆ 四星,
    // ★★★★★级 五星级, as a review is read; session 21: skipped with a warning), a row all empty 零星
    // (☆☆☆☆☆, a reviewer's none; session 22: skipped). A star alone rates only where its clause does
    // (评分：★ 一星, 只能给★); elsewhere it is a decoration (★重要通知★), said nothing and warned of as
    // a mark without a reading.
    auto stars_end = i;
    int filled = 0;
    while (is_one_of(value_at(text, stars_end), U"\u2605\u2606")) {
        filled += value_at(text, stars_end) == 0x2605 ? 1 : 0;
        ++stars_end;
    }
    if (stars_end - i >= 2 || (stars_end > i && rates(text, i, stars_end))) {
        form.words = (filled > 0 ? cardinal_words(std::to_string(filled), false) : std::string("零")) + "星";
        form.end = stars_end;
        return form;
    }
    // A fraction written as one character: its denominator 分之 its numerator, as 1/2 is.
    constexpr std::pair<char32_t, const char*> kFractions[] = {
        {0xBD, "二分之一"},   {0x2153, "三分之一"}, {0x2154, "三分之二"}, {0xBC, "四分之一"}, {0xBE, "四分之三"},
        {0x2155, "五分之一"}, {0x2156, "五分之二"}, {0x2157, "五分之三"}, {0x2158, "五分之四"}, {0x2159, "六分之一"},
        {0x215A, "六分之五"}, {0x2150, "七分之一"}, {0x215B, "八分之一"}, {0x215C, "八分之三"}, {0x215D, "八分之五"},
        {0x215E, "八分之七"}, {0x2151, "九分之一"}, {0x2152, "十分之一"},
    };
    // After a whole number it is a mixed number's part, joined by 又 as a recipe's 1½杯 is read
    // (一又二分之一杯; session 35: 一二分之一).
    for (const auto& [written, said] : kFractions) {
        if (c != written) continue;
        form.words = std::string(i > 0 && is_digit_at(text, i - 1) ? "又" : "") + said;
        return form;
    }
    return std::nullopt;
}

std::optional<SpokenForm> read_power(const std::vector<CodePoint>& text, std::size_t i) {
    if (i == 0 || !is_formula_term(value_at(text, i - 1))) return std::nullopt;
    bool negative = false;
    std::string exponent;
    auto k = i;
    if (value_at(text, k) == '^') {
        ++k;
        if (is_dash(value_at(text, k))) {
            negative = true;
            ++k;
        }
        exponent = digits_from(text, k);
    } else {
        if (value_at(text, k) == 0x207B /*⁻*/) {
            negative = true;
            ++k;
        }
        for (int digit = superscript_digit(value_at(text, k)); digit >= 0; digit = superscript_digit(value_at(text, k))) {
            exponent += static_cast<char>('0' + digit);
            ++k;
        }
        // A lone ² or ³ is said_math_sign's (平方 立方, and m² is a unit's), but ten's in scientific notation
        // (1.0×10³kg/m³ 一点零乘十的三次方千克每立方米, as 10⁸ is 十的八次方; session 33: 十的立方, and the
        // unit after it spelled).
        const bool scales_by_ten = i >= 3 && value_at(text, i - 1) == '0' && value_at(text, i - 2) == '1' &&
                                   is_one_of(value_at(text, i - 3), U"\u00D7x*");
        if (!negative && (exponent == "2" || exponent == "3") && !scales_by_ten) return std::nullopt;
    }
    constexpr std::size_t kLongestExponent = 3;
    if (exponent.empty() || exponent.size() > kLongestExponent) return std::nullopt;
    SpokenForm form;
    form.end = k;
    const bool after_digit = is_digit_at(text, i - 1);
    if (!negative && (exponent == "2" || exponent == "3") && value_at(text, i) == '^') {
        form.words = std::string(after_digit ? "的" : "") + (exponent == "2" ? "平方" : "立方");
    } else {
        form.words = std::string("的") + (negative ? "负" : "") + cardinal_words(exponent, false) + "次方";
    }
    return form;
}

}  // namespace talkface::detail

namespace talkface::detail {

namespace {

// A logarithm's number or letter from text[k] (a space before it skipped), said after `before` and before
// `after` (以二为底 八 的对数, 一百 的常用对数, 以三为底 x 的对数); nullopt where neither starts there, a
// letter follows the number, or the letter starts a word.
std::optional<SpokenForm> said_logarithm(const std::vector<CodePoint>& text, std::size_t k,
                                         const std::string& before, std::string_view after) {
    if (value_at(text, k) == ' ') ++k;
    // A variable, one letter (log₃x, log_2 n, lnx): said by its name, which the form's words may hold
    // (session 33: the letters of log, lo ge, and the letter after them).
    if (is_ascii_letter(value_at(text, k)) && !is_ascii_letter(value_at(text, k + 1)) &&
        !is_digit_at(text, k + 1)) {
        SpokenForm form;
        form.words = before + std::string(text[k].text) + std::string(after);
        form.end = k + 1;
        return form;
    }
    if (!is_digit_at(text, k)) return std::nullopt;
    const auto argument = parse_number(text, k);
    if (is_ascii_letter(value_at(text, argument.end))) return std::nullopt;
    const auto said = say_number(argument, {});
    SpokenForm form;
    form.words = before + said.words + std::string(after);
    form.warning = said.warning;
    form.end = argument.end;
    return form;
}

}  // namespace

std::optional<SpokenForm> read_logarithm(const std::vector<CodePoint>& text, std::size_t i) {
    if (i > 0 && is_ascii_letter(value_at(text, i - 1))) return std::nullopt;
    // The common and the natural logarithm, lg and ln before a number (lg100 一百的常用对数, ln10
    // 十的自然对数), as teachers read them: the number first, as log's is (session 33: the letters, ai le ji,
    // ai le en).
    const auto name = text_between(text, i, i + 2);
    if (name == "lg" || name == "ln")
        return said_logarithm(text, i + 2, "", name == "lg" ? "的常用对数" : "的自然对数");
    if (text_between(text, i, i + 3) != "log") return std::nullopt;
    auto k = i + 3;
    std::string base;
    if (value_at(text, k) == '_') {
        ++k;
        base = digits_from(text, k);
    } else {
        for (; k < text.size() && is_subscript_digit(text[k]); ++k)
            base += static_cast<char>(value_at(text, k));
    }
    if (base.empty()) return std::nullopt;
    return said_logarithm(text, k, "以" + cardinal_words(base, false) + "为底", "的对数");
}

std::optional<SpokenForm> read_repeating_decimal(const std::vector<CodePoint>& text,
                                                 const WrittenNumber& number, const std::string& sign_words) {
    constexpr char32_t kDotAbove = 0x307;
    if (!number.has_point || value_at(text, number.end) != kDotAbove) return std::nullopt;
    auto repeating = number;
    auto end = number.end + 1;
    // The dots stand over the first and the last digit of the repeating part (0.1̇2̇, 0.1̇23̇), or over each:
    // the digits run through the last dotted one.
    std::string undotted;
    for (auto k = end; is_digit_at(text, k); ++k) {
        undotted += static_cast<char>(value_at(text, k));
        if (value_at(text, k + 1) != kDotAbove) continue;
        repeating.fraction += undotted;
        undotted.clear();
        end = ++k + 1;
    }
    const auto said = say_number(repeating, {});
    SpokenForm form;
    form.words = sign_words + said.words + "循环";
    form.warning = said.warning;
    form.end = end;
    return form;
}

}  // namespace talkface::detail

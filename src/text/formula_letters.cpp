#include "text/formula_letters.hpp"

#include <algorithm>
#include <iterator>
#include <string>
#include <string_view>

#include "text/written_number_scan.hpp"

namespace talkface::detail {

bool in_chemical_formula(const std::vector<CodePoint>& text, std::size_t start) {
    static constexpr std::string_view kSymbols[] = {
        "H",  "He", "Li", "Be", "B",  "C",  "N",  "O",  "F",  "Ne", "Na", "Mg", "Al", "Si", "P",  "S",
        "Cl", "Ar", "K",  "Ca", "Sc", "Ti", "V",  "Cr", "Mn", "Fe", "Co", "Ni", "Cu", "Zn", "Ga", "Ge",
        "As", "Se", "Br", "Kr", "Rb", "Sr", "Y",  "Zr", "Nb", "Mo", "Tc", "Ru", "Rh", "Pd", "Ag", "Cd",
        "In", "Sn", "Sb", "Te", "I",  "Xe", "Cs", "Ba", "La", "Ce", "Pr", "Nd", "Pm", "Sm", "Eu", "Gd",
        "Tb", "Dy", "Ho", "Er", "Tm", "Yb", "Lu", "Hf", "Ta", "W",  "Re", "Os", "Ir", "Pt", "Au", "Hg",
        "Tl", "Pb", "Bi", "Po", "At", "Rn", "Fr", "Ra", "Ac", "Th", "Pa", "U",  "Np", "Pu", "Am"};
    auto is_symbol = [](std::string_view symbol) {
        return std::find(std::begin(kSymbols), std::end(kSymbols), symbol) != std::end(kSymbols);
    };
    auto in_run = [&](std::size_t k) {
        return is_ascii_letter(text[k].value) || is_ascii_digit(text[k].value);
    };
    auto first = start;
    while (first > 0 && in_run(first - 1)) --first;
    auto end = start;
    while (end < text.size() && in_run(end)) ++end;
    auto k = first;
    while (k < end && is_ascii_digit(text[k].value)) ++k;  // a coefficient (2H2O)
    std::size_t symbols = 0;
    // A count written in subscript digits shows a formula as one between symbols does (KMnO₄, whose only
    // count ends it; session 33: a word of letters): nothing but chemistry and a lesson's variables (x₁)
    // writes them, and a variable is no element's symbol.
    bool counted_between = false;
    bool counted_below = false;
    bool has_small = false;
    while (k < end) {
        if (!is_ascii_capital(text[k].value)) return false;
        std::string symbol(1, static_cast<char>(text[k].value));
        if (k + 1 < end && text[k + 1].value >= 'a' && text[k + 1].value <= 'z')
            symbol += static_cast<char>(text[k + 1].value);
        if (!is_symbol(symbol)) return false;
        has_small = has_small || symbol.size() == 2;
        k += symbol.size();
        ++symbols;
        const auto count_start = k;
        while (k < end && is_ascii_digit(text[k].value)) ++k;
        counted_between = counted_between || (k > count_start && k < end);
        counted_below = counted_below || (k > count_start && is_subscript_digit(text[count_start]));
    }
    if (symbols < 2) return false;
    if (counted_between || counted_below) return true;
    if (!has_small) return false;
    // Beside an equation's sign a symbol pair is a reactant or a product (CaCO₃↓+2NaCl; session 33: na, the
    // pinyin, and C L), as in a sentence of chemistry.
    if (touches_formula_sign(text, first, -1) || touches_formula_sign(text, end, 1)) return true;
    const std::string sentence = detail::text_between(text, 0, text.size());
    return detail::contains_any(
        sentence, {"溶液", "溶于", "溶於", "反应", "反應", "化学", "化學", "分子", "离子", "離子", "浓度",
                   "濃度", "摩尔", "摩爾", "晶体", "晶體", "沉淀", "电解", "電解"});
}

bool touches_formula_sign(const std::vector<CodePoint>& text, std::size_t edge, int step) {
    auto k = edge;
    if (step < 0) {
        while (k > 0 && text[k - 1].value == ' ') --k;
        if (k == 0) return false;
        --k;
    } else {
        while (k < text.size() && text[k].value == ' ') ++k;
        if (k == text.size()) return false;
    }
    return std::u32string_view(U"=<>+×÷≈≠≤≥∠⊥∥").find(text[k].value) != std::u32string_view::npos;
}

}  // namespace talkface::detail

namespace talkface::detail {

bool marks_reaction_arrow(const std::vector<CodePoint>& text, std::size_t i) {
    if (i == 0 || (text[i].value != 0x2191 /*↑*/ && text[i].value != 0x2193 /*↓*/)) return false;
    const auto before = text[i - 1].value;
    if (!is_ascii_letter(before) && !is_ascii_digit(before)) return false;
    const auto next = i + 1 < text.size() ? ascii_form(text[i + 1].value) : U'\n';
    if (!is_one_of(next, U"+=,;.) \n\u3001\u3002")) return false;
    for (auto k = i; k-- > 0;) {
        const auto c = ascii_form(text[k].value);
        if (c == '=') return true;
        if (is_one_of(c, U",;.\n\u3001\u3002")) break;
    }
    return false;
}

}  // namespace talkface::detail

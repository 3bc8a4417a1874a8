// Latin letters that stand in a formula, said as letters, not as pinyin or English words: a chemical
// formula's element symbols (H2SO4, NaCl) and a lesson's terms beside a formula's sign (∠A=30°).
#ifndef TALKFACE_TEXT_FORMULA_LETTERS_HPP
#define TALKFACE_TEXT_FORMULA_LETTERS_HPP

#include <cstddef>
#include <vector>

#include "text/code_points.hpp"

namespace talkface::detail {

// Whether text[start] stands in a chemical formula, as a chemistry lesson writes one (H2SO4, Fe2O3,
// C6H12O6, NaCl): the run of ASCII letters and digits around it is element symbols (a capital and at
// most one small letter, from the periodic table) with their counts, a coefficient allowed before
// (2H2O), and it shows itself a formula: a count between two symbols (Fe2O3, H2O; Win10 has its
// digits only at the end), or, where a symbol has a small letter and none is counted (NaCl, NaOH), a
// word of chemistry in the sentence (溶液 反应 分子 离子 ...). Each letter is then said by its name,
// small ones too (Fe ai fu yi), and each count as a number (C6H12O6 C六H十二O六), as lessons read
// them (session 17: Fe was the pinyin fei, and a formula's O the pinyin o in a line without Chinese).
bool in_chemical_formula(const std::vector<CodePoint>& text, std::size_t start);

// Whether the character next to a token (at `edge - 1` before it, step -1, or at `edge` after it,
// step 1; spaces skipped) is a sign a formula writes between or before terms (= < > ≈ ≠ ≤ ≥ + ×
// ÷ ∠ ⊥ ∥).
bool touches_formula_sign(const std::vector<CodePoint>& text, std::size_t edge, int step);

// Whether the arrow at text[i] marks a gas given off (↑) or a precipitate (↓) after a product of a chemical
// equation (2H₂O₂=2H₂O+O₂↑, CaCO₃↓): right after a term's letter or count, ending it, an = before it in the
// clause. A lesson reads the equation without them, so the reader keeps them unsaid and unwarned (session
// 33: skipped with a warning); an arrow after a word (宁德时代↑3.2%) is no such mark.
bool marks_reaction_arrow(const std::vector<CodePoint>& text, std::size_t i);

}  // namespace talkface::detail

#endif

// Pictures a chat line draws rather than writes: emoji (😂 🚀 👌 ☀️) and faces drawn in signs,
// kaomoji ((≧∇≦)ﾉ, (╯°□°)╯︵ ┻━┻, Σ(っ °Д °;)っ, (^_^)) and those typed in ASCII (^_^, T_T, :D).
// Nobody says them, as nobody says punctuation: the transcript reader keeps them in the sentence's
// text, unsaid and without a warning (session 31:
// each of their signs was warned of as a symbol without a reading, and a Greek letter drawn in a face,
// the ω of (｡･ω･｡), was said as a formula's, 欧米伽).
#ifndef TALKFACE_TEXT_DRAWN_FACES_HPP
#define TALKFACE_TEXT_DRAWN_FACES_HPP

#include <cstddef>
#include <vector>

#include "text/code_points.hpp"

namespace talkface::detail {

// Where each drawing of `text` ends (code points as the reader folds them: full-width forms as ASCII):
// ends[i] is the end of the emoji or face that begins at text[i], or i where none begins there.
// - An emoji: a pictograph (U+1F000-U+1FAFF, and U+2600-U+27BF but the stars ★ ☆, which a rating says,
//   and the circled digits ❶ ➀ of a list) and the selectors and joiners that join it to the next.
// - A face: a bracket, ( or （, closed on its line within 16 code points, holding at least two signs and no
//   Chinese character, Latin letter or digit, and not only punctuation (the 。！ of (。。。) are marks);
//   with the signs touching it on either side (Σ before it, ﾉ♡ and ╯︵ after it: no space, Chinese
//   character, Latin letter, digit or punctuation between; no ASCII sign, nor one a written form reads,
//   ² ° ± ½ ℃ ①) and a run of such signs one space after it (the table ┻━┻ the face throws).
// - A face typed in ASCII signs outside a bracket, set off by a space, a Chinese character, punctuation or
//   the line's ends (session 32: its signs were warned of, its letters said, T_T ti ti): two eyes alike
//   about a mouth (^_^ -_- =_= >_< ^o^; letters only about an underscore, T_T o_o x_x), ^^, a ; of sweat
//   after it allowed, and a sideways face with a letter's mouth after a space (:D :-P ;o).
std::vector<std::size_t> find_drawing_ends(const std::vector<CodePoint>& text);

}  // namespace talkface::detail

#endif

// Which line breaks of a plain transcript end a sentence: a line written as a sentence of its own
// (a script typed one line a sentence, a subtitle's or a lyric's lines copied without their times),
// not a paragraph wrapped at a width (docs/transcripts.md "Lines").
#ifndef TALKFACE_TEXT_LINE_SENTENCES_HPP
#define TALKFACE_TEXT_LINE_SENTENCES_HPP

#include <vector>

#include "text/code_points.hpp"

namespace talkface::detail {

// The lines (1-based, rising) after which a sentence ends though no mark ends it there: each line
// of a paragraph but its last that ends with no mark, or with a closing quote or bracket, where
// the paragraph is written line by line. A line ending in a pause mark or a dash (，、：, —) runs on
// into the next. A paragraph is running text, wrapped at a width, where a line of it ends a
// sentence inside it (a 。, or a word's . before a space, with text after it on the line): its breaks
// end nothing. So is a line that fills the paragraph's width (as wide as its widest line, and
// at least 40 columns, a Chinese character two).
std::vector<int> lines_ending_sentences(const std::vector<CodePoint>& text);

}  // namespace talkface::detail

#endif

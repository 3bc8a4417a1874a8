// The marks of a transcript's text as the reader walks it (SPEC "Transcript to syllables"): which end a
// sentence, mark a pause, close a quote or are punctuation not said, and the dots and signs that are no
// mark where they stand (a choice's A., a list item's 1., a lineage's XBB.1.5, a topic's #, a ticker's $, a
// screen mode's @).
#ifndef TALKFACE_TEXT_SENTENCE_MARKS_HPP
#define TALKFACE_TEXT_SENTENCE_MARKS_HPP

#include <cstddef>
#include <string_view>
#include <vector>

#include "text/code_points.hpp"

namespace talkface::detail {

bool is_space(char32_t c);

// Two line breaks with nothing but spaces between them.
bool has_blank_line(std::string_view space);

bool ends_sentence(char32_t c);

bool marks_pause(char32_t c);

// Closing quotes and brackets after an end mark belong to the sentence it ends: 「好。」
bool closes_quote(char32_t c);

// Punctuation that is not spoken (quotes, brackets, dashes, dots between names, a tilde: GB/T
// 15834's 连接号, which a chat line also writes to draw a word out, 好的～) stays in the sentence
// text silently. Symbols a reader says aloud (% $ + = & @ #) are not here: they get a
// warning like letters and digits, since the speech holds words the transcript lacks there.
bool is_silent_punctuation(char32_t c);

// The dot after a choice's letter (A.正确 B.错误, as a lesson's question lists its choices): a
// capital A to H alone, the dot, and a Chinese character right after it. It ends no sentence and
// is not said (session 14: the question was cut into a sentence at each choice).
bool marks_choice(const std::vector<CodePoint>& text, std::size_t i);

// The dot after a list item's number (积分榜：1.利物浦 68分 2.阿森纳 65分, as a table or a list numbers its
// rows): one or two digits at the start of a line or after a space or a colon, the dot, and a Chinese
// character right after it. It ends no sentence and is not said (session 16: the table was cut into a
// sentence at each row). A number after a word (增长了3.接下来) still ends its sentence.
bool marks_list_item(const std::vector<CodePoint>& text, std::size_t i);

// The dot in a virus lineage's name (XBB.1.5, BA.2, JN.1): two or more capitals, the dot and a digit. It
// ends no sentence and is not said, as the name is read (XBB 一点五; session 28: 毒株为XBB.1.5。 was cut
// after XBB.). A capital alone before a dot may be a choice's or an initial's.
bool marks_lineage_dot(const std::vector<CodePoint>& text, std::size_t i);

// A dot of an initialism written with its dots (K.O., U.S., J.K.罗琳): each after a letter alone, with
// another such letter and dot beside it. It ends no sentence and is not said, as the letters are read
// (直接K.O.！ kei ou; session 33: cut after K. and again after O.). A letter alone before a dot may be a
// choice's (A.选项) where no other follows.
bool marks_initialism_dot(const std::vector<CodePoint>& text, std::size_t i);

// A # that opens or closes a topic (#春节快乐#, as Weibo and other posts mark one): a bracket, not
// said; the topic between them is read. A # with no partner on its line (#5) is still a symbol.
bool marks_topic(const std::vector<CodePoint>& text, std::size_t i);

// A $ that tags a stock's ticker ($TSLA, $AAPL, as posts and market news cite one): one to five capitals
// right after it and no letter or digit on either side, a tag not said; the ticker's letters are read
// (session 22: the $ was skipped with a warning). $5 stays dollars.
bool marks_ticker(const std::vector<CodePoint>& text, std::size_t i);

// The @ of a screen's or a camera's mode between its resolution and its rate (4K@144Hz, 8K@60fps,
// 1080P@240fps, as spec sheets write them): no word, read as 4K 一百四十四赫兹 is (session 31: skipped with a
// warning). A resolution is digits and a K or a P; the rate's digits follow the @.
bool marks_screen_mode(const std::vector<CodePoint>& text, std::size_t i);

// A caption's or a list's bullet (▲图为救援现场, ● 国内油价, ■ 要点): a geometric shape (U+25A0 to U+25FF; △
// is a triangle's, △ABC) that opens its line. It is not said and not warned of, as a list item's dot is
// (session 36: skipped with a warning); a ticker's ▲ before a number is its rise (number_signs.hpp), and a
// shape a legend explains is named (legend_shapes.hpp).
bool marks_bullet(const std::vector<CodePoint>& text, std::size_t i);

// The brace at text[i] opens a set a lesson writes (A={1,2,3}, 集合{x|x>0}), no reading fix: a closing brace
// on its line within 40 characters, and between them only Latin letters, digits, spaces and a formula's
// signs, with a comma or a bar among them, which no fix holds. The braces are not said; the members are read
// (一，二，三); session 33: an error, a fix that follows nothing it reads.
bool opens_set(const std::vector<CodePoint>& text, std::size_t i);

}  // namespace talkface::detail

#endif

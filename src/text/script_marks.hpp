// What a script writes that nobody says: stage directions in brackets （笑） [掌声] 【音乐】 and the
// speaker labels a dialogue starts its lines with (主持人： A: 小明：). The transcript reader leaves
// them out with a warning, unless TranscriptOptions::keep_directions.
#ifndef TALKFACE_TEXT_SCRIPT_MARKS_HPP
#define TALKFACE_TEXT_SCRIPT_MARKS_HPP

#include <cstddef>
#include <vector>

#include "text/code_points.hpp"

namespace talkface::detail {

// text[begin, end): a stage direction with its brackets, or a speaker label with its colon and
// the spaces after it, and the time a chat log stamps the line with before it ([10:30] 小明：), or a
// chat log's line of a name and a time alone (小明 10:30); the label as its warning names it is
// text[name_begin, name_end).
struct ScriptMark {
    std::size_t begin = 0;
    std::size_t end = 0;
    bool is_label = false;
    std::size_t name_begin = 0;
    std::size_t name_end = 0;
};

// The marks of `text` (code points as the reader folds them: full-width forms as ASCII), in order.
// - A stage direction: a bracket, ( [ （ ［ 【 〔 〖, closed on its line, holding only words of
//   sounds and actions (笑 掌声 鼓掌 音乐 叹气 咳嗽 停顿 画外音 ..., laughter applause music ...,
//   with 众人 全场 观众 before and 起 声 不断 after them), separated by 、，, or spaces. A bracket
//   of anything else (（包邮） (2330)) is text and read.
// - A speaker label: at a line's start, a name of 1 to 8 characters (Chinese characters, Latin
//   letters, digits, spaces between; not digits alone, not a verb of saying such as 他说) and a
//   colon; only where two lines or more start so, and the text is a dialogue: a label names two
//   lines or more, or half the lines that are not blank start with one. One line alone
//   (客服热线：400-800-1234) is text. Where no name comes back, each must name a person (a news
//   digest's 外交部： 英超： are its items' headings); a body's name (部 局 委 署 社 ...) never does. A
//   chat log's time before the name (10:30 小明：, [2026-12-07 10:30:15] 小明：) goes with the label,
//   and so does a line of a name and a time alone, as a chat app exports each message's header
//   (小明 10:30, 2026-12-07 10:30:15 小明), where two lines or more are so written.
std::vector<ScriptMark> find_script_marks(const std::vector<CodePoint>& text);

// Whether the dash at text[start] opens a speaker's turn in a subtitle of two (-明天几号？-12号，周五。):
// the line starts with a dash, and this one stands at its start or right after an end mark, with
// another such dash in the line. Such a dash is no minus sign; a line of one dash (-5℃，晴) keeps its sign.
bool opens_turn(const std::vector<CodePoint>& text, std::size_t start);

}  // namespace talkface::detail

#endif

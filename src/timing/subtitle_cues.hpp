// The block structure SubRip and WebVTT share: cues of a timing line ("A --> B") and text lines,
// separated by blank lines. subrip.cpp and webvtt.cpp read their own header and times around it.
#ifndef TALKFACE_TIMING_SUBTITLE_CUES_HPP
#define TALKFACE_TIMING_SUBTITLE_CUES_HPP

#include <string>
#include <string_view>
#include <vector>

namespace talkface::detail {

struct TextLine {
    std::string text;  // without the line break (\n, \r\n or \r)
    int line = 0;      // 1-based
};

// The text split into lines; a UTF-8 byte order mark is dropped.
std::vector<TextLine> text_lines(std::string_view text);

// The blocks of non-blank lines, in order.
std::vector<std::vector<TextLine>> text_blocks(const std::vector<TextLine>& lines);

// "00:00:01,250 --> 00:00:02,000" (cue settings may follow) into start_s and end_s; false if
// the line is not a timing line with `separator` before the milliseconds.
bool read_cue_times(const std::string& line, char separator, double& start_s, double& end_s);

// A cue's text without its markup: tags (<i>, </b>, <c.yellow>, <v Ann>) and SubRip's {\an8}
// codes dropped, the entities &amp; &lt; &gt; &nbsp; replaced.
std::string without_markup(const std::string& text);

}  // namespace talkface::detail

#endif

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

// The times of the cue whose timing line ("00:00:01,250 --> 00:00:02,000", cue settings may follow)
// is line `at` of `block`, into start_s and end_s; returns that line's number.
// \throws talkface::ParseError naming `source`, the line and the form expected (`separator` before
//         the milliseconds) if the block has no line `at` or it is not a timing line.
int read_cue_timing(const std::vector<TextLine>& block, std::size_t at, char separator, const std::string& source,
                    double& start_s, double& end_s);

// A cue's text without its markup: tags (<i>, </b>, <c.yellow>, <v Ann>) and SubRip's {\an8}
// codes dropped, the entities &amp; &lt; &gt; &nbsp; replaced.
std::string without_markup(const std::string& text);

}  // namespace talkface::detail

#endif

// read_transcript for a transcript whose lines carry a cut of their own: a subtitle's cues, a
// TextGrid's intervals (src/timing/transcript_file.cpp lays their text out on the file's lines).
#ifndef TALKFACE_TEXT_TRANSCRIPT_CUT_HPP
#define TALKFACE_TEXT_TRANSCRIPT_CUT_HPP

#include <string>
#include <string_view>
#include <vector>

#include "talkface/transcript.hpp"

namespace talkface::detail {

// read_transcript of the text of a file laid out on its own lines, the others blank: a sentence
// also ends after each line of `lines_ending_sentences` (1-based, rising) that holds text, whatever
// marks it ends with; blank lines start no paragraph.
Timeline read_transcript_cut(std::string_view utf8_text, const TranscriptOptions& options,
                             const std::string& source_name, const std::vector<int>& lines_ending_sentences);

}  // namespace talkface::detail

#endif

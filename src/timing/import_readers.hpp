// The timing import readers, one per format file (textgrid.cpp, subrip.cpp, webvtt.cpp,
// words_json.cpp): the file's text to timed units, before they meet the transcript.
#ifndef TALKFACE_TIMING_IMPORT_READERS_HPP
#define TALKFACE_TIMING_IMPORT_READERS_HPP

#include <string>
#include <string_view>
#include <vector>

#include "timing/timed_units.hpp"

namespace talkface::detail {

// A timing file's text as UTF-8, whichever Unicode encoding its byte order mark names
// (utf8_from_marked_text). \throws FileError if it cannot be read.
std::string read_timing_text(const std::string& path);

// A Praat TextGrid (long or short text format, UTF-8 or UTF-16 with its byte order mark): the
// intervals of the tier named "syllables", else "words" (as Montreal Forced Aligner names it),
// else the only interval tier. \throws ParseError naming source:line and what was expected.
std::vector<TimedUnit> read_textgrid_units(std::string_view text, const std::string& source);

// What a TextGrid given as a transcript is read from: the intervals of its "sentences" tier
// (is_sentences), else those read_textgrid_units reads. \throws as read_textgrid_units.
struct TextGridText {
    std::vector<TimedUnit> intervals;
    bool is_sentences = false;
};
TextGridText read_textgrid_text_units(std::string_view text, const std::string& source);

// SubRip cues. \throws ParseError naming source:line and what was expected.
std::vector<TimedUnit> read_subrip_units(std::string_view text, const std::string& source);

// WebVTT cues, with their cue timestamps. \throws ParseError naming source:line and what was expected.
std::vector<TimedUnit> read_webvtt_units(std::string_view text, const std::string& source);

// A JSON list of {"text": str, "start": s, "end": s}. \throws ParseError naming source:line:column.
std::vector<TimedUnit> read_words_json_units(std::string_view text, const std::string& source);

// The timeline's syllables as that list, one per line.
std::string words_json(const Timeline& timeline);

}  // namespace talkface::detail

#endif

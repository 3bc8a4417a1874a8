// talkface: the timeline JSON, the one lossless, versioned file of a Timeline (SPEC "Contracts"):
// what `talkface align --json` and `talkface syllables --json` print, what `keyframes --timeline`
// reads, and what tf_timeline_to_json / talkface.timeline_to_json give. Every other timing format
// (TextGrid, subtitles, Rhubarb cues ...) drops something; this one keeps every field.
//
//   {"version":1,
//   "sentences":[
//   {"text":"你好。","start":0.5,"end":1.1}
//   ],
//   "syllables":[
//   {"text":"你","pinyin":"ni3","start":0.5,"end":0.8,"sentence":0,"final_start":0.57,"confidence":0.9,
//    "pause_after":false},
//   ...
//   ],
//   "duration":2.0,
//   "warnings":[]}
//
// Times are seconds in their shortest round-trip form, so a document read back is the same
// timeline, bit for bit. docs/timeline-format.md describes every key.
#ifndef TALKFACE_TIMELINE_JSON_HPP
#define TALKFACE_TIMELINE_JSON_HPP

#include <string>
#include <string_view>

#include "talkface/export.h"
#include "talkface/timeline.hpp"

namespace talkface {
inline namespace v0 {

/// The version of the timeline JSON this build writes, and the newest it reads. A document
/// without "version" is read as version 1 (what talkface wrote before the key existed).
inline constexpr int kTimelineJsonVersion = 1;

/// How timeline_to_json writes.
struct TimelineJsonOptions {
    /// false: leave out every time and what the aligner measured (start, end, final_start,
    /// confidence, duration), as `talkface syllables --json` does for a transcript not yet aligned.
    bool with_times = true;
};

/// The timeline as the timeline JSON (UTF-8, one sentence or syllable per line, ending in a
/// newline). Pure; thread-safe.
TALKFACE_API std::string timeline_to_json(const Timeline& timeline, const TimelineJsonOptions& options = {});

/// Reads the timeline JSON. Keys a document leaves out take their defaults (times 0, confidence 1,
/// no final start, no pause), so `talkface syllables --json` reads too; keys this build does not
/// know are skipped, so that a later minor addition stays readable.
/// \throws talkface::ParseError naming source_name:line:column and the item ("syllables[3].start")
///         for text that is not JSON, a missing or mistyped key, a sentence index out of range, a
///         negative time, an end before its start, or a "version" newer than kTimelineJsonVersion
///         (named, with the version this build reads).
TALKFACE_API Timeline timeline_from_json(std::string_view utf8_text, const std::string& source_name = "<timeline>");

/// timeline_from_json of a file. \throws talkface::FileError if it cannot be read; ParseError as above.
TALKFACE_API Timeline load_timeline_json(const std::string& path);

/// Writes timeline_to_json to `path` atomically (a temporary file renamed over it).
/// \throws talkface::FileError naming the path and the OS reason; the file is then left as it was.
TALKFACE_API void save_timeline_json(const std::string& path, const Timeline& timeline,
                                     const TimelineJsonOptions& options = {});

}  // namespace v0
}  // namespace talkface

#endif

// A transcript file as a user has it (load_transcript, transcript.hpp): text in whatever encoding
// (text/transcript_encoding.hpp), or subtitles or a TextGrid whose text is the transcript. Here,
// not in text/, since it reads the subtitles and TextGrids with the timing imports' readers.
#ifndef TALKFACE_TIMING_TRANSCRIPT_FILE_HPP
#define TALKFACE_TIMING_TRANSCRIPT_FILE_HPP

#include <string>
#include <string_view>

#include "talkface/transcript.hpp"

namespace talkface::detail {

// load_transcript of a file's bytes, messages naming `source`.
Timeline read_transcript_file(std::string_view bytes, const TranscriptOptions& options,
                              const std::string& source);

}  // namespace talkface::detail

#endif

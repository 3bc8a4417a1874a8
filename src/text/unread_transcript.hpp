// Why a transcript gives the aligner nothing to align, said once for every message that refuses
// one: the aligner's (validate_transcript) and the command's, which names the file before any audio
// is read (src/cli/timing_option.cpp).
#ifndef TALKFACE_TEXT_UNREAD_TRANSCRIPT_HPP
#define TALKFACE_TEXT_UNREAD_TRANSCRIPT_HPP

#include <string>

#include "talkface/export.h"
#include "talkface/timeline.hpp"

// Exported from libtalkface though not in its installed headers, for the command: not API, may change.
namespace talkface::detail {

// "N sentences, none with a Mandarin reading" ("1 sentence, with no Mandarin reading"), then the
// reader's first warning, which names the file, line and character it skipped (the user's way to
// the cause), and how many more there are:
// "; <transcript>:1:1: "★" (U+2605) has no Mandarin reading; skipped (and 2 more warnings)"
// ("and 1 more warning").
TALKFACE_API std::string describe_unread_transcript(const Timeline& transcript);

}  // namespace talkface::detail

#endif

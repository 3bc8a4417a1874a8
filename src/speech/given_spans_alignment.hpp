// Alignment pinned to sentence spans the caller gives (issue #15: what `--timing` does with
// subtitle cues): SpeechAligner::align_file with given_sentence_cut in place of finding the pauses.
// The re-estimation and the checks of a wrong text still see the whole recording, as they do
// when the aligner cuts; only where each sentence is searched is the caller's. Defined in
// speech_aligner.cpp, beside SpeechAligner::align_file, whose flow (validate_transcript,
// align_source) it shares.
#ifndef TALKFACE_SPEECH_GIVEN_SPANS_ALIGNMENT_HPP
#define TALKFACE_SPEECH_GIVEN_SPANS_ALIGNMENT_HPP

#include <string>
#include <vector>

#include "speech/sentence_cutter.hpp"
#include "talkface/progress.hpp"
#include "talkface/timeline.hpp"

namespace talkface::detail {

// The transcript aligned with the recording at `audio_path`, each sentence's
// syllables inside its span of `sentence_spans_s` (one per sentence; given_sentence_cut says how
// they are read), as `options` (checked as SpeechAligner's constructor does) say otherwise, their
// sentence_cut aside.
// \throws as SpeechAligner::align_file, and talkface::InvalidArgument as given_sentence_cut.
Timeline align_in_given_spans(const std::string& audio_path, const Timeline& transcript,
                              const std::vector<GivenSpan>& sentence_spans_s, const AlignOptions& options,
                              const ProgressCallback& progress = {});

}  // namespace talkface::detail

#endif

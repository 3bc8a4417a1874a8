// A reading of a recording that left its first samples out (the digital silence before its first
// sound, another phase of the frames): times moved between that reading's terms and the recording's.
#ifndef TALKFACE_SPEECH_SKIPPED_TIME_HPP
#define TALKFACE_SPEECH_SKIPPED_TIME_HPP

#include <vector>

#include "speech/sentence_cutter.hpp"
#include "talkface/speech_aligner.hpp"
#include "talkface/timeline.hpp"

namespace talkface::detail {

// The times of a reading that left `skipped_s` of the recording out, in that reading's terms: the
// caller's sentence spans and first pause moved earlier by it.
std::vector<GivenSpan> spans_after_skip(std::vector<GivenSpan> spans, double skipped_s);
AlignOptions options_after_skip(AlignOptions options, double skipped_s);

// A timeline found on a reading that left `skipped_s` of the recording out, moved onto the
// recording's times.
void move_onto_recording(Timeline& timeline, double skipped_s);

// A timeline's times to the microsecond, where hours of silence were left out before them: a frame's
// 60.57 s moved by 10740 s read 10800.570000000002, where the reading of the whole file gives 10800.57.
void round_to_microseconds(Timeline& timeline);

}  // namespace talkface::detail

#endif

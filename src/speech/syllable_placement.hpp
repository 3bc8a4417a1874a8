// A chain's best path turned into what the caller gets: each syllable's start (SPEC "Alignment":
// where its initial starts, a stop's closure after speech), its vowel's start, its end and its
// confidence; and the path's stretches and spans as the checks read them.
#ifndef TALKFACE_SPEECH_SYLLABLE_PLACEMENT_HPP
#define TALKFACE_SPEECH_SYLLABLE_PLACEMENT_HPP

#include <vector>

#include "speech/alignment_checks.hpp"
#include "speech/frame_features.hpp"
#include "speech/hsmm.hpp"
#include "speech/sentence_chains.hpp"
#include "talkface/timeline.hpp"

namespace talkface::detail {

// Writes the syllables of one aligned chain into `result` (times in seconds of the recording),
// and the evidence of their places into `evidence` (per syllable of the transcript), from which
// set_confidences gives their confidences once every chain is placed; `other_paths` (of the same
// chain, on the same frames; may be none) weigh in by where they start each syllable
// (syllable_steadiness).
void place_syllables(const SentenceChain& chain, const std::vector<StateSegment>& path,
                     const std::vector<std::vector<StateSegment>>& other_paths, const EmissionScores& scores,
                     const FeatureTrack& track, Timeline& result, std::vector<double>& evidence);

// The path's syllables and pauses, in frames of the whole recording.
std::vector<AlignedStretch> stretches_of(const SentenceChain& chain, const std::vector<StateSegment>& path);

// Frames from the first syllable's start to the last one's end of sentence `k` of `chain` as
// aligned in `result`.
FrameSpan aligned_span(const Timeline& result, const SentenceChain& chain, std::size_t k);

}  // namespace talkface::detail

#endif

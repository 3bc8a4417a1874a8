// The tones as a witness for a text (issue 12): each syllable's final against the tones the
// recording's syllables show, for a room's sentence that the checks would refuse, and for lenient
// alignment's skips.
#ifndef TALKFACE_SPEECH_TONE_WITNESS_HPP
#define TALKFACE_SPEECH_TONE_WITNESS_HPP

#include <cstddef>
#include <vector>

#include "speech/alignment_checks.hpp"
#include "speech/frame_features.hpp"
#include "speech/hsmm.hpp"
#include "speech/sentence_chains.hpp"

namespace talkface::detail {

// A room's sentence's tone gap (SentenceMetrics::tone_gap) is measured in files of at least this
// many spoken sentences, the tones learned mostly from the others' syllables (in a file of one or
// two a wrong text's own syllables teach them), and from this many of its syllables judged.
inline constexpr std::size_t kMinToneWitnessSentences = 3;
inline constexpr std::size_t kMinToneWitnessSyllables = 3;
// Thrown where check_text_fit refuses a sentence of a room's file of kMinToneWitnessSentences or
// more and the pitch was not measured: with it the sentence's tones may witness for its text
// (align_source reads the recording again). Not an AlignmentError: no refusal's handler takes it.
struct ToneWitnessWanted {};

// Per chain, per syllable, its tone_gaps (tone_contour.hpp) on the chains' `plain_paths`: the shape
// of each syllable's final against the tones of every chain's syllables.
std::vector<std::vector<double>> tone_gaps_of_chains(
    const std::vector<SentenceChain>& chains, const std::vector<std::vector<StateSegment>>& plain_paths,
    const FeatureTrack& track);

// Each sentence's SentenceMetrics::tone_gap on the chains' `paths`: the mean of its syllables' tone
// gaps, where at least kMinToneWitnessSyllables were judged.
void set_tone_gaps(const std::vector<SentenceChain>& chains,
                   const std::vector<std::vector<StateSegment>>& paths, const FeatureTrack& track,
                   std::vector<SentenceMetrics>& metrics);

}  // namespace talkface::detail

#endif

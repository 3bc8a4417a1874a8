// The level a steady noise stays under: what a sound must rise over to be heard in it, and what a
// voice's quiet end must fall under to have stopped (syllable_placement.hpp's onsets and closures
// in a chain's pauses, sentence_chains.hpp's quiet ends in the recording's).
#ifndef TALKFACE_SPEECH_NOISE_REACH_HPP
#define TALKFACE_SPEECH_NOISE_REACH_HPP

#include <vector>

namespace talkface::detail {

// The kNoiseReachShare percentile of `levels` (a band's level, dB, on frames that hold the noise
// alone): a frame above it is one the noise alone reaches one time in ten. +infinity where they
// are fewer than kMinNoiseFrames, or where the noise is not steady (its levels spread over more
// than kSteadyNoiseSpreadDb between that percentile and the one as far from the bottom: music,
// drums, a codec's gated comfort noise).
float steady_noise_reach(std::vector<float> levels);

// How far `levels` (as steady_noise_reach's) spread between the kNoiseReachShare percentile and
// the one as far from the bottom: the noise's own swing. 0 where they are fewer than
// kMinNoiseFrames.
float noise_spread(std::vector<float> levels);

}  // namespace talkface::detail

#endif

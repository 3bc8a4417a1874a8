// Landmarks the audio gives whatever the text (issue 12): frames where the spectrum changes
// fast, which is where one sound gives way to the next, so that the search puts the boundaries
// between its states there rather than where the duration priors alone would.
#ifndef TALKFACE_SPEECH_SPECTRAL_LANDMARKS_HPP
#define TALKFACE_SPEECH_SPECTRAL_LANDMARKS_HPP

#include <cstddef>
#include <vector>

#include "speech/hsmm.hpp"

namespace talkface::detail {

// EmissionScores::boundary of frames [0, frame_count) of `observations` (acoustic_model.hpp's
// columns): what a state gains by starting at each frame, from how much faster the cepstra change
// there than at the stretch's median frame; never a loss.
void set_boundary_bonus(const float* observations, std::size_t frame_count, EmissionScores& scores);

}  // namespace talkface::detail

#endif

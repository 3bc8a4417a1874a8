// The straight line through a stretch of frame levels: a room's ringing falls by the same dB each
// frame once the voice has stopped, so a tail's levels lie on a line (late_reverb.cpp reads the
// room's decay from it, sentence_chains.cpp follows it back to where the voice stopped).
#ifndef TALKFACE_SPEECH_LEVEL_LINE_HPP
#define TALKFACE_SPEECH_LEVEL_LINE_HPP

#include <cstddef>

#include "speech/frame_features.hpp"

namespace talkface::detail {

// A line over frames: its level at the first frame and its change a frame.
struct LevelLine {
    double start_db = 0.0;
    double slope_db_per_frame = 0.0;

    // Its level `frames` after its first frame (before it where negative).
    double at(double frames) const { return start_db + slope_db_per_frame * frames; }
};

// The least-squares line through column `column` of frames [first, end) of `track` (first < end).
LevelLine fit_level_line(const FeatureTrack& track, int column, std::size_t first, std::size_t end);

}  // namespace talkface::detail

#endif

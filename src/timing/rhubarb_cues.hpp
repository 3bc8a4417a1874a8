// Rhubarb Lip Sync's mouth cues from talkface's key frames: the 12 Mandarin shapes mapped onto
// Rhubarb's nine (A-H, X; docs/timing-formats.md has the table), on Rhubarb's centisecond clock.
// Shared by the three Rhubarb formats and Moho's switch data, which Rhubarb writes from the same cues.
#ifndef TALKFACE_TIMING_RHUBARB_CUES_HPP
#define TALKFACE_TIMING_RHUBARB_CUES_HPP

#include <string>
#include <vector>

#include "talkface/timing_formats.hpp"

namespace talkface::detail {

// One cue: Rhubarb's shape `letter` from start_cs to end_cs (centiseconds, end_cs > start_cs).
struct RhubarbCue {
    long start_cs = 0;
    long end_cs = 0;
    char letter = 'X';
};

// Rhubarb's letter for a key frame: X for the rest of a pause, else the shape's row of the table.
char rhubarb_letter(const MouthKeyFrame& key_frame);

// The audio's end on Rhubarb's clock: truncated to a multiple of 0.01 s, as Rhubarb writes it.
long rhubarb_end_cs(double duration_s);

// The cues of the whole speech, 0 to rhubarb_end_cs: each key frame's letter from its time
// (rounded to the centisecond) to the next one's, neighbours of one letter joined, as Rhubarb's
// timeline joins them. \throws InvalidArgument if the duration is not positive or the key
// frames are not in rising time.
std::vector<RhubarbCue> rhubarb_cues(const ExportInput& input);

// "0.05": centiseconds as Rhubarb's formatDuration writes seconds (two decimals).
std::string rhubarb_seconds(long centiseconds);

}  // namespace talkface::detail

#endif

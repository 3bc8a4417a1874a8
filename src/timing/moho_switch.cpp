// Moho and OpenToonz switch data (.dat, "MohoSwitch1"), as Rhubarb Lip Sync 1.14 writes it with
// --datUsePrestonBlair: a line per cue, its frame (1 + the whole frames before its start) and its
// Preston Blair name; a cue falling on the frame of the one before is skipped; last, the rest
// shape on the frame of the recording's end (one later if that frame is taken). Lossy: the
// letters of the Rhubarb cues on the frame clock.
#include <string>

#include "timing/export_writers.hpp"
#include "timing/rhubarb_cues.hpp"

namespace talkface::detail {

namespace {

// Rhubarb's README, --datUsePrestonBlair: the Preston Blair name of each letter.
const char* preston_blair_name(char letter) {
    switch (letter) {
        case 'A': return "MBP";
        case 'B': return "etc";
        case 'C': return "E";
        case 'D': return "AI";
        case 'E': return "O";
        case 'F': return "U";
        case 'G': return "FV";
        case 'H': return "L";
        default: return "rest";
    }
}

int frame_number(long centiseconds, double fps) {
    return 1 + static_cast<int>(fps * (static_cast<double>(centiseconds) / 100.0));
}

}  // namespace

std::string moho_switch(const ExportInput& input) {
    const std::vector<RhubarbCue> cues = rhubarb_cues(input);
    std::string dat = "MohoSwitch1\n";
    int last_frame = 0;
    for (const RhubarbCue& cue : cues) {
        const int frame = frame_number(cue.start_cs, input.fps);
        if (frame == last_frame) continue;
        dat += std::to_string(frame) + " " + preston_blair_name(cue.letter) + "\n";
        last_frame = frame;
    }
    int end_frame = frame_number(cues.back().end_cs, input.fps);
    if (end_frame == last_frame) ++end_frame;
    return dat + std::to_string(end_frame) + " rest\n";
}

}  // namespace talkface::detail

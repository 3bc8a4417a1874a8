// Rhubarb Lip Sync 1.14's TSV cues (its README, "Tab-separated values"): a line per cue, its start
// in seconds with two decimals, a tab and the shape; then the end of the recording with the
// closed mouth X. Lossy: keeps only the mouth's letters on a centisecond clock.
#include <string>

#include "timing/export_writers.hpp"
#include "timing/rhubarb_cues.hpp"

namespace talkface::detail {

std::string rhubarb_tsv(const ExportInput& input) {
    std::string tsv;
    const std::vector<RhubarbCue> cues = rhubarb_cues(input);
    for (const RhubarbCue& cue : cues) tsv += rhubarb_seconds(cue.start_cs) + "\t" + cue.letter + "\n";
    return tsv + rhubarb_seconds(cues.back().end_cs) + "\tX\n";
}

}  // namespace talkface::detail

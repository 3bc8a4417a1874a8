// Rhubarb Lip Sync 1.14's XML cues (its README, "XML format"), laid out as the Boost property-tree
// writer Rhubarb uses lays them out: a declaration, two-space indents, start and end as attributes,
// the shape as the element's text. Lossy as the TSV is.
#include <string>

#include "common/markup_escape.hpp"
#include "timing/export_writers.hpp"
#include "timing/rhubarb_cues.hpp"

namespace talkface::detail {

std::string rhubarb_xml(const ExportInput& input) {
    const std::vector<RhubarbCue> cues = rhubarb_cues(input);
    std::string xml = "<?xml version=\"1.0\" encoding=\"utf-8\"?>\n<rhubarbResult>\n  <metadata>\n";
    xml += "    <soundFile>" + escape_markup(absolute_audio_path(input.audio_path), QuoteEscape::xml) + "</soundFile>\n";
    xml += "    <duration>" + rhubarb_seconds(cues.back().end_cs) + "</duration>\n  </metadata>\n  <mouthCues>\n";
    for (const RhubarbCue& cue : cues) {
        xml += "    <mouthCue start=\"" + rhubarb_seconds(cue.start_cs) + "\" end=\"" + rhubarb_seconds(cue.end_cs) +
               "\">" + cue.letter + "</mouthCue>\n";
    }
    return xml + "  </mouthCues>\n</rhubarbResult>\n";
}

}  // namespace talkface::detail

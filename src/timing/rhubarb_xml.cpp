// Rhubarb Lip Sync 1.14's XML cues (its README, "XML format"), laid out as the Boost property-tree
// writer Rhubarb uses lays them out: a declaration, two-space indents, start and end as attributes,
// the shape as the element's text. Lossy as the TSV is.
#include <string>

#include "timing/export_writers.hpp"
#include "timing/rhubarb_cues.hpp"

namespace talkface::detail {

namespace {

// The five characters the Boost writer turns into entities.
std::string xml_text(const std::string& text) {
    std::string out;
    for (const char c : text) {
        switch (c) {
            case '<': out += "&lt;"; break;
            case '>': out += "&gt;"; break;
            case '&': out += "&amp;"; break;
            case '"': out += "&quot;"; break;
            case '\'': out += "&apos;"; break;
            default: out += c;
        }
    }
    return out;
}

}  // namespace

std::string rhubarb_xml(const ExportInput& input) {
    const std::vector<RhubarbCue> cues = rhubarb_cues(input);
    std::string xml = "<?xml version=\"1.0\" encoding=\"utf-8\"?>\n<rhubarbResult>\n  <metadata>\n";
    xml += "    <soundFile>" + xml_text(absolute_audio_path(input.audio_path)) + "</soundFile>\n";
    xml += "    <duration>" + rhubarb_seconds(cues.back().end_cs) + "</duration>\n  </metadata>\n  <mouthCues>\n";
    for (const RhubarbCue& cue : cues) {
        xml += "    <mouthCue start=\"" + rhubarb_seconds(cue.start_cs) + "\" end=\"" + rhubarb_seconds(cue.end_cs) +
               "\">" + cue.letter + "</mouthCue>\n";
    }
    return xml + "  </mouthCues>\n</rhubarbResult>\n";
}

}  // namespace talkface::detail

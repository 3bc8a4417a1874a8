// SubRip (.srt) subtitles: a cue per sentence, numbered from 1, times to the millisecond
// (HH:MM:SS,mmm), the sentence's text as written. Lossy: keeps sentence times only. Read back as
// cues (a number line, "start --> end", text lines), whatever sentences they hold.
#include <string>

#include "timing/export_writers.hpp"
#include "timing/import_readers.hpp"
#include "timing/subtitle_cues.hpp"
#include "timing/subtitle_time.hpp"

namespace talkface::detail {

std::string subrip(const Timeline& timeline) {
    std::string srt;
    for (std::size_t k = 0; k < timeline.sentences.size(); ++k) {
        const Sentence& sentence = timeline.sentences[k];
        if (k > 0) srt += "\n";
        srt += std::to_string(k + 1) + "\n" + subtitle_time(sentence.start_s, ',') + " --> " +
               subtitle_time(sentence.end_s, ',') + "\n" + sentence.text + "\n";
    }
    return srt;
}

std::vector<TimedUnit> read_subrip_units(std::string_view text, const std::string& source) {
    std::vector<TimedUnit> units;
    for (const std::vector<TextLine>& block : text_blocks(text_lines(text))) {
        // The cue number is optional in practice; the timing line is not.
        std::size_t at = 0;
        if (block[0].text.find("-->") == std::string::npos) ++at;
        TimedUnit unit;
        unit.line = read_cue_timing(block, at, ',', source, unit.start_s, unit.end_s);
        for (std::size_t k = at + 1; k < block.size(); ++k) {
            unit.text += (k > at + 1 ? "\n" : "") + without_markup(block[k].text);
        }
        units.push_back(std::move(unit));
    }
    return units;
}

}  // namespace talkface::detail

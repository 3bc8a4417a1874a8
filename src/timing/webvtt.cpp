// WebVTT (.vtt) subtitles: a cue per sentence, and inside it a timestamp tag before each syllable
// after the first (<00:00:01.250>), so that players that support karaoke-style cue timestamps
// (the ::cue(:past) / ::cue(:future) selectors) highlight the syllable being spoken.
// Lossy: keeps sentence times and syllable starts to the millisecond. Read back as cues, with
// their cue timestamps as the starts of the syllables that follow them.
#include <optional>
#include <string>

#include "common/markup_escape.hpp"
#include "talkface/errors.hpp"
#include "timing/export_writers.hpp"
#include "timing/import_readers.hpp"
#include "timing/subtitle_cues.hpp"
#include "timing/subtitle_time.hpp"

namespace talkface::detail {

namespace {

// Cue text may not hold "<" or "&" raw (they start tags and entities), nor ">" after "-" ("-->"),
// nor a line break, which could end the cue.
std::string cue_text(std::string text) {
    for (char& c : text) {
        if (c == '\n' || c == '\r') c = ' ';
    }
    return escape_markup(text, QuoteEscape::none);
}

}  // namespace

std::string webvtt(const Timeline& timeline) {
    std::string vtt = "WEBVTT\n";
    std::size_t next_syllable = 0;
    for (std::size_t k = 0; k < timeline.sentences.size(); ++k) {
        const Sentence& sentence = timeline.sentences[k];
        const std::string start = subtitle_time(sentence.start_s, '.');
        const std::string end = subtitle_time(sentence.end_s, '.');
        vtt += "\n" + std::to_string(k + 1) + "\n" + start + " --> " + end + "\n";
        // Each syllable's characters are found in the sentence's text in order; the text between
        // (punctuation, spaces) goes with the syllable before it.
        std::string last_tag = start;
        std::size_t at = 0;
        std::string line;
        for (; next_syllable < timeline.syllables.size() && timeline.syllables[next_syllable].sentence <= k;
             ++next_syllable) {
            const Syllable& syllable = timeline.syllables[next_syllable];
            if (syllable.sentence != k || syllable.text.empty()) continue;
            const std::size_t found = sentence.text.find(syllable.text, at);
            if (found == std::string::npos) continue;
            line += cue_text(sentence.text.substr(at, found - at));
            const std::string tag = subtitle_time(syllable.start_s, '.');
            // Timestamps inside a cue must rise strictly and lie inside it.
            if (tag > last_tag && tag < end) {
                line += "<" + tag + ">";
                last_tag = tag;
            }
            line += cue_text(syllable.text);
            at = found + syllable.text.size();
        }
        vtt += line + cue_text(sentence.text.substr(at)) + "\n";
    }
    return vtt;
}

namespace {

// A cue's payload lines joined, markup dropped, each cue timestamp kept with where it stands.
void read_payload(const std::vector<TextLine>& lines, std::size_t first, TimedUnit& unit) {
    for (std::size_t k = first; k < lines.size(); ++k) {
        const std::string& text = lines[k].text;
        if (k > first) unit.text += "\n";
        for (std::size_t at = 0; at < text.size();) {
            const std::size_t close = text[at] == '<' ? text.find('>', at) : std::string::npos;
            if (close == std::string::npos) {
                const std::size_t next = text.find('<', at + 1);
                unit.text += without_markup(text.substr(at, next == std::string::npos ? std::string::npos : next - at));
                at = next == std::string::npos ? text.size() : next;
                continue;
            }
            const std::optional<double> time = parse_subtitle_time(std::string_view(text).substr(at + 1, close - at - 1), '.');
            if (time) unit.inner_starts_s.emplace_back(unit.text.size(), *time);
            at = close + 1;
        }
    }
}

}  // namespace

std::vector<TimedUnit> read_webvtt_units(std::string_view text, const std::string& source) {
    const std::vector<TextLine> lines = text_lines(text);
    if (lines.empty() || lines[0].text.compare(0, 6, "WEBVTT") != 0 ||
        (lines[0].text.size() > 6 && lines[0].text[6] != ' ' && lines[0].text[6] != '\t')) {
        throw ParseError(source, 1, 0, "", "expected \"WEBVTT\" on the first line, found \"" +
                                                (lines.empty() ? std::string() : lines[0].text) + "\"");
    }
    std::vector<TimedUnit> units;
    const auto blocks = text_blocks(lines);
    for (std::size_t b = 1; b < blocks.size(); ++b) {
        const std::vector<TextLine>& block = blocks[b];
        const std::string& head = block[0].text;
        if (head.compare(0, 4, "NOTE") == 0 || head.compare(0, 5, "STYLE") == 0 || head.compare(0, 6, "REGION") == 0) {
            continue;
        }
        const std::size_t at = head.find("-->") == std::string::npos ? 1 : 0;  // an identifier line first
        TimedUnit unit;
        unit.line = read_cue_timing(block, at, '.', source, unit.start_s, unit.end_s);
        read_payload(block, at + 1, unit);
        double previous_s = unit.start_s;
        for (const auto& inner : unit.inner_starts_s) {
            if (inner.second < previous_s || inner.second > unit.end_s) {
                throw ParseError(source, unit.line, 0, "",
                                 "a cue timestamp at " + subtitle_time(inner.second, '.') +
                                     " lies outside its cue or before the one before it (times out of order)");
            }
            previous_s = inner.second;
        }
        units.push_back(std::move(unit));
    }
    return units;
}

}  // namespace talkface::detail

#include "timing/transcript_file.hpp"

#include <algorithm>
#include <vector>

#include "common/atomic_file.hpp"
#include "common/string_ends.hpp"
#include "text/transcript_cut.hpp"
#include "text/transcript_encoding.hpp"
#include "timing/import_readers.hpp"
#include "timing/subtitle_cues.hpp"

namespace talkface {
inline namespace v0 {

Timeline load_transcript(const std::string& path, const TranscriptOptions& options) {
    return detail::read_transcript_file(detail::read_file(path), options, path);
}

}  // namespace v0
}  // namespace talkface

namespace talkface::detail {

namespace {

enum class TextKind { plain, subrip, webvtt, textgrid };

// What the file is, by its first lines: a subtitle's or a TextGrid's are never a transcript's.
TextKind text_kind(std::string_view text) {
    const auto lines = text_lines(text.substr(0, 4096));
    auto first = std::find_if(lines.begin(), lines.end(), [](const TextLine& line) {
        return line.text.find_first_not_of(" \t") != std::string::npos;
    });
    if (first == lines.end()) return TextKind::plain;
    const std::string& head = first->text;
    if (starts_with(head, "WEBVTT") && (head.size() == 6 || head[6] == ' ' || head[6] == '\t'))
        return TextKind::webvtt;
    if (starts_with(head, "File type = \"ooTextFile\"") && std::next(first) != lines.end() &&
        starts_with(std::next(first)->text, "Object class = \"TextGrid\"")) {
        return TextKind::textgrid;
    }
    // A SubRip cue: its number alone on a line, then its times; or the times first.
    const auto is_times = [](const std::string& line) {
        return line.find(" --> ") != std::string::npos && !line.empty() && line[0] >= '0' && line[0] <= '9';
    };
    const bool is_number = head.find_first_not_of("0123456789 \t") == std::string::npos;
    if (is_times(head) || (is_number && std::next(first) != lines.end() && is_times(std::next(first)->text)))
        return TextKind::subrip;
    return TextKind::plain;
}

// A cue whose text ends in a pause mark or a dash goes on into the next one.
bool runs_on(const std::string& text) {
    auto end = text.find_last_not_of(" \t\r\n");
    if (end == std::string::npos) return false;
    const std::string_view kept = std::string_view(text).substr(0, end + 1);
    for (std::string_view mark : {",", ":", "-", "，", "、", "：", "—", "–"}) {
        if (kept.size() >= mark.size() && kept.substr(kept.size() - mark.size()) == mark) return true;
    }
    return false;
}

// The units' text laid out on the lines it stood on (the first of a unit's lines is `first_line`
// of it), every other line blank, so that the reader's warnings name the file's lines.
struct LaidOut {
    std::vector<std::string> lines;
    std::vector<int> lines_ending_sentences;

    // Puts `text` from line `line` on; returns its last line.
    int put(const std::string& text, int line) {
        std::size_t start = 0;
        for (;;) {
            const std::size_t end = text.find('\n', start);
            if (lines.size() < static_cast<std::size_t>(line)) lines.resize(static_cast<std::size_t>(line));
            std::string& at = lines[static_cast<std::size_t>(line) - 1];
            at += (at.empty() ? "" : " ") +
                  text.substr(start, end == std::string::npos ? std::string::npos : end - start);
            if (end == std::string::npos) return line;
            start = end + 1;
            ++line;
        }
    }

    Timeline read(const TranscriptOptions& options, const std::string& source) {
        std::string text;
        for (const std::string& line : lines) text += line + "\n";
        std::sort(lines_ending_sentences.begin(), lines_ending_sentences.end());
        return read_transcript_cut(text, options, source, lines_ending_sentences);
    }
};

Timeline read_cues(const std::vector<TimedUnit>& cues, const TranscriptOptions& options,
                   const std::string& source) {
    LaidOut laid_out;
    for (const TimedUnit& cue : cues) {
        const int last = laid_out.put(cue.text, cue.line + 1);  // the text follows the times' line
        if (!runs_on(cue.text)) laid_out.lines_ending_sentences.push_back(last);
    }
    return laid_out.read(options, source);
}

Timeline read_textgrid(const TextGridText& grid, const TranscriptOptions& options,
                       const std::string& source) {
    // A pause this long between words is one between sentences (as the aligner's sentence cut takes one).
    constexpr double kSentencePauseS = 0.3;
    LaidOut laid_out;
    const auto& intervals = grid.intervals;
    for (std::size_t k = 0; k < intervals.size(); ++k) {
        if (intervals[k].text.find_first_not_of(" \t\r\n") == std::string::npos) continue;
        const int last = laid_out.put(intervals[k].text, intervals[k].line);
        const bool is_last =
            std::none_of(intervals.begin() + static_cast<std::ptrdiff_t>(k) + 1, intervals.end(),
                         [](const TimedUnit& unit) {
                             return unit.text.find_first_not_of(" \t\r\n") != std::string::npos;
                         });
        const bool before_pause = k + 1 < intervals.size() &&
                                  intervals[k + 1].text.find_first_not_of(" \t\r\n") == std::string::npos &&
                                  intervals[k + 1].end_s - intervals[k + 1].start_s >= kSentencePauseS;
        if (grid.is_sentences || is_last || before_pause) laid_out.lines_ending_sentences.push_back(last);
    }
    return laid_out.read(options, source);
}

}  // namespace

Timeline read_transcript_file(std::string_view bytes, const TranscriptOptions& options,
                              const std::string& source) {
    const std::string text = transcript_utf8(bytes, options.encoding, source);
    switch (text_kind(text)) {
        case TextKind::subrip:
            return read_cues(read_subrip_units(text, source), options, source);
        case TextKind::webvtt:
            return read_cues(read_webvtt_units(text, source), options, source);
        case TextKind::textgrid:
            return read_textgrid(read_textgrid_text_units(text, source), options, source);
        case TextKind::plain:
            break;
    }
    return read_transcript(text, options, source);
}

}  // namespace talkface::detail

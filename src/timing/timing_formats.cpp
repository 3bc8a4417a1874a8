// The timing import formats by name and by suffix, and the readers and writers behind the four
// verbs of timing_formats.hpp (OpenTimelineIO's read/write from/to string/file).
#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "common/atomic_file.hpp"
#include "common/utf8.hpp"
#include "talkface/errors.hpp"
#include "talkface/timeline_json.hpp"
#include "talkface/timing_formats.hpp"
#include "timing/export_writers.hpp"
#include "timing/import_readers.hpp"
#include "timing/timed_units.hpp"

namespace talkface {
inline namespace v0 {

namespace {

void check_format(const std::string& format) {
    const auto& names = timing_format_names();
    if (format != "json" && std::find(names.begin(), names.end(), format) == names.end()) {
        throw InvalidArgument("format", "\"" + format + "\" is not a timing format; the formats are " + detail::format_list(names));
    }
}

// A timeline JSON is already a timeline; it must still be this transcript's, inside this audio.
Timeline checked_timeline(Timeline timeline, const Timeline& transcript, double duration_s, const std::string& source) {
    std::vector<detail::TimedUnit> units;
    for (const Syllable& syllable : timeline.syllables) units.push_back({syllable.text, syllable.start_s, syllable.end_s, 0, {}});
    detail::check_unit_times(units, duration_s, source);
    const auto ranges = detail::unit_syllable_ranges(transcript, units, source);
    for (std::size_t k = 0; k < ranges.size(); ++k) {
        if (ranges[k] != std::make_pair(k, k + 1)) {
            throw ParseError(source, 0, 0, "syllables[" + std::to_string(k) + "]",
                             "\"" + timeline.syllables[k].text + "\" is not the transcript's syllable " +
                                 std::to_string(k + 1));
        }
    }
    if (duration_s > 0.0) timeline.duration_s = duration_s;
    return timeline;
}

}  // namespace

const std::vector<std::string>& timing_format_names() {
    static const std::vector<std::string> names = {"textgrid", "srt", "vtt", "words-json", "timeline-json"};
    return names;
}

std::string timing_format_for_path(const std::string& path) {
    const std::string name = std::filesystem::path(path).filename().string();
    const std::size_t dot = name.rfind('.');
    const std::string suffix = dot == std::string::npos ? std::string() : name.substr(dot);
    if (suffix == ".TextGrid") return "textgrid";
    if (suffix == ".srt") return "srt";
    if (suffix == ".vtt") return "vtt";
    if (suffix == ".json") return "json";  // timeline-json or words-json: the document says which
    throw InvalidArgument("format", "no timing format for suffix \"" + suffix + "\" on file \"" + path +
                                        "\"; the formats are " + detail::format_list(timing_format_names()));
}

Timeline read_timing_string(std::string_view utf8_text, const std::string& format, const Timeline& transcript,
                            double duration_s, const std::string& source_name) {
    check_format(format);
    std::string chosen = format;
    if (chosen == "json") {
        const std::size_t first = utf8_text.find_first_not_of(" \t\r\n");
        chosen = first != std::string_view::npos && utf8_text[first] == '[' ? "words-json" : "timeline-json";
    }
    if (chosen == "timeline-json") {
        return checked_timeline(timeline_from_json(utf8_text, source_name), transcript, duration_s, source_name);
    }
    if (chosen == "textgrid") {
        return detail::match_timed_units(transcript, detail::read_textgrid_units(utf8_text, source_name), duration_s,
                                         source_name, detail::UnitKind::words);
    }
    if (chosen == "words-json") {
        return detail::match_timed_units(transcript, detail::read_words_json_units(utf8_text, source_name), duration_s,
                                         source_name, detail::UnitKind::words);
    }
    const auto cues = chosen == "srt" ? detail::read_subrip_units(utf8_text, source_name)
                                      : detail::read_webvtt_units(utf8_text, source_name);
    return detail::match_timed_units(transcript, cues, duration_s, source_name, detail::UnitKind::cues);
}

Timeline read_timing_file(const std::string& path, const Timeline& transcript, double duration_s,
                          const std::string& format) {
    const std::string chosen = format.empty() ? timing_format_for_path(path) : format;
    check_format(chosen);
    return read_timing_string(detail::read_timing_text(path), chosen, transcript, duration_s, path);
}

std::string write_timing_string(const Timeline& timeline, const std::string& format) {
    check_format(format);
    if (format == "textgrid") return detail::textgrid(timeline);
    if (format == "srt") return detail::subrip(timeline);
    if (format == "vtt") return detail::webvtt(timeline);
    if (format == "words-json") return detail::words_json(timeline);
    if (format == "timeline-json") return timeline_to_json(timeline);
    throw InvalidArgument("format", "\"json\" reads either JSON; to write, name timeline-json or words-json");
}

}  // namespace v0
}  // namespace talkface

namespace talkface::detail {

// Subtitle editors and Notepad on Windows save UTF-16 ("Unicode") as readily as UTF-8.
std::string read_timing_text(const std::string& path) { return utf8_from_marked_text(read_file(path), path); }

}  // namespace talkface::detail

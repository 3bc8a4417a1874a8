// The export formats by name and by suffix (OpenTimelineIO's adapters: from_name, from_filepath),
// and the one place that checks an ExportInput before any writer sees it.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "common/atomic_file.hpp"
#include "common/string_ends.hpp"
#include "talkface/errors.hpp"
#include "talkface/timing_formats.hpp"
#include "timing/export_writers.hpp"

namespace talkface {
inline namespace v0 {

namespace {

// The file name's suffix for messages: ".motion3.json" where it is one, else the last one.
std::string suffix_of(const std::string& path) {
    const std::string name = std::filesystem::path(path).filename().string();
    if (detail::ends_with(name, ".motion3.json")) return ".motion3.json";
    const std::size_t dot = name.rfind('.');
    return dot == std::string::npos ? std::string() : name.substr(dot);
}

void check_input(const ExportInput& input) {
    if (!(input.timeline.duration_s > 0.0) || !std::isfinite(input.timeline.duration_s)) {
        throw InvalidArgument("timeline.duration_s", "expected the audio's length in seconds (> 0), found " +
                                                         std::to_string(input.timeline.duration_s));
    }
    if (!(input.fps > 0.0) || !std::isfinite(input.fps)) {
        throw InvalidArgument("fps", "expected frames per second > 0, found " + std::to_string(input.fps));
    }
}

}  // namespace

const std::vector<std::string>& export_format_names() {
    static const std::vector<std::string> names = {"rhubarb-tsv", "rhubarb-json", "rhubarb-xml", "moho",
                                                   "live2d",      "textgrid",     "srt",         "vtt"};
    return names;
}

std::string export_format_for_path(const std::string& path) {
    const std::string suffix = suffix_of(path);
    if (suffix == ".tsv") return "rhubarb-tsv";
    if (suffix == ".xml") return "rhubarb-xml";
    if (suffix == ".dat") return "moho";
    if (suffix == ".motion3.json") return "live2d";
    if (suffix == ".TextGrid") return "textgrid";
    if (suffix == ".srt") return "srt";
    if (suffix == ".vtt") return "vtt";
    if (suffix == ".json") {
        throw InvalidArgument("format", "a .json file (\"" + path +
                                            "\") may be rhubarb-json or live2d (.motion3.json): name the format; "
                                            "the formats are " + detail::format_list(export_format_names()));
    }
    throw InvalidArgument("format", "no export format for suffix \"" + suffix + "\" on file \"" + path +
                                        "\"; the formats are " + detail::format_list(export_format_names()));
}

std::string export_to_string(const ExportInput& input, const std::string& format) {
    const auto& names = export_format_names();
    if (std::find(names.begin(), names.end(), format) == names.end()) {
        throw InvalidArgument("format", "\"" + format + "\" is not an export format; the formats are " +
                                            detail::format_list(names));
    }
    check_input(input);
    if (format == "rhubarb-tsv") return detail::rhubarb_tsv(input);
    if (format == "rhubarb-json") return detail::rhubarb_json(input);
    if (format == "rhubarb-xml") return detail::rhubarb_xml(input);
    if (format == "moho") return detail::moho_switch(input);
    if (format == "live2d") return detail::live2d_motion(input);
    if (format == "textgrid") return detail::textgrid(input.timeline);
    if (format == "srt") return detail::subrip(input.timeline);
    return detail::webvtt(input.timeline);
}

void export_to_file(const std::string& path, const ExportInput& input, const std::string& format) {
    const std::string document = export_to_string(input, format.empty() ? export_format_for_path(path) : format);
    detail::write_file_atomically(path, document);
}

}  // namespace v0
}  // namespace talkface

namespace talkface::detail {

std::string format_list(const std::vector<std::string>& names) {
    std::string text;
    for (const std::string& name : names) text += (text.empty() ? "" : ", ") + name;
    return text;
}

std::string absolute_audio_path(const std::string& audio_path) {
    if (audio_path.empty()) return audio_path;
    std::error_code error;
    const std::filesystem::path absolute = std::filesystem::absolute(audio_path, error);
    return error ? audio_path : absolute.string();  // not normalised: Rhubarb writes absolute() as it is
}

}  // namespace talkface::detail

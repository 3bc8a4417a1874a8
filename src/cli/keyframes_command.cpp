// `talkface keyframes`: the key frames of an animation (mouth shapes per time, expression events) as
// JSON or TSV for other animation tools (issue #5), from audio and transcript or from a timeline.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>
#include <talkface/talkface.hpp>

#include "animate_command.hpp"
#include "commands.hpp"
#include "error_report.hpp"
#include "timing_option.hpp"
#include "common/atomic_file.hpp"

namespace talkface_cli {

namespace {

using Json = nlohmann::json;

struct KeyframesOptions {
    std::string audio_path;
    TranscriptArgument transcript;
    std::string timeline_path;
    SpeechTiming timing;
    std::uint64_t seed = 0;
    StyleOptions expression;
    std::string events_path;
    std::string events_mode = "add";
    double fps = talkface::LipSyncOptions{}.fps;
    bool tsv = false;
    std::string output_path;
};

// nlohmann reports a byte offset; messages give line:column (columns count bytes here).
Json parse_json(const std::string& path) {
    const std::string text = talkface::detail::read_file(path);
    try {
        return Json::parse(text);
    } catch (const Json::parse_error& error) {
        std::size_t offset = std::min<std::size_t>(error.byte > 0 ? error.byte - 1 : 0, text.size());
        int line = 1;
        int column = 1;
        for (std::size_t k = 0; k < offset; ++k) {
            if (text[k] == '\n') {
                ++line;
                column = 1;
            } else {
                ++column;
            }
        }
        std::string problem = error.what();
        // "[json.exception.parse_error.101] parse error at line 1, column 16: syntax error ..." -> the reason.
        const std::size_t reason = problem.find(": ");
        if (reason != std::string::npos) problem = problem.substr(reason + 2);
        throw talkface::ParseError(path, line, column, "", "not JSON: " + problem);
    }
}

// Reads the items of an events document, naming them ("events[3].start") in messages.
class DocumentReader {
public:
    explicit DocumentReader(std::string path) : path_(std::move(path)) {}

    [[noreturn]] void fail(const std::string& item, const std::string& problem) const {
        throw talkface::ParseError(path_, 0, 0, item, problem);
    }

    const Json& object(const Json& value, const std::string& item) const {
        if (!value.is_object()) fail(item, "expected an object, found " + found(value));
        return value;
    }

    const Json& list(const Json& value, const std::string& item) const {
        if (!value.is_array()) fail(item, "expected a list, found " + found(value));
        return value;
    }

    const Json& member(const Json& owner, const char* key, const std::string& item) const {
        if (!owner.contains(key)) fail(item, "\"" + std::string(key) + "\" is missing");
        return owner.at(key);
    }

    std::string text(const Json& owner, const char* key, const std::string& item) const {
        const Json& value = member(owner, key, item);
        if (!value.is_string()) fail(item + "." + key, "expected a string, found " + found(value));
        return value.get<std::string>();
    }

    double number(const Json& owner, const char* key, const std::string& item,
                  std::optional<double> default_value) const {
        if (!owner.contains(key) && default_value) return *default_value;
        const Json& value = member(owner, key, item);
        if (!value.is_number() || !std::isfinite(value.get<double>())) {
            fail(item + "." + key, "expected a number, found " + found(value));
        }
        return value.get<double>();
    }

private:
    static std::string found(const Json& value) {
        std::string text = value.dump(-1, ' ', false, Json::error_handler_t::replace);
        return text.size() > 40 ? text.substr(0, 40) + "..." : text;
    }

    std::string path_;
};

// docs/events-format.md: the "events" list of the keyframes JSON, alone or inside a document.
std::vector<talkface::ExpressionEvent> read_events(const std::string& path) {
    const Json document = parse_json(path);
    const DocumentReader reader(path);
    const Json& events = reader.list(document.is_object() ? reader.member(document, "events", "document") : document,
                                     "events");
    std::vector<talkface::ExpressionEvent> result;
    for (std::size_t k = 0; k < events.size(); ++k) {
        const std::string item = "events[" + std::to_string(k) + "]";
        const Json& entry = reader.object(events[k], item);
        talkface::ExpressionEvent event;
        try {
            event.kind = talkface::expression_event_kind_from_name(reader.text(entry, "kind", item));
        } catch (const talkface::InvalidArgument& error) {
            reader.fail(item + ".kind", error.what());
        }
        event.start_s = reader.number(entry, "start", item, std::nullopt);
        event.end_s = reader.number(entry, "end", item, std::nullopt);
        event.amount = reader.number(entry, "amount", item, std::nullopt);
        result.push_back(event);
    }
    return result;
}

talkface::Timeline timeline_for(const KeyframesOptions& options) {
    if (!options.timeline_path.empty()) return talkface::load_timeline_json(options.timeline_path);
    const talkface::Timeline transcript = load_transcript_to_time(options.transcript);
    talkface::Timeline timeline = timed_speech(options.audio_path, transcript, options.timing);
    report_warnings(timeline);
    return timeline;
}

void run_keyframes(const KeyframesOptions& options) {
    const bool has_audio_form = !options.audio_path.empty() && !options.transcript.path.empty();
    if (has_audio_form == !options.timeline_path.empty()) {
        throw CLI::ValidationError("keyframes", "give either AUDIO TRANSCRIPT or --timeline TIMELINE.json");
    }
    if ((!options.timing.timing_path.empty() || options.timing.lenient) && !has_audio_form) {
        throw CLI::ValidationError(options.timing.lenient ? "--lenient" : "--timing", "times AUDIO TRANSCRIPT: give them, not --timeline");
    }
    // Everything is computed before the output is opened: a bad input leaves no file.
    const talkface::Timeline timeline = timeline_for(options);
    talkface::ExpressionSimulator simulator(timeline, options.seed, expression_style(options.expression));
    if (!options.events_path.empty()) {
        const auto events = read_events(options.events_path);
        const auto mode =
            options.events_mode == "replace" ? talkface::UserEventMode::replace : talkface::UserEventMode::add;
        try {
            simulator.set_user_events(events, mode);
        } catch (const talkface::Error& error) {
            std::throw_with_nested(talkface::Error(error.code(), options.events_path + ": the events are refused"));
        }
    }
    talkface::LipSyncOptions lip_sync;
    lip_sync.fps = options.fps;
    const auto key_frames = talkface::mouth_key_frames(timeline, lip_sync);
    // The animation's length as talkface::animate() takes it (Animation::duration_s).
    const double duration_s = std::max(talkface::timeline_end_s(timeline), simulator.duration_s());
    const std::string document =
        options.tsv ? talkface::key_frames_tsv(key_frames)
                    : talkface::key_frames_json(key_frames, simulator.events(), options.fps, duration_s);
    if (options.output_path == "-") {
        std::cout << document << std::flush;
    } else {
        talkface::detail::write_file_atomically(options.output_path, document);
    }
}

}  // namespace

void setup_keyframes_command(CLI::App& app) {
    auto options = std::make_shared<KeyframesOptions>();
    CLI::App* keyframes = app.add_subcommand(
        "keyframes", "Export the key frames (mouth shapes per time, blinks, brows, head moves) as JSON or TSV");
    keyframes->add_option("AUDIO", options->audio_path, kSpeechFormatsHelp)
        ->check(CLI::ExistingFile);
    add_transcript_argument(*keyframes, options->transcript, "Its transcript (as `talkface align` reads it)");
    keyframes
        ->add_option("--timeline", options->timeline_path,
                     "An aligned timeline (the timeline JSON of `talkface align --json`) instead of AUDIO TRANSCRIPT")
        ->check(CLI::ExistingFile);
    add_timing_option(*keyframes, options->timing);
    keyframes->add_option("--seed", options->seed, "Seed of the simulated events; the same seed, the same events")
        ->capture_default_str();
    add_style_options(*keyframes, options->expression);
    keyframes
        ->add_option("--events", options->events_path,
                     "Your own events, JSON (docs/events-format.md): "
                     "[{\"kind\":\"nod\",\"start\":s,\"end\":s,\"amount\":x}, ...]")
        ->check(CLI::ExistingFile);
    keyframes
        ->add_option("--events-mode", options->events_mode,
                     "add: your events drop only the simulated ones they overlap; "
                     "replace: your events replace every simulated one of their kinds (--without switches a "
                     "kind off with no events of your own)")
        ->check(CLI::IsMember({"add", "replace"}))
        ->capture_default_str();
    keyframes->add_option("--fps", options->fps, "Frames per second; key frames sit on frames")
        ->check(CLI::PositiveNumber)
        ->capture_default_str();
    keyframes->add_flag("--tsv", options->tsv, "Write the mouth key frames as time<TAB>shape lines instead of JSON");
    keyframes->add_option("-o,--output", options->output_path, "Output file; - writes to stdout")->required();
    keyframes->callback([options] { run_keyframes(*options); });
}

}  // namespace talkface_cli

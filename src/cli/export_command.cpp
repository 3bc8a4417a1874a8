// `talkface export`: the timing of a speech for the tools animators use (issue #15): Rhubarb cues,
// Moho switch data, a Live2D motion, a Praat TextGrid, subtitles. Format from -o's suffix or --format.
#include <iostream>
#include <memory>
#include <string>

#include <CLI/CLI.hpp>
#include <talkface/talkface.hpp>

#include "animate_command.hpp"
#include "commands.hpp"
#include "progress_bar.hpp"
#include "timing_option.hpp"

namespace talkface_cli {

namespace {

struct ExportOptions {
    std::string audio_path;
    std::string transcript_path;
    std::string output_path;
    std::string format;
    SpeechTiming timing;
    std::uint64_t seed = 0;
    StyleOptions expression;
    double fps = talkface::LipSyncOptions{}.fps;
    bool quiet = false;
};

void run_export(const ExportOptions& options) {
    // The format is settled before the long work, so that a wrong suffix fails at once.
    const std::string format =
        options.format.empty() ? talkface::export_format_for_path(options.output_path) : options.format;
    const talkface::Timeline transcript = talkface::load_transcript(options.transcript_path);
    talkface::Timeline timeline;
    {
        const std::unique_ptr<ProgressBar> bar = make_progress_bar(options.quiet);
        timeline = timed_speech(options.audio_path, transcript, options.timing, progress_part(bar.get(), 0.0, 1.0));
    }
    print_mismatches(options.audio_path, timeline);
    const talkface::ExpressionSimulator simulator(timeline, options.seed, expression_style(options.expression));
    talkface::LipSyncOptions lip_sync;
    lip_sync.fps = options.fps;
    const talkface::Animation animation =
        talkface::animate(talkface::FaceModel::default_face(), timeline, simulator, lip_sync);
    talkface::ExportInput input;
    input.timeline = timeline;
    input.mouth_key_frames = animation.mouth_key_frames;
    input.fps = animation.fps;
    input.frames = animation.frames;
    input.audio_path = options.audio_path;
    if (options.output_path == "-") {
        std::cout << talkface::export_to_string(input, format) << std::flush;
    } else {
        talkface::export_to_file(options.output_path, input, format);
    }
}

}  // namespace

void setup_export_command(CLI::App& app) {
    auto options = std::make_shared<ExportOptions>();
    CLI::App* command = app.add_subcommand(
        "export", "Write a speech's timing for other tools: Rhubarb cues, Moho, Live2D, TextGrid, subtitles");
    command->add_option("AUDIO", options->audio_path, "Recorded speech (WAV, FLAC, OGG)")
        ->required()
        ->check(CLI::ExistingFile);
    command->add_option("TRANSCRIPT", options->transcript_path, "Its transcript, UTF-8")
        ->required()
        ->check(CLI::ExistingFile);
    command
        ->add_option("-o,--output", options->output_path,
                     "Output file (- is stdout, with --format); its suffix picks the format: .tsv .xml .dat "
                     ".motion3.json .TextGrid .srt .vtt")
        ->required();
    command
        ->add_option("--format", options->format,
                     "rhubarb-tsv, rhubarb-json, rhubarb-xml, moho, live2d, textgrid, srt or vtt "
                     "(docs/timing-formats.md); needed for any other .json")
        ->check(CLI::IsMember(talkface::export_format_names()));
    add_timing_option(*command, options->timing);
    command->add_option("--seed", options->seed, "Seed of the simulated blinks and head moves (live2d)")
        ->capture_default_str();
    add_style_options(*command, options->expression);
    command->add_option("--fps", options->fps, "Frames per second: Moho's frame numbers, Live2D's frames")
        ->check(CLI::PositiveNumber)
        ->capture_default_str();
    command->add_flag("-q,--quiet", options->quiet, "No progress bar");
    command->callback([options] {
        if (options->output_path == "-" && options->format.empty()) {
            throw CLI::ValidationError("--format", "writing to stdout (-o -) needs --format");
        }
        run_export(*options);
    });
}

}  // namespace talkface_cli

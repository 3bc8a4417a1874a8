// `talkface export`: the timing of a speech for the tools animators use (issue #15): Rhubarb cues,
// Moho switch data, a Live2D motion, a Praat TextGrid, subtitles; the talking face itself as Lottie.
// Format from -o's suffix or --format.
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <talkface/talkface.hpp>

#include "animate_command.hpp"
#include "commands.hpp"
#include "error_report.hpp"
#include "progress_bar.hpp"
#include "timing_option.hpp"

namespace talkface_cli {

namespace {

struct ExportOptions {
    std::string audio_path;
    TranscriptArgument transcript;
    std::string format;
    AnimateOptions animate;  // face, look, fps, seed, style, output, timing (and --lenient), quiet
};

// The formats of export_to_string() and the face itself as Lottie, which SvgAnimator draws.
std::vector<std::string> format_names() {
    std::vector<std::string> names = talkface::export_format_names();
    names.emplace_back("lottie");
    return names;
}

void run_export(const ExportOptions& options) {
    const std::string& output_path = options.animate.output_path;
    // The format is settled before the long work, so that a wrong suffix fails at once.
    const std::string format = options.format.empty() ? talkface::export_format_for_path(output_path) : options.format;
    const talkface::Timeline transcript = load_transcript_to_time(options.transcript);
    TalkingFace talking;
    {
        const std::unique_ptr<ProgressBar> bar = make_progress_bar(options.animate.quiet);
        talking = animate_talking_face(options.animate, options.audio_path, transcript,
                                       progress_part(bar.get(), 0.0, 1.0));
    }
    report_warnings(talking.timeline);
    if (format == "lottie") {
        const talkface::SvgAnimator animator(talking.face, svg_options(options.animate));
        talkface::LottieOptions lottie;
        lottie.tolerance_px = options.animate.tolerance_px;
        const std::unique_ptr<ProgressBar> bar = make_progress_bar(options.animate.quiet);
        const auto progress = progress_part(bar.get(), 0.0, 1.0);
        if (output_path == "-") {
            std::cout << animator.render_animation_lottie(talking.animation, lottie, progress) << std::flush;
        } else {
            animator.write_animation_lottie(output_path, talking.animation, lottie, progress);
        }
        return;
    }
    talkface::ExportInput input;
    input.timeline = talking.timeline;
    input.mouth_key_frames = talking.animation.mouth_key_frames;
    input.fps = talking.animation.fps;
    input.frames = talking.animation.frames;
    input.audio_path = options.audio_path;
    if (output_path == "-") {
        std::cout << talkface::export_to_string(input, format) << std::flush;
    } else {
        talkface::export_to_file(output_path, input, format);
    }
}

}  // namespace

void setup_export_command(CLI::App& app) {
    auto options = std::make_shared<ExportOptions>();
    CLI::App* command = app.add_subcommand(
        "export",
        "Write a speech's timing for other tools: Rhubarb cues, Moho, Live2D, TextGrid, subtitles; the face as Lottie");
    command->add_option("AUDIO", options->audio_path, kSpeechFormatsHelp)
        ->required()
        ->check(CLI::ExistingFile);
    add_transcript_argument(*command, options->transcript, "Its transcript (as `talkface align` reads it)")
        ->required();
    command
        ->add_option("-o,--output", options->animate.output_path,
                     "Output file (- is stdout, with --format); its suffix picks the format: .tsv .xml .dat "
                     ".motion3.json .TextGrid .srt .vtt")
        ->required();
    command
        ->add_option("--format", options->format,
                     "rhubarb-tsv, rhubarb-json, rhubarb-xml, moho, live2d, textgrid, srt, vtt or lottie "
                     "(docs/timing-formats.md); needed for any other .json")
        ->check(CLI::IsMember(format_names()));
    add_timing_option(*command, options->animate.timing);
    add_face_options(*command, options->animate);
    add_tolerance_option(*command, options->animate);
    std::vector<CLI::Option*> drawing;
    for (const char* name : {"--look", "--stroke-width", "--no-clothes", "--tolerance"}) {
        CLI::Option* option = command->get_option(name);
        option->description(option->get_description() +
                            "; the lottie export only (a timing format refuses it)");
        drawing.push_back(option);
    }
    command->add_flag("-q,--quiet", options->animate.quiet, "No progress bar");
    command->callback([options, drawing] {
        // A timing format has no face to paint: a drawing option it would drop is refused, not
        // ignored (Lottie is only ever named by --format: its .json suffix is ambiguous).
        for (const CLI::Option* option : drawing) {
            if (option->count() > 0 && options->format != "lottie") {
                throw CLI::ValidationError(option->get_name(),
                                           "only the lottie export draws the face; the other "
                                           "formats carry the timing alone (--format lottie to "
                                           "export the face)");
            }
        }
        if (options->animate.output_path == "-" && options->format.empty()) {
            throw CLI::ValidationError("--format", "writing to stdout (-o -) needs --format");
        }
        run_export(*options);
    });
}

}  // namespace talkface_cli

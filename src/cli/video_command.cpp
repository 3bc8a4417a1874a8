// `talkface video`: a speech, its transcript and a face in, a video of the talking face with the
// voice out (issue #16): MP4, WebM, animated WebP or a PNG sequence, by the output's extension.
#include "video_command.hpp"

#include <csignal>
#include <cstdlib>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>

#include "commands.hpp"
#include "error_report.hpp"
#include "progress_bar.hpp"
#include "timing_option.hpp"

namespace talkface_cli {

namespace {

// Share of the whole job in the progress bar until the face is animated; drawing and encoding
// the frames take the rest.
constexpr double kVideoAnimatedAt = 0.15;

// Set by Ctrl-C while a video is made: the progress callback then stops the work, the library
// removes its temporary file, and the command exits 130 with nothing written.
volatile std::sig_atomic_t g_is_interrupted = 0;

extern "C" void note_interrupt(int) { g_is_interrupted = 1; }

// The main program's handler exits at once, which suits outputs written in one go; a video takes
// minutes, so Ctrl-C asks the work to stop instead, while this lives.
class InterruptScope {
public:
    InterruptScope() : previous_(std::signal(SIGINT, note_interrupt)) { g_is_interrupted = 0; }
    ~InterruptScope() { std::signal(SIGINT, previous_); }
    InterruptScope(const InterruptScope&) = delete;
    InterruptScope& operator=(const InterruptScope&) = delete;

private:
    void (*previous_)(int);
};

// `bar`'s part [start, end] of the job, stopping when Ctrl-C was pressed.
talkface::ProgressCallback interruptible(ProgressBar* bar, double start, double end) {
    const auto part = progress_part(bar, start, end);
    return [part](double fraction, const std::string& stage) {
        if (g_is_interrupted != 0) return false;
        return part ? part(fraction, stage) : true;
    };
}

std::pair<int, int> parse_size(const std::string& text) {
    std::istringstream in(text);
    int width = 0, height = 0;
    char separator = 0;
    in >> width >> separator >> height;
    return {width, height};
}

CLI::Validator size_validator() {
    return CLI::Validator(
        [](std::string& text) -> std::string {
            std::istringstream in(text);
            int width = 0, height = 0;
            char separator = 0;
            if ((in >> width >> separator >> height) && separator == 'x' && (in >> std::ws).eof()) return {};
            return "expected WIDTHxHEIGHT in pixels (e.g. 1280x720), found \"" + text + "\"";
        },
        "WIDTHxHEIGHT");
}

talkface::FaceVideoOptions face_video_options(const VideoCommandOptions& options) {
    talkface::FaceVideoOptions video;
    const auto [width, height] = parse_size(options.size);
    video.video.width_px = width;
    video.video.height_px = height;
    video.video.fps = options.animate.fps;
    video.video.crf = options.crf;
    video.video.transparent = options.transparent;
    video.frame.layout = options.app == "plain" ? talkface::FrameLayout::face : talkface::FrameLayout::announcer;
    video.frame.look = options.animate.look;
    video.frame.stroke_width_in_d = options.animate.stroke_width_in_d;
    video.frame.draw_clothes = !options.animate.no_clothes;
    video.frame.face_origin_px = face_origin_px(options.animate);
    video.frame.face_d_px = options.animate.face_d;
    const std::string& background = options.animate.background;
    if (!background.empty()) {
        if (background.front() == '#') {
            video.frame.background = talkface::rgb_from_hex(background, "--background");
        } else {
            video.background_image_path = background;
        }
    }
    return video;
}

// The library names its parameters (width_px, fps ...); the command names its options.
[[noreturn]] void rethrow_as_option_error(const talkface::InvalidArgument& error) {
    const std::string& parameter = error.parameter();
    const char* option = parameter == "width_px" || parameter == "height_px" ? "--size"
                         : parameter == "fps"                               ? "--fps"
                         : parameter == "crf"                               ? "--crf"
                         : parameter == "transparent"                       ? "--transparent"
                                                                            : "--output";
    throw CLI::ValidationError(option, error.what());
}

}  // namespace

void add_video_options(CLI::App& command, VideoCommandOptions& options) {
    options.animate.fps = talkface::VideoOptions{}.fps;
    add_face_options(command, options.animate);
    add_timing_option(command, options.animate.timing);
    command.add_option("--size", options.size, "Frame size WIDTHxHEIGHT in pixels (even for .mp4 and .webm)")
        ->check(size_validator())
        ->capture_default_str();
    command
        .add_option("--app", options.app,
                    "announcer: the face on a stage over a background, as tall as the frame; plain: the face's own "
                    "canvas fitted into the frame")
        ->check(CLI::IsMember({"announcer", "plain"}))
        ->capture_default_str();
    command.add_option("--background", options.animate.background,
                       "The frame's background: a colour #rrggbb or a picture file (PNG, JPEG, WebP, SVG ...)");
    add_face_placement_options(command, options.animate, "announcer: in the frame");
    command.add_option("--crf", options.crf,
                       "Constant quality, lower is better and larger: H.264 0..51 (default 20), VP9 0..63 (32)");
    command.add_flag("--transparent", options.transparent,
                     "Keep an alpha channel where nothing is drawn (.webm, .webp, .gif, .png only)");
    command
        .add_option("-o,--output", options.animate.output_path,
                    "OUT.mp4 (H.264 + AAC), OUT.webm (VP9 + Opus), OUT.webp or OUT.gif (animated, no sound; .gif "
                    "up to 50 fps) or OUT.png (OUT-000000.png ...)")
        ->required();
    command.add_flag("-q,--quiet", options.animate.quiet, "No progress bar");
}

void make_video(const VideoCommandOptions& options, const std::string& audio_path,
                const talkface::Timeline& transcript) {
    talkface::FaceVideoOptions video = face_video_options(options);
    try {
        // Before the alignment, the slow part: a bad size, rate or extension fails at once.
        talkface::check_video_options(options.animate.output_path, video.video);
    } catch (const talkface::InvalidArgument& error) {
        rethrow_as_option_error(error);
    }
    const InterruptScope interrupt_scope;
    const std::unique_ptr<ProgressBar> bar = make_progress_bar(options.animate.quiet);
    try {
        const TalkingFace talking = animate_talking_face(options.animate, audio_path, transcript,
                                                         interruptible(bar.get(), 0.0, kVideoAnimatedAt));
        talkface::render_video(options.animate.output_path, talking.face, talking.animation, audio_path, video,
                               interruptible(bar.get(), kVideoAnimatedAt, 1.0));
        report_warnings(talking.timeline);
    } catch (const talkface::Cancelled&) {
        if (g_is_interrupted == 0) throw;
        std::cerr << "\ntalkface: interrupted; " << options.animate.output_path << " was not written\n";
        std::_Exit(kExitInterrupted);
    }
}

bool is_video_output(const std::string& path) {
    try {
        talkface::video_format_from_path(path);
        return true;
    } catch (const talkface::InvalidArgument&) {
        return false;
    }
}

void setup_video_command(CLI::App& app) {
    auto options = std::make_shared<VideoCommandOptions>();
    auto audio_path = std::make_shared<std::string>();
    auto transcript = std::make_shared<TranscriptArgument>();
    CLI::App* video = app.add_subcommand(
        "video", "Make a video of the face talking in sync with a speech (MP4, WebM, animated WebP or GIF, or PNG frames)");
    add_speech_arguments(*video, *audio_path, *transcript);
    add_video_options(*video, *options);
    video->callback([options, audio_path, transcript] {
        make_video(*options, *audio_path, load_transcript_to_time(*transcript));
    });
}

}  // namespace talkface_cli

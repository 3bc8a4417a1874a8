// `talkface animate`: a speech, its transcript and a face in, a web page where the face talks in
// sync with the voice out (issue #6; thesis 6.3.2 and chapter 7), or the bare SVG animation.
#include "animate_command.hpp"

#include <filesystem>
#include <iostream>
#include <locale>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <utility>

#include "choice_option.hpp"
#include "commands.hpp"
#include "error_report.hpp"
#include "progress_bar.hpp"
#include "timing_option.hpp"
#include "written_report.hpp"

namespace talkface_cli {

namespace {

// Share of the whole job in the progress bar until the face is animated: alignment is most of it.
constexpr double kAnimatedAt = 0.6;
// Alignment's share of animate_talking_face(); animating is the rest.
constexpr double kAlignmentShare = 0.9;

std::optional<std::pair<double, double>> parse_pair(const std::string& text, char separator) {
    std::istringstream in(text);
    in.imbue(std::locale::classic());
    double first = 0.0, second = 0.0;
    if (!(in >> first) || in.get() != separator || !(in >> second)) return std::nullopt;
    in >> std::ws;
    if (!in.eof()) return std::nullopt;
    return std::make_pair(first, second);
}

CLI::Validator pair_validator(char separator, const std::string& form, const std::string& example) {
    return CLI::Validator(
        [separator, form, example](std::string& text) -> std::string {
            if (parse_pair(text, separator)) return {};
            return "expected " + form + " (e.g. " + example + "), found \"" + text + "\"";
        },
        form);
}

bool is_svg_output(const std::string& path) {
    const std::filesystem::path extension = std::filesystem::path(path).extension();
    return extension == ".svg" || extension == ".SVG";
}

talkface::WebPageOptions page_options(const AnimateOptions& options) {
    talkface::WebPageOptions page;
    page.app = talkface::web_page_app_from_name(options.app);
    page.title = options.title;
    page.animation.encoding = talkface::animation_encoding_from_name(options.encoding);
    page.audio = options.audio;
    page.audio_bitrate_bps = options.audio_bitrate;
    for (const std::string& link : options.links) {
        const std::size_t equals = link.find('=');
        // "TEXT=URL"; an absolute URL may hold '=' in its query, after its "://".
        if (equals != std::string::npos && link.find("://") > equals) {
            page.links.push_back({link.substr(0, equals), link.substr(equals + 1)});
        } else {
            page.links.push_back({link, link});
        }
    }
    if (!options.background.empty()) {
        if (options.background.front() == '#') {
            page.stage_colour = talkface::rgb_from_hex(options.background, "--background");
        } else {
            page.background_image_path = options.background;
        }
    }
    page.face_origin_px = face_origin_px(options);
    page.face_d_px = options.face_d;
    page.animation.tolerance_px = options.tolerance_px;
    const auto stage = parse_pair(options.stage, 'x').value_or(std::make_pair(800.0, 450.0));
    page.stage_width_px = static_cast<int>(stage.first);
    page.stage_height_px = static_cast<int>(stage.second);
    return page;
}

const char* mouth_interpolation_name(talkface::MouthInterpolation interpolation) {
    return interpolation == talkface::MouthInterpolation::smooth ? "smooth" : "linear";
}

void add_lip_sync_options(CLI::App& command, talkface::LipSyncOptions& lip_sync) {
    command
        .add_option(
            "--rest-min-pause", lip_sync.rest_min_pause_s,
            "Seconds between syllables from which the mouth closes to rest; shorter gaps keep it moving")
        ->check(CLI::NonNegativeNumber)
        ->capture_default_str();
    command
        .add_option(
            "--rest-transition", lip_sync.rest_transition_s,
            "Seconds the mouth takes to reach rest after a pause starts and to leave it before speech")
        ->check(CLI::NonNegativeNumber)
        ->capture_default_str();
    command
        .add_option("--max-mouth-speed", lip_sync.max_speed_mns0_per_s,
                    "Fastest a mouth point moves, mouth-nose separations (MNS0) a second")
        ->check(CLI::PositiveNumber)
        ->capture_default_str();
    command
        .add_option("--mouth-interpolation", lip_sync.interpolation,
                    "Between key frames: linear (the thesis's) or smooth (eased in and out)")
        ->transform(choice_of({talkface::MouthInterpolation::linear, talkface::MouthInterpolation::smooth},
                              mouth_interpolation_name))
        ->type_name("TEXT")
        ->default_str(mouth_interpolation_name(lip_sync.interpolation));
}

void run_animate(const AnimateOptions& options, const std::string& audio_path,
                 const TranscriptArgument& transcript) {
    std::string linked_url;
    if (options.audio == talkface::WebPageAudio::link) {
        // The page links the audio where it lies, relative to the page's folder.
        const std::filesystem::path page_folder =
            std::filesystem::absolute(options.output_path).parent_path();
        linked_url = std::filesystem::relative(std::filesystem::absolute(audio_path), page_folder).generic_string();
    }
    make_talking_face(options, audio_path, load_transcript_to_time(transcript), linked_url);
}

}  // namespace

talkface::SvgOptions svg_options(const AnimateOptions& options) {
    talkface::SvgOptions drawing;
    drawing.look = options.look;
    drawing.stroke_width_in_d = options.stroke_width_in_d;
    drawing.draw_clothes = !options.no_clothes;
    drawing.decimals = options.decimals;
    return drawing;
}

void add_speech_arguments(CLI::App& command, std::string& audio_path, TranscriptArgument& transcript) {
    command.add_option("AUDIO", audio_path, kSpeechFormatsHelp)
        ->required()
        ->check(CLI::ExistingFile);
    add_transcript_argument(command, transcript, "Its transcript (as `talkface align` reads it)")->required();
}

void add_style_options(CLI::App& command, StyleOptions& options) {
    command
        .add_option("--style", options.style,
                    "Simulated behaviour: normal, announcer (faster head moves), or a style file "
                    "(JSON, docs/style-format.md)")
        ->check(CLI::IsMember({"normal", "announcer"}) | CLI::ExistingFile)
        ->capture_default_str();
    command
        .add_option("--without", options.without,
                    "Event kinds not to simulate, comma-separated: blink, brows, tilt, turn, nod")
        ->delimiter(',')
        ->check(CLI::IsMember({"blink", "brows", "tilt", "turn", "nod"}));
}

talkface::ExpressionStyle expression_style(const StyleOptions& options) {
    // A name wins over a file of that name in the working folder.
    talkface::ExpressionStyle style = options.style == "normal" || options.style == "announcer"
                                          ? talkface::ExpressionStyle::from_name(options.style)
                                          : talkface::ExpressionStyle::load(options.style);
    for (const std::string& kind : options.without) {
        style.set_simulated(talkface::expression_event_kind_from_name(kind), false);
    }
    return style;
}

void add_look_option(CLI::App& command, talkface::FaceLook& look) {
    command.add_option("--look", look, "How the face is painted: outlined (the thesis's cartoon) or flat (no outlines)")
        ->transform(choice_of({talkface::FaceLook::outlined, talkface::FaceLook::flat}, talkface::face_look_name))
        ->type_name("TEXT")
        ->default_str(talkface::face_look_name(look));
}

void add_stroke_width_option(CLI::App& command, double& stroke_width_in_d) {
    command
        .add_option("--stroke-width", stroke_width_in_d, "outlined: the outlines' width, in eye distances d")
        ->check(CLI::PositiveNumber)
        ->capture_default_str();
}

void add_decimals_option(CLI::App& command, int& decimals) {
    command
        .add_option("--decimals", decimals,
                    "Digits after the point in the SVG's coordinates, 0.." +
                        std::to_string(talkface::kMaxSvgDecimals))
        ->check(CLI::Range(0, talkface::kMaxSvgDecimals))
        ->capture_default_str();
}

void add_face_options(CLI::App& command, AnimateOptions& options) {
    command.add_option("--face", options.face_path, "Face model file (default: the built-in face)")
        ->check(CLI::ExistingFile);
    add_look_option(command, options.look);
    add_stroke_width_option(command, options.stroke_width_in_d);
    command.add_flag("--no-clothes", options.no_clothes, "Leave out the neck and shoulders");
    command.add_option("--fps", options.fps, "Frames per second of the animation")
        ->check(CLI::Range(1.0, 120.0))
        ->capture_default_str();
    add_lip_sync_options(command, options.lip_sync);
    command.add_option("--seed", options.seed, "Seed of the simulated blinks and head moves")->capture_default_str();
    add_style_options(command, options.expression);
}

void add_face_placement_options(CLI::App& command, AnimateOptions& options, const std::string& where) {
    command
        .add_option("--face-origin", options.face_origin,
                    "Where the face's neck (rotation origin O) stands, X,Y in pixels (" + where + ")")
        ->check(pair_validator(',', "X,Y", "600,420"));
    command.add_option("--face-d", options.face_d, "The face's eye distance d, pixels (" + where + ")")
        ->check(CLI::PositiveNumber);
}

std::optional<talkface::Point2> face_origin_px(const AnimateOptions& options) {
    if (options.face_origin.empty()) return std::nullopt;
    const auto origin = parse_pair(options.face_origin, ',').value_or(std::make_pair(0.0, 0.0));
    return talkface::Point2{origin.first, origin.second};
}

void add_tolerance_option(CLI::App& command, AnimateOptions& options) {
    command
        .add_option(
            "--tolerance", options.tolerance_px,
            "keyframes and Lottie: how far, in the face's pixels, the animation may stray from a frame; "
            "larger: smaller files")
        ->check(CLI::PositiveNumber)
        ->capture_default_str();
}

void add_page_options(CLI::App& command, AnimateOptions& options) {
    add_face_options(command, options);
    command
        .add_option("--encoding", options.encoding,
                    "keyframes: the face animated between key frames (small); frames: one group per frame")
        ->check(CLI::IsMember({"keyframes", "frames"}))
        ->capture_default_str();
    command
        .add_option("--audio-embed", options.audio,
                    "compressed: the speech encoded anew (Opus in WebM, mono, plays in Chromium, Firefox and "
                    "Safari 17.4+) and embedded; original: the audio file's own bytes embedded; link: the page "
                    "links the audio file (keep it beside the page)")
        ->transform(choice_of({talkface::WebPageAudio::compressed, talkface::WebPageAudio::original,
                               talkface::WebPageAudio::link},
                              talkface::web_page_audio_name))
        ->type_name("TEXT")
        ->default_str(talkface::web_page_audio_name(options.audio));
    command.add_flag_callback(
        "--link-audio", [&options] { options.audio = talkface::WebPageAudio::link; },
        "The same as --audio-embed link");
    command
        .add_option("--audio-bitrate", options.audio_bitrate,
                    "compressed: the Opus bit rate, bits a second (default 11000: wideband speech)")
        ->check(CLI::Range(6000, 128000));
    command
        .add_option("--app", options.app,
                    "plain; announcer: the face on a stage with a background; audiobook: title, text with the "
                    "spoken sentence highlighted, links, the face beside them")
        ->check(CLI::IsMember({"plain", "announcer", "audiobook"}))
        ->capture_default_str();
    command.add_option("--title", options.title,
                       "Title of the page (default: the first sentence, cut to 30 characters)");
    command.add_option("--link", options.links, "audiobook: a link under the text, TEXT=URL or URL (repeatable)");
    command.add_option("--background", options.background,
                       "announcer: the stage's background, a colour #rrggbb or an image file (PNG, JPEG, SVG ...)");
    add_decimals_option(command, options.decimals);
    add_face_placement_options(command, options, "announcer: on the stage");
    add_tolerance_option(command, options);
    command.add_option("--stage", options.stage, "announcer: the stage's size, WIDTHxHEIGHT in pixels (its shape; the page shows it as large as the "
                       "window lets it be)")
        ->check(pair_validator('x', "WIDTHxHEIGHT", "800x450"))
        ->capture_default_str();
    command.add_option("-o,--output", options.output_path, "OUT.html for a web page, OUT.svg for the bare animation (demo: OUT.mp4, .webm, .webp, .gif, .png for a video)")
        ->required();
    command.add_flag("-q,--quiet", options.quiet,
                     "No progress bar, and no line saying what was written (its kind, duration and size)");
}

TalkingFace animate_talking_face(const AnimateOptions& options, const std::string& audio_path,
                                 const talkface::Timeline& transcript, const talkface::ProgressCallback& progress) {
    const talkface::ExpressionStyle style = expression_style(options.expression);
    talkface::FaceModel face =
        options.face_path.empty() ? talkface::FaceModel::default_face() : talkface::FaceModel::load(options.face_path);
    talkface::ProgressCallback alignment_progress;
    if (progress) {
        alignment_progress = [&progress](double fraction, const std::string& stage) {
            return progress(fraction * kAlignmentShare, stage);
        };
    }
    talkface::Timeline timeline = timed_speech(audio_path, transcript, options.timing, alignment_progress);
    const talkface::ExpressionSimulator simulator(timeline, options.seed, style);
    talkface::LipSyncOptions lip_sync = options.lip_sync;
    lip_sync.fps = options.fps;
    talkface::Animation animation = talkface::animate(face, timeline, simulator, lip_sync);
    if (progress) progress(1.0, "animating");
    return {std::move(face), std::move(timeline), std::move(animation)};
}

void make_talking_face(const AnimateOptions& options, const std::string& audio_path,
                       const talkface::Timeline& transcript, const std::string& linked_audio_url) {
    const bool is_svg = is_svg_output(options.output_path);
    if (is_svg && (options.app != "plain" || options.audio == talkface::WebPageAudio::link)) {
        throw CLI::ValidationError("--output", "an .svg output is the bare animation: --app and --link-audio need .html");
    }
    // Read before the alignment, the slow part: a bad option fails at once.
    talkface::WebPageOptions page = page_options(options);
    page.audio_url = linked_audio_url;
    const std::unique_ptr<ProgressBar> bar = make_progress_bar(options.quiet);
    const TalkingFace talking =
        animate_talking_face(options, audio_path, transcript, progress_part(bar.get(), 0.0, kAnimatedAt));
    const talkface::Timeline& timeline = talking.timeline;
    const talkface::Animation& animation = talking.animation;
    const talkface::SvgAnimator animator(talking.face, svg_options(options));
    // The output is written whole at the end (a temporary file renamed): a failure leaves no page.
    if (is_svg) {
        animator.write_animation_svg(options.output_path, animation, page.animation,
                                     progress_part(bar.get(), kAnimatedAt, 1.0));
    } else {
        talkface::write_web_page(options.output_path, animator, animation, timeline, audio_path, page,
                                 progress_part(bar.get(), kAnimatedAt, 1.0));
    }
    if (!options.quiet) {
        const std::string what = is_svg ? "SVG animation (" + options.encoding + ")"
                                        : options.app + " web page, audio " +
                                              (options.audio == talkface::WebPageAudio::link       ? "linked"
                                               : options.audio == talkface::WebPageAudio::original ? "embedded as it is"
                                                                             : "compressed and embedded");
        report_written(std::cerr, options.output_path, what, animation.duration_s);
    }
    report_warnings(timeline);
}

void setup_animate_command(CLI::App& app) {
    auto options = std::make_shared<AnimateOptions>();
    auto audio_path = std::make_shared<std::string>();
    auto transcript = std::make_shared<TranscriptArgument>();
    CLI::App* animate = app.add_subcommand(
        "animate", "Make a web page where the face talks in sync with a speech (or the bare SVG animation)");
    add_speech_arguments(*animate, *audio_path, *transcript);
    add_page_options(*animate, *options);
    add_timing_option(*animate, options->timing);
    animate->callback([options, audio_path, transcript] { run_animate(*options, *audio_path, *transcript); });
}

}  // namespace talkface_cli

// `talkface render`: one face state (pose, expression, mouth) drawn as an SVG document.
#include <exception>
#include <iostream>
#include <optional>
#include <sstream>
#include <string>

#include <CLI/CLI.hpp>
#include <talkface/talkface.hpp>

#include "animate_command.hpp"
#include "commands.hpp"

namespace talkface_cli {

namespace {

struct RenderOptions {
    std::string face_path;  // empty: the built-in default face
    std::string pose_text = "0,0,0";
    std::string mouth_name;  // empty: the face's own neutral mouth
    std::optional<double> blink;
    std::optional<double> blink_left;
    std::optional<double> blink_right;
    double smile = 0.0;
    double brows = 0.0;
    std::string background = talkface::to_hex(*talkface::SvgOptions{}.background);
    bool no_clothes = false;
    talkface::FaceLook look = talkface::FaceLook::outlined;
    double stroke_width_in_d = talkface::SvgOptions{}.stroke_width_in_d;
    int decimals = talkface::SvgOptions{}.decimals;
    std::string output_path;
};

// "ALPHA,BETA,GAMMA" in degrees; nullopt unless it is exactly three numbers.
std::optional<talkface::Pose> parse_pose(const std::string& text) {
    std::istringstream in(text);
    in.imbue(std::locale::classic());
    double angles[3];
    for (int i = 0; i < 3; ++i) {
        if (!(in >> angles[i])) return std::nullopt;
        if (i < 2 && in.get() != ',') return std::nullopt;
    }
    in >> std::ws;
    if (!in.eof()) return std::nullopt;
    return talkface::Pose{angles[0], angles[1], angles[2]};
}

std::optional<talkface::Rgb> parse_background(const std::string& text) {
    if (text == "none") return std::nullopt;
    return talkface::rgb_from_hex(text, "--background");
}

const CLI::Validator& pose_validator() {
    static const CLI::Validator validator(
        [](std::string& text) -> std::string {
            if (parse_pose(text)) return {};
            return "expected three comma-separated angles ALPHA,BETA,GAMMA in degrees (e.g. 0,10,-5), "
                   "found \"" + text + "\"";
        },
        "ALPHA,BETA,GAMMA");
    return validator;
}

const CLI::Validator& mouth_validator() {
    static const CLI::Validator validator(
        [](std::string& text) -> std::string {
            try {
                talkface::mouth_shape_from_name(text);
                return {};
            } catch (const talkface::InvalidArgument& error) {
                return error.what();
            }
        },
        "SHAPE");
    return validator;
}

const CLI::Validator& background_validator() {
    static const CLI::Validator validator(
        [](std::string& text) -> std::string {
            try {
                parse_background(text);
                return {};
            } catch (const talkface::InvalidArgument& error) {
                return error.what();
            }
        },
        "COLOUR|none");
    return validator;
}

void run_render(const RenderOptions& options) {
    // Everything is computed before the output is opened: a bad face or pose leaves no file.
    const talkface::FaceModel face = options.face_path.empty()
                                         ? talkface::FaceModel::default_face()
                                         : talkface::FaceModel::load(options.face_path);
    talkface::FaceState state;
    // The validators have accepted the pose already.
    state.pose = parse_pose(options.pose_text).value_or(talkface::Pose{});
    state.expression.blink_left = options.blink_left.value_or(options.blink.value_or(0.0));
    state.expression.blink_right = options.blink_right.value_or(options.blink.value_or(0.0));
    state.expression.smile = options.smile;
    state.expression.brows = options.brows;
    if (!options.mouth_name.empty()) {
        state.mouth = talkface::mouth_controls(face, talkface::mouth_shape_from_name(options.mouth_name));
    }
    talkface::SvgOptions svg_options;
    svg_options.background = parse_background(options.background);
    svg_options.draw_clothes = !options.no_clothes;
    svg_options.look = options.look;
    svg_options.stroke_width_in_d = options.stroke_width_in_d;
    svg_options.decimals = options.decimals;
    const talkface::SvgAnimator animator(face, svg_options);
    try {
        if (options.output_path == "-") {
            std::cout << animator.render_svg(state) << std::flush;
        } else {
            animator.write_svg(options.output_path, state);
        }
    } catch (const talkface::Error& error) {
        std::throw_with_nested(talkface::Error(
            error.code(), "cannot render " + (options.face_path.empty() ? "the default face" : options.face_path) +
                              " at --pose " + options.pose_text + " to " + options.output_path));
    }
}

}  // namespace

void setup_render_command(CLI::App& app) {
    auto options = std::make_shared<RenderOptions>();
    CLI::App* render = app.add_subcommand("render", "Draw one face state as an SVG file");
    render->add_option("--face", options->face_path, "Face file (docs/face-format.md); default: built-in face")
        ->check(CLI::ExistingFile);
    render->add_option("--pose", options->pose_text, "Head pose in degrees: nod, turn, tilt, each within +-15")
        ->check(pose_validator())
        ->capture_default_str();
    render->add_option("--mouth", options->mouth_name,
                       "Mouth shape: m f h' h r z a i u e o n; default: the neutral mouth")
        ->check(mouth_validator());
    render->add_option("--blink", options->blink, "Both eyes closed by this much, 0..1")
        ->check(CLI::Range(0.0, 1.0));
    render->add_option("--blink-left", options->blink_left, "Image-left eye closed by this much, 0..1")
        ->check(CLI::Range(0.0, 1.0));
    render->add_option("--blink-right", options->blink_right, "Image-right eye closed by this much, 0..1")
        ->check(CLI::Range(0.0, 1.0));
    render->add_option("--smile", options->smile, "Smile amount, 0..1")->check(CLI::Range(0.0, 1.0));
    render->add_option("--brows", options->brows, "Eyebrow raise, 0..1")->check(CLI::Range(0.0, 1.0));
    render->add_option("--background", options->background, "Background colour #rrggbb, or none")
        ->check(background_validator())
        ->capture_default_str();
    render->add_flag("--no-clothes", options->no_clothes, "Leave out the neck and shoulders");
    add_look_option(*render, options->look);
    add_stroke_width_option(*render, options->stroke_width_in_d);
    add_decimals_option(*render, options->decimals);
    render->add_option("-o,--output", options->output_path, "Output SVG file; - writes to stdout")
        ->required();
    render->callback([options] { run_render(*options); });
}

}  // namespace talkface_cli

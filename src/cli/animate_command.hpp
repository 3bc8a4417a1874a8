// What `talkface animate` and `talkface demo` share: a speech, its transcript and a face in, a
// talking face out, as a web page or a bare SVG animation (animate_command.cpp); and the options
// of the simulated expressions, which `talkface keyframes` takes too.
#ifndef TALKFACE_CLI_ANIMATE_COMMAND_HPP
#define TALKFACE_CLI_ANIMATE_COMMAND_HPP

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <talkface/talkface.hpp>

#include "progress_bar.hpp"
#include "timing_option.hpp"

namespace talkface_cli {

// --style NAME|FILE.json and --without KIND,...
struct StyleOptions {
    std::string style = "normal";      // a named style, or a style JSON file (docs/style-format.md)
    std::vector<std::string> without;  // event kinds not simulated
};

// Adds the AUDIO and TRANSCRIPT arguments (existing files) of the commands that animate a speech, and
// the transcript's options.
void add_speech_arguments(CLI::App& command, std::string& audio_path, TranscriptArgument& transcript);

// Adds --style and --without to `command`.
void add_style_options(CLI::App& command, StyleOptions& options);

// The style the options give: the named or read style with the kinds of --without switched off.
// Throws talkface::ParseError / FileError naming the style file.
talkface::ExpressionStyle expression_style(const StyleOptions& options);

struct AnimateOptions {
    std::string face_path;  // empty: the built-in face
    double fps = talkface::LipSyncOptions{}.fps;
    // --rest-min-pause, --rest-transition, --max-mouth-speed, --mouth-interpolation; its fps is --fps's.
    talkface::LipSyncOptions lip_sync;
    double stroke_width_in_d = talkface::SvgOptions{}.stroke_width_in_d;  // --stroke-width
    bool no_clothes = false;                                              // --no-clothes
    int decimals = talkface::SvgOptions{}.decimals;                       // --decimals (pages and SVG)
    double tolerance_px = talkface::SvgAnimationOptions{}.tolerance_px;   // --tolerance
    std::uint64_t seed = 0;
    StyleOptions expression;
    talkface::FaceLook look = talkface::FaceLook::outlined;
    std::string encoding = "keyframes";
    talkface::WebPageAudio audio = talkface::WebPageAudio::compressed;  // --audio-embed, --link-audio
    int audio_bitrate = 0;             // --audio-bitrate, bits a second (0: the page's default)
    std::string app = "plain";
    std::string title;
    std::vector<std::string> links;  // "TEXT=URL" or "URL"
    std::string background;          // "#rrggbb" or an image file
    std::string face_origin;         // "X,Y"
    double face_d = 0.0;
    std::string stage = "800x450";
    std::string output_path;
    SpeechTiming timing;  // --timing FILE instead of aligning, --lenient
    bool quiet = false;
};

// Adds --face, --look, --stroke-width, --no-clothes, --fps, the lip-sync options, --seed, --style
// and --without: what every command that animates a face from a speech takes (animate, demo, video,
// export).
void add_face_options(CLI::App& command, AnimateOptions& options);

// Adds --face-origin X,Y and --face-d, where the face stands and how large; `where` names the
// picture they place it in ("announcer: ... on the stage", "... in the frame").
void add_face_placement_options(CLI::App& command, AnimateOptions& options, const std::string& where);

// --face-origin's point, if it was given.
std::optional<talkface::Point2> face_origin_px(const AnimateOptions& options);

// Adds --tolerance, how far an animation's key frames may stray from its frames (SVG and Lottie).
void add_tolerance_option(CLI::App& command, AnimateOptions& options);

// Adds --look (outlined or flat) to a command that draws a face.
void add_look_option(CLI::App& command, talkface::FaceLook& look);

// Adds --stroke-width, the outlines' width in eye distances d, to a command that draws a face.
void add_stroke_width_option(CLI::App& command, double& stroke_width_in_d);

// Adds --decimals, the digits after the point of an SVG's coordinates, to a command that writes SVG.
void add_decimals_option(CLI::App& command, int& decimals);

// Adds the options both page commands take (all but the inputs) to `command`: add_face_options()
// and the page's own.
void add_page_options(CLI::App& command, AnimateOptions& options);

// How the face of `options` is drawn as SVG and Lottie: --look, --stroke-width, --no-clothes,
// --decimals.
talkface::SvgOptions svg_options(const AnimateOptions& options);

// A speech aligned and the face animated on it.
struct TalkingFace {
    talkface::FaceModel face;
    talkface::Timeline timeline;
    talkface::Animation animation;
};

// Aligns `audio_path` with `transcript` and animates the face of `options` (face, fps, seed,
// style), reporting 0..1 to `progress` (may be empty; returning false cancels). A bad style or
// face file fails before the alignment, the slow part.
TalkingFace animate_talking_face(const AnimateOptions& options, const std::string& audio_path,
                                 const talkface::Timeline& transcript, const talkface::ProgressCallback& progress);

// Aligns `audio_path` with `transcript`, animates the face and writes options.output_path: a page
// (.html), or the bare animation (.svg). A linked page links `linked_audio_url`.
void make_talking_face(const AnimateOptions& options, const std::string& audio_path,
                       const talkface::Timeline& transcript, const std::string& linked_audio_url);

}  // namespace talkface_cli

#endif

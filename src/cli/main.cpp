// `talkface`: assembles the subcommands; each lives in its own file (see commands.hpp).
#include <csignal>
#include <cstdlib>
#include <exception>
#include <iostream>

#include <CLI/CLI.hpp>
#include <talkface/library.hpp>

#include "commands.hpp"
#include "error_report.hpp"

namespace {

// Outputs are written to a temporary file and renamed, so stopping at once never leaves a partial
// output behind; exit with the conventional 128 + SIGINT.
extern "C" void exit_on_interrupt(int) { std::_Exit(talkface_cli::kExitInterrupted); }

}  // namespace

int main(int argc, char** argv) {
    std::signal(SIGINT, exit_on_interrupt);

    CLI::App app{"talkface: talking cartoon faces from a face model, a speech and its transcript",
                 "talkface"};
    app.set_version_flag("--version", talkface::version());
    app.footer(talkface_cli::exit_code_help());
    app.require_subcommand(1);
    // Usage errors read as every other error (STYLE.md section 8): "talkface: error: " first, then
    // CLI11's message (a missing file: "AUDIO: File does not exist: x.wav") and its pointer to --help.
    app.failure_message([](const CLI::App* failed, const CLI::Error& error) {
        return "talkface: error: " + CLI::FailureMessage::simple(failed, error);
    });

    talkface_cli::setup_render_command(app);
    talkface_cli::setup_syllables_command(app);
    talkface_cli::setup_keyframes_command(app);
    talkface_cli::setup_export_command(app);
    talkface_cli::setup_align_command(app);
#ifdef TALKFACE_WITH_PHOTO
    talkface_cli::setup_face_from_photo_command(app);
#endif
    talkface_cli::setup_animate_command(app);
    talkface_cli::setup_video_command(app);
    talkface_cli::setup_demo_command(app);

    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& error) {
        // CLI11's own codes start at 100; talkface documents 2 for every usage error.
        const int cli11_code = app.exit(error);
        return cli11_code == static_cast<int>(CLI::ExitCodes::Success) ? talkface_cli::kExitSuccess
                                                                       : talkface_cli::kExitUsage;
    } catch (const std::exception& error) {
        return talkface_cli::report_error(error);
    } catch (...) {
        std::cerr << "talkface: error: internal error (a bug in talkface): unknown exception\n";
        return talkface_cli::kExitInternal;
    }
    return talkface_cli::kExitSuccess;
}

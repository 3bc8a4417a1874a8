// The subcommands of `talkface`. Each adds itself to the app and runs its work from its own
// callback, after the whole command line has parsed (CLI11's subcom_in_files pattern).
#ifndef TALKFACE_CLI_COMMANDS_HPP
#define TALKFACE_CLI_COMMANDS_HPP

#include <CLI/CLI.hpp>

namespace talkface_cli {

// `talkface render`: one face state drawn as an SVG file (render_command.cpp).
void setup_render_command(CLI::App& app);

// `talkface syllables`: a transcript's sentences and readings, plain or JSON (syllables_command.cpp).
void setup_syllables_command(CLI::App& app);

}  // namespace talkface_cli

#endif

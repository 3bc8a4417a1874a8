// `--timing FILE`, shared by every command that times a speech (export, keyframes, animate, video):
// a TextGrid, subtitles or a word-time JSON instead of the aligner (issue #15). Wiring it into a
// command is add_timing_option() beside its options and timed_speech() where it aligned.
#ifndef TALKFACE_CLI_TIMING_OPTION_HPP
#define TALKFACE_CLI_TIMING_OPTION_HPP

#include <string>

#include <CLI/CLI.hpp>
#include <talkface/talkface.hpp>

namespace talkface_cli {

// Adds --timing FILE (an existing file) to `command`, bound to `timing_path`.
void add_timing_option(CLI::App& command, std::string& timing_path);

// The transcript spoken in `audio_path`: timed by the --timing file when `timing_path` is not
// empty (talkface::time_transcript), else aligned (SpeechAligner::align_file).
talkface::Timeline timed_speech(const std::string& audio_path, const talkface::Timeline& transcript,
                                const std::string& timing_path, const talkface::ProgressCallback& progress = {});

}  // namespace talkface_cli

#endif

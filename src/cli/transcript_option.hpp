// The TRANSCRIPT argument of every command that reads one, with how to read it: `--transcript-encoding NAME`
// for a file in a legacy encoding (GB18030, Big5), `--keep-directions` to say a script's stage
// directions and speaker labels and `--no-pinyin-input` to read Latin letters never as pinyin
// (talkface::TranscriptOptions, every field, so each command reads a transcript the same way).
#ifndef TALKFACE_CLI_TRANSCRIPT_OPTION_HPP
#define TALKFACE_CLI_TRANSCRIPT_OPTION_HPP

#include <string>

#include <CLI/CLI.hpp>
#include <talkface/talkface.hpp>

namespace talkface_cli {

struct TranscriptArgument {
    std::string path;
    talkface::TranscriptOptions options;
};

// Adds the positional TRANSCRIPT (an existing file; `help` says what it is), --transcript-encoding,
// --keep-directions and --no-pinyin-input to `command`, bound to `transcript`; returns the positional.
CLI::Option* add_transcript_argument(CLI::App& command, TranscriptArgument& transcript,
                                     const std::string& help);

}  // namespace talkface_cli

#endif

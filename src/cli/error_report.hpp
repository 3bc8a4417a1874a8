// How the command reports a failure (the message chain on stderr and the exit code) and what a
// timeline warns of.
#ifndef TALKFACE_CLI_ERROR_REPORT_HPP
#define TALKFACE_CLI_ERROR_REPORT_HPP

#include <exception>

#include <talkface/timeline.hpp>

namespace talkface_cli {

// Exit codes, listed in the --help footer; scripts rely on them.
enum ExitCode : int {
    kExitSuccess = 0,
    kExitFailed = 1,       // the work failed: a file, a parse, an argument value
    kExitUsage = 2,        // the command line is wrong
    kExitInternal = 3,     // a bug in talkface
    kExitInterrupted = 130,
};

// The text of the --help footer.
const char* exit_code_help();

// Prints "talkface: error: <message>" for `error` and one indented line per nested layer, and
// returns the exit code for it.
int report_error(const std::exception& error);

// Prints "talkface: warning: <warning>" for each of the timeline's warnings: what the transcript
// reader skipped, what a check found with --check warn, each stretch --lenient found.
void report_warnings(const talkface::Timeline& timeline);

}  // namespace talkface_cli

#endif

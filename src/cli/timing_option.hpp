// `--timing FILE`, shared by every command that times a speech (export, keyframes, animate, video):
// a TextGrid, subtitles or a word-time JSON instead of the aligner (issue #15); and `--lenient`,
// what the aligner does with a transcript a word or two off (issue #13). Wiring them into a
// command is add_timing_option() beside its options and timed_speech() where it aligned.
#ifndef TALKFACE_CLI_TIMING_OPTION_HPP
#define TALKFACE_CLI_TIMING_OPTION_HPP

#include <string>

#include <CLI/CLI.hpp>
#include <talkface/talkface.hpp>

#include "transcript_option.hpp"

namespace talkface_cli {

// How a command times its speech.
struct SpeechTiming {
    std::string timing_path;  // --timing: time the speech by this file instead of aligning
    bool lenient = false;     // --lenient: report a stretch that does not say its text, not refuse
};

// Adds --timing FILE (an existing file) and --lenient to `command`, bound to `timing`.
void add_timing_option(CLI::App& command, SpeechTiming& timing);

// Adds --lenient alone (the align command has no --timing).
void add_lenient_option(CLI::App& command, bool& lenient);

// The transcript of a command that times it (talkface::load_transcript). Throws
// talkface::InvalidArgument naming its path for a transcript with no syllable to time (an empty file,
// only punctuation or symbols), with the first thing the reader skipped, before any audio is read.
talkface::Timeline load_transcript_to_time(const TranscriptArgument& transcript_file);

// The transcript spoken in `audio_path`: timed by the --timing file when there is one
// (talkface::time_transcript: subtitle cues pin the aligner, lenient with --lenient), else aligned
// (SpeechAligner::align_file, lenient with --lenient). Throws CLI::ValidationError (exit 2) for
// --lenient with a --timing file that times every syllable, where nothing is aligned.
talkface::Timeline timed_speech(const std::string& audio_path, const talkface::Timeline& transcript,
                                const SpeechTiming& timing, const talkface::ProgressCallback& progress = {});

}  // namespace talkface_cli

#endif

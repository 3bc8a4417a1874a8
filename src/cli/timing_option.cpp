#include "timing_option.hpp"

#include <iostream>

namespace talkface_cli {

void add_lenient_option(CLI::App& command, bool& lenient) {
    command.add_flag("--lenient", lenient,
                     "A transcript a word or two off is aligned, not refused: each stretch of speech that does not "
                     "say its text is reported (time span, expected text; \"mismatches\" in the timeline JSON) "
                     "and the mouth follows its loudness there");
}

void add_timing_option(CLI::App& command, SpeechTiming& timing) {
    add_lenient_option(command, timing.lenient);
    command
        .add_option("--timing", timing.timing_path,
                    "Time the speech by this file instead of aligning it: a Praat TextGrid (a \"syllables\" or "
                    "\"words\" tier, as Montreal Forced Aligner writes), SRT or WebVTT subtitles (each "
                    "sentence is aligned inside its cue), or JSON (a list of {\"text\",\"start\",\"end\"}, or the timeline JSON); "
                    "docs/timing-formats.md")
        ->check(CLI::ExistingFile);
}

talkface::Timeline timed_speech(const std::string& audio_path, const talkface::Timeline& transcript,
                                const SpeechTiming& timing, const talkface::ProgressCallback& progress) {
    if (!timing.timing_path.empty()) return talkface::time_transcript(timing.timing_path, audio_path, transcript, "", progress);
    talkface::AlignOptions options;
    options.lenient = timing.lenient;
    return talkface::SpeechAligner(options).align_file(audio_path, transcript, progress);
}

void print_mismatches(const std::string& audio_path, const talkface::Timeline& timeline) {
    for (const auto& mismatch : timeline.mismatches) {
        std::cerr << "talkface: warning: " << audio_path << ": " << mismatch.start_s << "-" << mismatch.end_s << " s: "
                  << (mismatch.syllable_count > 0 ? "the speech does not say \"" + mismatch.expected_text + "\""
                                                  : std::string("speech the transcript lacks"))
                  << " (--lenient: the mouth follows its loudness there)\n";
    }
}

}  // namespace talkface_cli

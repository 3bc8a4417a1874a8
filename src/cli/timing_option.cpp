#include "timing_option.hpp"

namespace talkface_cli {

void add_timing_option(CLI::App& command, std::string& timing_path) {
    command
        .add_option("--timing", timing_path,
                    "Time the speech by this file instead of aligning it: a Praat TextGrid (a \"syllables\" or "
                    "\"words\" tier, as Montreal Forced Aligner writes), SRT or WebVTT subtitles (the aligner's "
                    "syllables are kept inside each cue), or JSON (a list of {\"text\",\"start\",\"end\"}, or the timeline JSON); "
                    "docs/timing-formats.md")
        ->check(CLI::ExistingFile);
}

talkface::Timeline timed_speech(const std::string& audio_path, const talkface::Timeline& transcript,
                                const std::string& timing_path, const talkface::ProgressCallback& progress) {
    if (timing_path.empty()) return talkface::SpeechAligner().align_file(audio_path, transcript, progress);
    return talkface::time_transcript(timing_path, audio_path, transcript, "", progress);
}

}  // namespace talkface_cli

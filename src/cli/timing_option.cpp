#include "timing_option.hpp"

#include "text/unread_transcript.hpp"

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

talkface::Timeline load_transcript_to_time(const TranscriptArgument& transcript_file) {
    const std::string& path = transcript_file.path;
    talkface::Timeline transcript = talkface::load_transcript(path, transcript_file.options);
    if (!transcript.syllables.empty()) return transcript;
    if (transcript.sentences.empty() && transcript.warnings.empty())
        throw talkface::InvalidArgument(path, "no text to align: the transcript holds no sentence");
    throw talkface::InvalidArgument(path, "no syllables to align: " + talkface::detail::describe_unread_transcript(transcript));
}

talkface::Timeline timed_speech(const std::string& audio_path, const talkface::Timeline& transcript,
                                const SpeechTiming& timing, const talkface::ProgressCallback& progress) {
    talkface::AlignOptions options;
    options.lenient = timing.lenient;
    if (timing.timing_path.empty()) return talkface::SpeechAligner(options).align_file(audio_path, transcript, progress);
    try {
        return talkface::time_transcript(timing.timing_path, audio_path, transcript, options, "", progress);
    } catch (const talkface::InvalidArgument& error) {
        // --lenient with a file that times every syllable is a command line that cannot work.
        const std::string prefix = error.parameter() + ": ";  // what() names the parameter first
        if (error.parameter() == "lenient") throw CLI::ValidationError("--lenient", std::string(error.what()).substr(prefix.size()));
        throw;
    }
}

}  // namespace talkface_cli

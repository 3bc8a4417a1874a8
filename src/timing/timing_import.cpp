// A transcript timed by a timing file and its recording (timing_formats.hpp's time_transcript):
// word and syllable timings are read as they are; subtitle cues bound the aligner: the whole
// recording is aligned, and each cue's syllables are kept inside the cue.
//
// Why not align each cue's stretch of audio alone: the aligner's checks of a wrong text need the
// rest of the recording (its one-sentence checks refuse right sentences cut from a longer file, as
// tests/data/speech/two_sentences' second sentence), so a cue alone is not enough to align.
#include <algorithm>
#include <memory>
#include <string>
#include <vector>

#include "audio/audio_source.hpp"
#include "common/atomic_file.hpp"
#include "talkface/errors.hpp"
#include "talkface/speech_aligner.hpp"
#include "talkface/timing_formats.hpp"
#include "timing/import_readers.hpp"
#include "timing/timed_units.hpp"

namespace talkface {
inline namespace v0 {

namespace {

// Where the aligner may overshoot a cue without being moved: subtitle times are milliseconds.
constexpr double kCueToleranceS = 0.0015;

// Maps the syllables [first, last) of `timeline` from the span the aligner gave them into the
// cue: unchanged where they lie inside it, else moved in proportion into the part of the cue they
// overlap (or the whole cue, where they missed it).
void keep_inside(Timeline& timeline, std::size_t first, std::size_t last, const detail::TimedUnit& cue) {
    const double from_s = timeline.syllables[first].start_s;
    const double to_s = timeline.syllables[last - 1].end_s;
    if (from_s >= cue.start_s - kCueToleranceS && to_s <= cue.end_s + kCueToleranceS) return;
    double new_from_s = std::max(from_s, cue.start_s);
    double new_to_s = std::min(to_s, cue.end_s);
    if (!(new_to_s > new_from_s)) {
        new_from_s = cue.start_s;
        new_to_s = cue.end_s;
    }
    const double scale = to_s > from_s ? (new_to_s - new_from_s) / (to_s - from_s) : 0.0;
    const auto moved = [&](double t) { return new_from_s + (t - from_s) * scale; };
    for (std::size_t k = first; k < last; ++k) {
        Syllable& syllable = timeline.syllables[k];
        syllable.start_s = moved(syllable.start_s);
        syllable.end_s = moved(syllable.end_s);
        if (syllable.final_start_s) syllable.final_start_s = moved(*syllable.final_start_s);
    }
}

}  // namespace

Timeline time_transcript(const std::string& timing_path, const std::string& audio_path, const Timeline& transcript,
                         const std::string& format, const ProgressCallback& progress) {
    const std::unique_ptr<detail::AudioSource> audio = detail::open_audio_file(audio_path);
    const double rate_hz = audio->sample_rate_hz();
    const double duration_s = static_cast<double>(audio->frame_count()) / rate_hz;
    const std::string chosen = format.empty() ? timing_format_for_path(timing_path) : format;
    if (chosen != "srt" && chosen != "vtt") return read_timing_file(timing_path, transcript, duration_s, chosen);

    const std::string text = detail::read_file(timing_path);
    const std::vector<detail::TimedUnit> cues = chosen == "srt" ? detail::read_subrip_units(text, timing_path)
                                                                : detail::read_webvtt_units(text, timing_path);
    detail::check_unit_times(cues, duration_s, timing_path);
    const auto ranges = detail::unit_syllable_ranges(transcript, cues, timing_path);
    Timeline timeline = SpeechAligner().align_file(audio_path, transcript, progress);
    for (std::size_t c = 0; c < cues.size(); ++c) {
        if (ranges[c].first < ranges[c].second) keep_inside(timeline, ranges[c].first, ranges[c].second, cues[c]);
    }
    detail::span_sentences(timeline);
    timeline.duration_s = duration_s;
    return timeline;
}

double audio_duration_s(const std::string& audio_path) {
    const std::unique_ptr<detail::AudioSource> audio = detail::open_audio_file(audio_path);
    return static_cast<double>(audio->frame_count()) / audio->sample_rate_hz();
}

}  // namespace v0
}  // namespace talkface

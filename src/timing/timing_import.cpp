// A transcript timed by a timing file and its recording (timing_formats.hpp's time_transcript):
// word and syllable timings are read as they are; subtitle cues pin the aligner: each sentence is
// searched only inside its cues (speech/given_spans_alignment.hpp), in place of the pauses the
// aligner would choose.
//
// Why not align each cue's stretch of audio alone: the aligner's checks of a wrong text need the
// rest of the recording (its one-sentence checks refuse right sentences cut from a longer file, as
// tests/data/speech/two_sentences' second sentence), so a cue alone is not enough to align; the
// pinned alignment re-estimates and checks over every cue at once.
#include <algorithm>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "audio/audio_source.hpp"
#include "common/atomic_file.hpp"
#include "speech/given_spans_alignment.hpp"
#include "talkface/errors.hpp"
#include "talkface/timing_formats.hpp"
#include "timing/import_readers.hpp"
#include "timing/timed_units.hpp"

namespace talkface {
inline namespace v0 {

namespace {

// Where the aligner may overshoot a cue without being moved: subtitle times are milliseconds.
constexpr double kCueToleranceS = 0.0015;

// Each sentence's span: from the start of the first cue holding one of its syllables to the end of
// the last (a sentence split over cues is searched over all of them; sentences sharing a cue, or
// a cue across a sentence end, are aligned together). Sentences without syllables: 0..0, unread.
std::vector<detail::GivenSpan> sentence_spans(const Timeline& transcript, const std::vector<detail::TimedUnit>& cues,
                                              const std::vector<std::pair<std::size_t, std::size_t>>& ranges) {
    std::vector<detail::GivenSpan> spans(transcript.sentences.size());
    std::vector<bool> is_set(spans.size(), false);
    for (std::size_t c = 0; c < cues.size(); ++c) {
        for (std::size_t i = ranges[c].first; i < ranges[c].second; ++i) {
            const std::size_t k = transcript.syllables[i].sentence;
            spans[k] = is_set[k] ? detail::GivenSpan{std::min(spans[k].start_s, cues[c].start_s), std::max(spans[k].end_s, cues[c].end_s)}
                                 : detail::GivenSpan{cues[c].start_s, cues[c].end_s};
            is_set[k] = true;
        }
    }
    return spans;
}

// Where a cue splits a sentence, or two sentences share a chain, the aligner keeps the syllables
// only inside the sentences' spans: maps the syllables [first, last) of `timeline` from the span
// the aligner gave them into the cue: unchanged where they lie inside it, else moved in
// proportion into the part of the cue they overlap (or the whole cue, where they missed it).
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

// Why lenient alignment cannot be had with a timing file of `format_name` that times every syllable.
[[noreturn]] void refuse_lenient(const std::string& timing_path, const std::string& format_name) {
    throw InvalidArgument("lenient", timing_path + " (" + format_name +
                                         ") times every syllable itself: nothing is aligned, so nothing is found "
                                         "not to say its text; lenient alignment needs subtitle cues that time "
                                         "sentences (srt, vtt), or no timing file");
}

}  // namespace

Timeline time_transcript(const std::string& timing_path, const std::string& audio_path, const Timeline& transcript,
                         const std::string& format, const ProgressCallback& progress) {
    return time_transcript(timing_path, audio_path, transcript, AlignOptions(), format, progress);
}

Timeline time_transcript(const std::string& timing_path, const std::string& audio_path, const Timeline& transcript,
                         const AlignOptions& options, const std::string& format, const ProgressCallback& progress) {
    const SpeechAligner checked(options);  // options out of range are refused before any reading
    const std::unique_ptr<detail::AudioSource> audio = detail::open_audio_file(audio_path);
    const double duration_s = static_cast<double>(audio->frame_count()) / audio->sample_rate_hz();
    const std::string chosen = format.empty() ? timing_format_for_path(timing_path) : format;
    if (chosen != "srt" && chosen != "vtt") {
        if (options.lenient) refuse_lenient(timing_path, chosen);
        return read_timing_file(timing_path, transcript, duration_s, chosen);
    }

    const std::string text = detail::read_timing_text(timing_path);
    const std::vector<detail::TimedUnit> cues = chosen == "srt" ? detail::read_subrip_units(text, timing_path)
                                                                : detail::read_webvtt_units(text, timing_path);
    detail::check_unit_times(cues, duration_s, timing_path);
    const auto ranges = detail::unit_syllable_ranges(transcript, cues, timing_path);
    // Cues that time every syllable (WebVTT cue timestamps, one before each syllable after the
    // first, as talkface's vtt export writes) are a syllable timing: read as they are.
    const bool times_syllables = std::all_of(cues.begin(), cues.end(), [&](const detail::TimedUnit& cue) {
        const auto& range = ranges[static_cast<std::size_t>(&cue - cues.data())];
        return cue.inner_starts_s.size() + 1 == range.second - range.first;
    });
    if (times_syllables) {
        if (options.lenient) refuse_lenient(timing_path, "vtt with a timestamp per syllable");
        return detail::time_matched_units(transcript, cues, ranges, duration_s, detail::UnitKind::cues);
    }
    Timeline timeline = detail::align_in_given_spans(
        audio_path, transcript, sentence_spans(transcript, cues, ranges), checked.options(), progress);
    for (std::size_t c = 0; c < cues.size(); ++c) {
        if (ranges[c].first < ranges[c].second) keep_inside(timeline, ranges[c].first, ranges[c].second, cues[c]);
    }
    detail::span_sentences(timeline);
    return timeline;
}

double audio_duration_s(const std::string& audio_path) {
    const std::unique_ptr<detail::AudioSource> audio = detail::open_audio_file(audio_path);
    return static_cast<double>(audio->frame_count()) / audio->sample_rate_hz();
}

}  // namespace v0
}  // namespace talkface

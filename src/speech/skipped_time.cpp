#include "speech/skipped_time.hpp"

#include <algorithm>

#include "common/number_format.hpp"
#include "speech/frame_features.hpp"

namespace talkface::detail {

namespace {

// Calls `change` on each time `timeline` holds: its sentences', syllables' (their finals' too) and
// mismatches' edges, and its duration.
template <typename Change>
void change_times(Timeline& timeline, const Change& change) {
    for (Sentence& sentence : timeline.sentences) {
        change(sentence.start_s);
        change(sentence.end_s);
    }
    for (Syllable& syllable : timeline.syllables) {
        change(syllable.start_s);
        change(syllable.end_s);
        if (syllable.final_start_s) change(*syllable.final_start_s);
    }
    for (TextMismatch& mismatch : timeline.mismatches) {
        change(mismatch.start_s);
        change(mismatch.end_s);
    }
    change(timeline.duration_s);
}

}  // namespace

std::vector<GivenSpan> spans_after_skip(std::vector<GivenSpan> spans, double skipped_s) {
    for (GivenSpan& span : spans) {
        span.start_s = std::max(0.0, span.start_s - skipped_s);
        span.end_s = std::max(span.start_s, span.end_s - skipped_s);
    }
    return spans;
}

AlignOptions options_after_skip(AlignOptions options, double skipped_s) {
    if (options.sentence_cut == SentenceCutMode::first_pause) {
        options.first_pause_start_s = std::max(0.0, options.first_pause_start_s - skipped_s);
        options.first_pause_end_s =
            std::max(options.first_pause_start_s + kFrameStepS, options.first_pause_end_s - skipped_s);
    }
    return options;
}

void move_onto_recording(Timeline& timeline, double skipped_s) {
    change_times(timeline, [skipped_s](double& time_s) { time_s += skipped_s; });
}

void round_to_microseconds(Timeline& timeline) {
    change_times(timeline, [](double& time_s) { time_s = rounded(time_s, 6); });
}

}  // namespace talkface::detail

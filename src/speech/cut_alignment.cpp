#include "speech/cut_alignment.hpp"

#include <algorithm>
#include <cstddef>
#include <utility>

#include "speech/alignment_checks.hpp"
#include "speech/chain_alignment.hpp"
#include "speech/placed_missing_text.hpp"
#include "speech/room_placement.hpp"
#include "speech/run_together.hpp"
#include "speech/tone_witness.hpp"
#include "talkface/errors.hpp"

namespace talkface::detail {

namespace {

// Each sentence runs from its first syllable's start to its last one's end; one without
// syllables is an instant where the cut put it.
void set_sentence_times(const std::vector<FrameSpan>& spans, Timeline& result) {
    for (std::size_t k = 0; k < result.sentences.size(); ++k) {
        const auto first = std::find_if(result.syllables.begin(), result.syllables.end(),
                                        [&](const Syllable& s) { return s.sentence == k; });
        if (first == result.syllables.end()) {
            const double at = frame_time_s(spans[k].first_frame);
            result.sentences[k].start_s = result.sentences[k].end_s = at;
            continue;
        }
        const auto last = std::find_if(result.syllables.rbegin(), result.syllables.rend(),
                                       [&](const Syllable& s) { return s.sentence == k; });
        result.sentences[k].start_s = first->start_s;
        result.sentences[k].end_s = last->end_s;
    }
}

// The sum of the sentences' text fit gaps (text_fit_gap): the lower, the better the syllables fit
// the audio, each alignment judged on the models it re-estimated.
double total_fit_gap(const CutAlignment& aligned) {
    double sum = 0.0;
    for (const auto& metrics : aligned.metrics) sum += metrics.fit_gap;
    return sum;
}

// The sentences whose text fits their speech so much worse than free sounds do that check_text_fit
// would refuse them (kMaxTextFitGap); empty if none.
std::vector<std::size_t> poorly_fitting(const std::vector<SentenceMetrics>& metrics) {
    std::vector<std::size_t> poor;
    for (std::size_t k = 0; k < metrics.size(); ++k)
        if (metrics[k].fit_gap > kMaxTextFitGap) poor.push_back(k);
    return poor;
}

}  // namespace

AlignedTimelines align_cut(const FeatureTrack& track, const FeatureTrack& heard,
                           const LoudnessProfile& loudness, const Timeline& transcript,
                           const SentenceCut& cut, ProgressReporter& progress, bool is_checked,
                           bool is_lenient) {
    const bool has_blocks = std::find(cut.runs_on.begin(), cut.runs_on.end(), true) != cut.runs_on.end();
    if (!has_blocks && is_checked) check_sentence_lengths(cut.spans, heard, loudness, transcript);
    CutAlignment aligned =
        align_chains(track, loudness, transcript, cut, progress, is_checked, is_lenient, false, false);
    bool is_kept_to_marks = false;
    std::optional<CutAlignment> unkept;
    if (aligned.has_long_unmarked_pause) {
        try {
            CutAlignment kept =
                align_chains(track, loudness, transcript, cut, progress, is_checked, is_lenient, true, false);
            if (total_fit_gap(kept) < total_fit_gap(aligned)) {
                unkept = std::move(aligned);
                aligned = std::move(kept);
                is_kept_to_marks = true;
            }
        } catch (const AlignmentError&) {
            // No path keeps every pause the text does not mark short, or one a check refuses: the
            // first alignment stands.
        }
    }
    if (const auto poor = poorly_fitting(aligned.metrics); !poor.empty()) {
        try {
            CutAlignment released = align_chains(track, loudness, transcript, cut, progress, is_checked,
                                                 is_lenient, is_kept_to_marks, true);
            if (fits_as_well_as_free_sounds(released.metrics, poor)) aligned = std::move(released);
        } catch (const AlignmentError&) {
            // A check refuses the new paths: the alignment before stands, for the checks to judge.
        }
    }
    const std::vector<FrameSpan>& spans = aligned.spans;
    const std::vector<SentenceMetrics>& metrics = aligned.metrics;
    Timeline& result = aligned.result;
    if (is_checked) {
        if (has_blocks) check_sentence_lengths(spans, heard, loudness, transcript);
        try {
            check_text_fit(metrics, spans, transcript);
        } catch (const AlignmentError&) {
            const std::vector<bool> is_spoken = spoken_sentences_of(transcript);
            if (aligned.room_result && track.pitch.empty() &&
                static_cast<std::size_t>(std::count(is_spoken.begin(), is_spoken.end(), true)) >=
                    kMinToneWitnessSentences)
                throw ToneWitnessWanted();
            throw;
        }
        check_held_out_fit(metrics, spans, transcript, result.warnings);
        if (!cut.syllable_bounds.empty()) check_typical_syllable_off_noise(metrics, spans, transcript);
        check_unspoken_tail(metrics, spans, transcript);
        check_own_fit(metrics, spans, transcript);
        check_syllable_lengths(metrics, spans, transcript);
        check_fit(metrics, spans, transcript);
        check_missing_text_as_placed(aligned, unkept ? &*unkept : nullptr, heard, loudness, result.warnings);
    }
    for (const VoicedEnd& voiced : aligned.voiced_ends)
        result.syllables[voiced.syllable].end_s = voiced.end_s;
    set_sentence_times(spans, result);
    AlignedTimelines timelines{std::move(result), std::nullopt, is_checked && is_vouched_by_order(metrics)};
    if (aligned.room_result) {
        Timeline in_room = with_room_placement(timelines.checked, *aligned.room_result);
        set_sentence_times(spans, in_room);
        timelines.in_room = std::move(in_room);
    }
    return timelines;
}

AlignedTimelines align_confirmed(const FeatureTrack& track, const FeatureTrack& heard,
                                 const LoudnessProfile& loudness, const Timeline& transcript,
                                 const SentenceCut& cut, const std::vector<bool>& is_spoken,
                                 ProgressReporter& progress, bool is_checked, bool is_lenient) {
    AlignedTimelines aligned =
        align_cut(track, heard, loudness, transcript, cut, progress, is_checked, is_lenient);
    SentenceCut confirmed = cut;
    for (const auto& [k, next] : spoken_neighbours(is_spoken)) {
        // Too few pauses: the cutter chose none for this end, and the chain is all there is.
        const bool has_cut_pause = cut.spans[k].end_frame <= cut.spans[next].first_frame;
        if (cut.runs_on[k] && has_cut_pause &&
            !(moves_sentence_end(cut, aligned.checked, k, next) &&
              is_cut_pause_in_text(cut, aligned.checked, k, next)))
            confirmed.runs_on[k] = false;
    }
    if (confirmed.runs_on == cut.runs_on) return aligned;
    return align_cut(track, heard, loudness, transcript, confirmed, progress, is_checked, is_lenient);
}

}  // namespace talkface::detail

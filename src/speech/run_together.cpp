#include "speech/run_together.hpp"

#include <algorithm>
#include <limits>
#include <utility>

#include "common/order_statistics.hpp"

namespace talkface::detail {

namespace {

// Neighbouring sentences of one speaker differ in rate by up to ~1.4 (bench/ draws 170-230
// syllables a minute per sentence; read speech varies about as much). A sentence end cut at a
// comma of the next sentence moves a clause from one to the other: the rates then part by 2-3.
constexpr double kMaxNeighbourRateRatio = 1.6;
// Against the recording's typical sentence (the median), a sentence varies less than against a
// single neighbour: beyond this its cut is in doubt.
constexpr double kMaxTypicalRateRatio = 1.5;

// A sentence end that the syllables of a chain put this far outside the pause the cutter chose
// for it shows that the cut was wrong: the benchmark's tolerance for a sentence boundary.
constexpr std::size_t kMovedEndFrames = 15;

// Frames of `span` inside pauses, and the longest of those pauses.
struct PausesInside {
    std::size_t frames = 0;
    std::size_t longest = 0;
};

PausesInside pauses_inside(const LoudnessProfile& loudness, const FrameSpan& span) {
    PausesInside inside;
    for (const auto& pause : loudness.pauses) {
        if (pause.first_frame < span.first_frame || pause.end_frame > span.end_frame) continue;
        inside.frames += pause.length();
        inside.longest = std::max(inside.longest, pause.length());
    }
    return inside;
}

struct SentenceMeasures {
    std::vector<double> frames_per_syllable;  // on the cut: speech frames, pauses inside left out
    std::vector<std::size_t> longest_inside;  // the longest pause inside each sentence
};

SentenceMeasures measure_sentences(const std::vector<FrameSpan>& spans, const std::vector<std::size_t>& syllables,
                                   const LoudnessProfile& loudness) {
    SentenceMeasures measures;
    for (std::size_t k = 0; k < spans.size(); ++k) {
        const PausesInside inside = pauses_inside(loudness, spans[k]);
        const std::size_t speech = spans[k].length() > inside.frames ? spans[k].length() - inside.frames : 0;
        measures.frames_per_syllable.push_back(static_cast<double>(std::max<std::size_t>(speech, 1)) /
                                               static_cast<double>(std::max<std::size_t>(syllables[k], 1)));
        measures.longest_inside.push_back(inside.longest);
    }
    return measures;
}

std::size_t cut_pause(const std::vector<FrameSpan>& spans, std::size_t k) {
    return spans[k + 1].first_frame > spans[k].end_frame ? spans[k + 1].first_frame - spans[k].end_frame : 0;
}

bool is_outside_ratio(double ratio, double limit) { return ratio > limit || ratio < 1.0 / limit; }

// The frames [first, end) of the pause `cut` put between spoken sentence `k` and the next (empty
// where their spans meet).
std::pair<double, double> cut_pause_frames(const SentenceCut& cut, std::size_t k, std::size_t next) {
    return {static_cast<double>(cut.spans[k].end_frame),
            static_cast<double>(std::max(cut.spans[k].end_frame, cut.spans[next].first_frame))};
}

}  // namespace

std::vector<bool> find_run_together(const std::vector<FrameSpan>& spans, const std::vector<std::size_t>& syllables,
                                    const LoudnessProfile& loudness) {
    std::vector<bool> runs_on(spans.size(), false);
    const SentenceMeasures measures = measure_sentences(spans, syllables, loudness);
    for (std::size_t k = 0; k + 1 < spans.size(); ++k) {
        const bool pause_in_doubt = cut_pause(spans, k) <= std::max(measures.longest_inside[k], measures.longest_inside[k + 1]);
        const bool rates_disagree = is_outside_ratio(measures.frames_per_syllable[k] / measures.frames_per_syllable[k + 1],
                                                     kMaxNeighbourRateRatio);
        runs_on[k] = pause_in_doubt || rates_disagree;
    }
    return runs_on;
}

bool are_sentence_ends_in_doubt(const std::vector<FrameSpan>& spans, const std::vector<std::size_t>& syllables,
                                const LoudnessProfile& loudness) {
    if (spans.size() < 2) return false;
    const SentenceMeasures measures = measure_sentences(spans, syllables, loudness);
    std::size_t shortest_cut = std::numeric_limits<std::size_t>::max();
    for (std::size_t k = 0; k + 1 < spans.size(); ++k) shortest_cut = std::min(shortest_cut, cut_pause(spans, k));
    if (shortest_cut <= *std::max_element(measures.longest_inside.begin(), measures.longest_inside.end())) return true;
    const double typical = upper_median(measures.frames_per_syllable);
    return std::any_of(measures.frames_per_syllable.begin(), measures.frames_per_syllable.end(),
                       [&](double rate) { return is_outside_ratio(rate / typical, kMaxTypicalRateRatio); });
}

std::vector<bool> spoken_sentences_of(const Timeline& transcript) {
    std::vector<bool> is_spoken(transcript.sentences.size(), false);
    for (const auto& syllable : transcript.syllables) is_spoken[syllable.sentence] = true;
    return is_spoken;
}

std::size_t block_count(const SentenceCut& cut, const Timeline& transcript) {
    const std::vector<bool> is_spoken = spoken_sentences_of(transcript);
    std::size_t blocks = 0;
    bool continues_block = false;
    for (std::size_t k = 0; k < cut.runs_on.size(); ++k) {
        if (!is_spoken[k]) continue;
        if (!continues_block) ++blocks;
        continues_block = cut.runs_on[k];
    }
    return blocks;
}

bool moves_sentence_end(const SentenceCut& cut, const Timeline& aligned, std::size_t k, std::size_t next) {
    const std::size_t pause_first = cut.spans[k].end_frame;
    const std::size_t pause_end = std::max(pause_first, cut.spans[next].first_frame);
    auto is_outside = [&](double time_s) {
        const double frame = time_s / kFrameStepS;
        return frame + static_cast<double>(kMovedEndFrames) < static_cast<double>(pause_first) ||
               frame > static_cast<double>(pause_end + kMovedEndFrames);
    };
    return is_outside(aligned.sentences[k].end_s) || is_outside(aligned.sentences[next].start_s);
}

bool is_cut_pause_in_text(const SentenceCut& cut, const Timeline& aligned, std::size_t k, std::size_t next) {
    const auto [pause_first, pause_end] = cut_pause_frames(cut, k, next);
    const double tolerance = static_cast<double>(kMovedEndFrames);
    const auto& syllables = aligned.syllables;
    for (std::size_t i = 0; i + 1 < syllables.size(); ++i) {
        if (!syllables[i].pause_after && syllables[i].sentence == syllables[i + 1].sentence) continue;
        if (syllables[i].end_s / kFrameStepS <= pause_first + tolerance &&
            syllables[i + 1].start_s / kFrameStepS >= pause_end - tolerance)
            return true;
    }
    return false;
}

bool is_cut_pause_passed_over(const SentenceCut& cut, const Timeline& aligned, std::size_t k,
                              std::size_t next) {
    const auto [pause_first, pause_end] = cut_pause_frames(cut, k, next);
    const auto& syllables = aligned.syllables;
    for (std::size_t i = 0; i + 1 < syllables.size(); ++i) {
        const double gap_first = std::max(pause_first, syllables[i].end_s / kFrameStepS);
        const double gap_end = std::min(pause_end, syllables[i + 1].start_s / kFrameStepS);
        if (gap_first < gap_end) return false;
    }
    const double own_pause = (aligned.sentences[next].start_s - aligned.sentences[k].end_s) / kFrameStepS;
    return own_pause > pause_end - pause_first;
}

std::vector<std::pair<std::size_t, std::size_t>> spoken_neighbours(const std::vector<bool>& is_spoken) {
    std::vector<std::pair<std::size_t, std::size_t>> pairs;
    std::size_t previous = is_spoken.size();
    for (std::size_t k = 0; k < is_spoken.size(); ++k) {
        if (!is_spoken[k]) continue;
        if (previous < is_spoken.size()) pairs.emplace_back(previous, k);
        previous = k;
    }
    return pairs;
}

}  // namespace talkface::detail

#include "speech/chain_measures.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "common/order_statistics.hpp"
#include "speech/lead_noise.hpp"
#include "speech/syllable_placement.hpp"
#include "speech/text_fit.hpp"

namespace talkface::detail {

double forgiven_closure_run_on(const Reestimation& learned, std::size_t spoken_sentences, bool in_room) {
    if (spoken_sentences <= kMaxHeldOutCheckSentences) return 0.0;
    if (in_room || learned.closure_run_on <= 0.0) return learned.closure_run_on;
    return std::numeric_limits<double>::infinity();
}

bool is_judged_by_order_margin(const SentenceChain& chain, std::size_t spoken_sentences,
                               bool is_on_bed_free_models) {
    return is_on_bed_free_models || (!chain.ends_in_tail && spoken_sentences <= kMaxHeldOutCheckSentences);
}

namespace {

// A frame's speech stands clear of the noise where its loudest band rises this far above the band's
// floor (the level kNucleusAboveFloorDb asks of a voiced peak). Under pink noise at SNR 15-20 dB a
// person's sentence said quieter than the others (bench/ w-fast-pink15 tuning-015's second) holds
// 57-67% of its frames under it, and its right text gapped 0.15 and 0.23 per frame over all its
// frames at two of three frame phases; over the frames clear of the noise -0.06 and -0.07, where
// wrong texts gap more than over all (bench/README.md, session 45 (noisegap)).
constexpr float kClearOfNoiseDb = 10.0f;

// Per frame of the chain's scores, whether its speech stands clear of the noise.
std::vector<bool> frames_clear_of_noise(const LoudnessProfile& loudness, std::size_t first_frame,
                                        std::size_t frames) {
    std::vector<bool> clear(frames, false);
    for (std::size_t t = 0; t < frames && first_frame + t < loudness.activity_db.size(); ++t)
        clear[t] = loudness.activity_db[first_frame + t] >= kClearOfNoiseDb;
    return clear;
}

}  // namespace

void measure_chain(const ChainMeasureInputs& in, EmissionScores& scores, ViterbiWorkspace& workspace,
                   Timeline& result, std::vector<SyllableEvidence>& evidence, std::vector<FrameSpan>& spans,
                   std::vector<SentenceMetrics>& metrics) {
    const SentenceChain& chain = in.chain;
    const std::vector<StateSegment>& path = in.path;
    place_syllables(chain, in.chain_index, path, in.other_frames, scores, in.track, result, evidence);
    const std::vector<bool> is_clear =
        frames_clear_of_noise(in.loudness, chain.searched.first_frame, scores.frame_count);
    for (const auto& [k, share] : split_by_sentence(chain, path)) {
        if (chain.is_block()) spans[k] = aligned_span(result, chain, k);
        metrics[k].fit = speech_fit(chain, share, scores);
        metrics[k].fit_gap = text_fit_gap(chain, share, scores, in.forgiven_run_on);
        metrics[k].clear_fit_gap = clear_text_fit_gap(chain, share, scores, is_clear, in.forgiven_run_on);
        metrics[k].noise_covered_share = noise_covered_share(chain, share, is_clear);
    }
    // Where a sentence ends in a room's tail a right text gaps up to 0.07 and spreads its syllables'
    // lengths up to 0.79 (bench/ reverb), as much as a wrong text: there check_own_fit and
    // check_syllable_lengths would refuse right texts. check_path judges on `scores` of the whole
    // recording's models, before held_out_fit_gaps overwrites them.
    const bool is_own_model = !chain.ends_in_tail && in.spoken_sentences <= kMaxHeldOutCheckSentences;
    const bool is_judged_by_margin =
        is_judged_by_order_margin(chain, in.spoken_sentences, in.is_on_bed_free_models);
    const double margin = is_judged_by_margin ? order_margin(chain, path, scores, workspace)
                                              : std::numeric_limits<double>::quiet_NaN();
    // Alone in its file, a sentence's speech after its last syllable is judged against generic
    // speech: beside another sentence it would take that one's start.
    if (is_own_model && in.spoken_sentences == 1)
        metrics[chain.syllables.back()->sentence].unspoken_tail_frames =
            unspoken_tail_frames(chain, scores, workspace);
    const std::vector<std::size_t> syllables = syllables_per_sentence(in.transcript);
    for (const auto& [k, share] : split_by_sentence(chain, path)) {
        metrics[k].order_margin = margin;
        const auto stretches = stretches_of(chain, share);
        if (is_own_model) {
            metrics[k].own_fit_gap = metrics[k].fit_gap;
            metrics[k].length_spread = syllable_length_spread(stretches);
            // A line of a few syllables is judged on its own fit and rhythm with the noise before
            // its voice left out as well, and refused only where both readings refuse it: the
            // noise is no evidence of its text (lead_noise.hpp). A longer line's first syllable
            // weighs little in either. Its text fit (check_text_fit) is the same lesser reading: on
            // models learned from the line alone it is the own fit.
            if (syllables[k] < kMinHeldOutSyllables) {
                const OwnVoiceShare own =
                    own_voice_share(share, stretches, in.loudness, chain.searched.first_frame);
                if (own.has_noise) {
                    metrics[k].own_fit_gap = std::min(
                        metrics[k].own_fit_gap, text_fit_gap(chain, own.path, scores, in.forgiven_run_on));
                    metrics[k].fit_gap = std::min(metrics[k].fit_gap, metrics[k].own_fit_gap);
                    metrics[k].clear_fit_gap =
                        std::min(metrics[k].clear_fit_gap,
                                 clear_text_fit_gap(chain, own.path, scores, is_clear, in.forgiven_run_on));
                    metrics[k].length_spread =
                        std::min(metrics[k].length_spread, syllable_length_spread(own.stretches));
                }
            }
        }
        if (in.is_checked)
            check_path(stretches, in.loudness, scores, chain.searched.first_frame, k, spans[k],
                       in.transcript);
    }
    // In a room every sound rings into the next, and a right text's halves gap up to 0.85 (bench/
    // reverb): there the check would refuse one right sentence in six. With three sentences or
    // more, check_text_fit and check_fit compare each with the others, which holds better than this
    // absolute limit. In a chain, models re-estimated on it fit its sentences' texts as they would
    // in a file of one or two: the halves of each are checked the same way.
    if (is_judged_by_margin || (!chain.ends_in_tail && chain.is_block())) {
        const auto halves = split_in_halves(chain, path);
        const auto gaps = held_out_fit_gaps(chain, halves, in.observations, in.learned.whole,
                                            in.learned.halves[in.chain_index], scores, in.forgiven_run_on);
        for (std::size_t h = 0; h < halves.size(); ++h) {
            if (halves[h].empty()) continue;
            const std::size_t k = chain.syllables[chain.states[halves[h].front().state].syllable]->sentence;
            metrics[k].held_out_gap = std::max(metrics[k].held_out_gap, gaps.halves[h]);
            if (h % 2 == 1) metrics[k].held_out_end_gap = std::max(0.0, gaps.halves[h]);
        }
        // The typical syllable's gap, of the whole sentence and of its second half: one noisy
        // stretch (a note of music, a squeezed syllable) rules a half's gap but not its median.
        std::vector<std::vector<double>> whole_gaps(metrics.size()), end_gaps(metrics.size());
        for (std::size_t h = 0; h < halves.size(); ++h) {
            std::size_t previous = chain.syllables.size();
            for (const auto& segment : halves[h]) {
                const std::size_t i = chain.states[segment.state].syllable;
                if (i == previous || !std::isfinite(gaps.syllables[i])) continue;
                previous = i;
                const std::size_t k = chain.syllables[i]->sentence;
                whole_gaps[k].push_back(gaps.syllables[i]);
                if (h % 2 == 1) end_gaps[k].push_back(gaps.syllables[i]);
            }
        }
        for (std::size_t k = 0; k < metrics.size(); ++k) {
            if (whole_gaps[k].empty()) continue;
            metrics[k].held_out_median = mean_median(whole_gaps[k]);
            metrics[k].is_held_out_in_room = in.is_in_room;
            metrics[k].held_out_last_is_worst =
                whole_gaps[k].back() >= *std::max_element(whole_gaps[k].begin(), whole_gaps[k].end());
            if (!end_gaps[k].empty()) metrics[k].held_out_end_median = mean_median(end_gaps[k]);
        }
    }
}

}  // namespace talkface::detail

#include "speech/own_reading_bound.hpp"

#include <algorithm>
#include <cstddef>
#include <vector>

#include "speech/alignment_checks.hpp"
#include "speech/line_among_voices.hpp"
#include "talkface/errors.hpp"

namespace talkface::detail {

bool is_held_to_own_reading(const FeatureTrack& track, const LoudnessProfile& loudness, const FrameSpan& own,
                            std::size_t syllables) {
    return syllables < kMinEndClauseSyllables && static_cast<double>(count_nuclei(track, loudness, own)) <=
                                                     kMaxNucleiPerSyllable * static_cast<double>(syllables);
}

std::optional<SentenceCut> cut_bounded_by_own_reading(const FeatureTrack& track,
                                                      const LoudnessProfile& loudness,
                                                      const Timeline& transcript, const SentenceCut& cut,
                                                      const AlignOptions& options) {
    if (!is_one_spoken_line(transcript)) return std::nullopt;
    const std::vector<std::size_t> syllables = syllables_per_sentence(transcript);
    const auto k = static_cast<std::size_t>(
        std::find_if(syllables.begin(), syllables.end(), [](std::size_t count) { return count > 0; }) -
        syllables.begin());
    const auto lifted = loudness_after_lifted_lead_in(track, loudness);
    if (!lifted) return std::nullopt;
    std::optional<FrameSpan> own;
    try {
        own = cut_sentences(track, *lifted, transcript, options).spans.at(k);
    } catch (const AlignmentError&) {
        // The sentence cannot be cut after the lifted noise: no own reading to bound it by.
    }
    if (!own || !is_held_to_own_reading(track, loudness, *own, syllables[k])) return std::nullopt;
    SentenceCut bounded = cut;
    bounded.syllable_bounds.assign(cut.spans.size(), {0, track.frame_count});
    bounded.syllable_bounds[k] = *own;
    return bounded;
}

}  // namespace talkface::detail

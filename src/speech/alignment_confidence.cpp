#include "speech/alignment_confidence.hpp"

#include <algorithm>
#include <cmath>

#include "speech/text_fit.hpp"

namespace talkface::detail {

namespace {

// The free sounds are compared with the path over the syllable and this much on either side, so
// that a boundary placed a few frames into the wrong sound counts.
constexpr std::size_t kGapMarginFrames = 10;
// Neighbours on each side whose evidence joins a syllable's.
constexpr std::size_t kNeighbours = 2;
// The evidence (mean posterior minus fit gap, the syllable's and its neighbourhood's averaged),
// less half the recording's median, mapped to 0..1 by a logistic: 0.5, kLowAlignmentConfidence,
// where 9.7% of the syllables within 100 ms fall on bench/'s human tuning passages, all
// conditions pooled (issue 12: at most 10% of the right ones flagged; a little under, so that a
// small change of the aligner does not cross it; set again each time the aligner changes which
// syllables are right); the slope spreads the evidence's usual range over most of 0..1.
constexpr double kEvidenceAtLow = 0.052;
constexpr double kSlope = 10.0;
constexpr double kRelativeShare = 0.5;

double log_sum_exp(const float* values, int count) {
    float largest = values[0];
    for (int i = 1; i < count; ++i) largest = std::max(largest, values[i]);
    double sum = 0.0;
    for (int i = 0; i < count; ++i) sum += std::exp(static_cast<double>(values[i] - largest));
    return largest + std::log(sum);
}

}  // namespace

std::vector<double> syllable_fits(const SentenceChain& chain, const std::vector<StateSegment>& path,
                                  const EmissionScores& scores, const std::vector<SyllableFrames>& frames) {
    // The class the path gives each frame.
    std::vector<int> frame_class(scores.frame_count, kSilence);
    for (const auto& segment : path)
        for (std::size_t t = segment.first_frame; t < std::min(segment.end_frame, scores.frame_count); ++t)
            frame_class[t] = chain.states[segment.state].phone_class;
    std::vector<double> fits(frames.size(), 0.0);
    for (std::size_t i = 0; i < frames.size(); ++i) {
        const std::size_t first = std::min(frames[i].first_frame, scores.frame_count);
        const std::size_t end = std::min(std::max(frames[i].end_frame, first), scores.frame_count);
        double sum = 0.0;
        for (std::size_t t = first; t < end; ++t) {
            const float* row = &scores.values[t * kPhoneClassCount];
            sum += std::exp(static_cast<double>(scores.at(t, frame_class[t])) - log_sum_exp(row, kPhoneClassCount));
        }
        const double posterior = end > first ? sum / static_cast<double>(end - first) : 0.0;
        const std::size_t low = first > kGapMarginFrames ? first - kGapMarginFrames : 0;
        const std::size_t high = std::min(scores.frame_count, end + kGapMarginFrames);
        double forced = 0.0;
        for (std::size_t t = low; t < high; ++t) forced += scores.at(t, frame_class[t]);
        const double gap = high > low ? (free_sounds_score(scores, low, high) - forced) / static_cast<double>(high - low) : 0.0;
        fits[i] = posterior - gap;
    }
    return fits;
}

std::vector<double> syllable_evidence(const std::vector<double>& fits) {
    const std::size_t count = fits.size();
    std::vector<double> evidence(count, 0.0);
    for (std::size_t i = 0; i < count; ++i) {
        const std::size_t first = i > kNeighbours ? i - kNeighbours : 0;
        const std::size_t end = std::min(count, i + kNeighbours + 1);
        double around = 0.0;
        for (std::size_t j = first; j < end; ++j) around += fits[j];
        around /= static_cast<double>(end - first);
        evidence[i] = 0.5 * fits[i] + 0.5 * around;
    }
    return evidence;
}

void set_confidences(const std::vector<double>& evidence, Timeline& result) {
    std::vector<double> placed;
    for (const double value : evidence)
        if (!std::isnan(value)) placed.push_back(value);
    if (placed.empty()) return;
    const auto middle = placed.begin() + static_cast<std::ptrdiff_t>(placed.size() / 2);
    std::nth_element(placed.begin(), middle, placed.end());
    const double median = *middle;
    for (std::size_t i = 0; i < evidence.size() && i < result.syllables.size(); ++i) {
        if (std::isnan(evidence[i])) continue;
        const double calibrated = evidence[i] - kRelativeShare * median;
        result.syllables[i].confidence = 1.0 / (1.0 + std::exp(-kSlope * (calibrated - kEvidenceAtLow)));
    }
}

}  // namespace talkface::detail

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
// The evidence (mean posterior minus fit gap, plus the timing's, the syllable's and its
// neighbourhood's averaged), less half the recording's median, mapped to 0..1 by a logistic: 0.5,
// kLowAlignmentConfidence, where 9.6% of the syllables within 100 ms fell on bench/'s human tuning
// passages, all conditions pooled, when it was set (9.0% since the cutter reads held music as
// pause). Issue 12: at most 10% of the right ones flagged; a little under, so that a small change
// of the aligner does not cross it; set again each time the aligner or the evidence changes. The
// slope spreads the evidence's usual range over most of 0..1.
constexpr double kEvidenceAtLow = 0.027;
constexpr double kSlope = 10.0;
constexpr double kRelativeShare = 0.5;
// What a syllable's timing adds to its evidence (syllable_timing): the spectral change where it
// starts, per unit of the landmarks' bonus; its length against the pace of the syllables around it
// (kPaceSyllables either side), per unit of |log ratio|; and its states' lengths against their
// priors, per unit of mean squared log-normal z. Set together on bench/'s human tuning passages
// (session 11): a drifted syllable starts where the spectrum changes little, and the path squeezes
// or stretches it and its sounds to make it fit. Each alone catches a few more; halving or
// doubling one moves the catch by a few of bench/'s 368 syllables more than 100 ms off.
constexpr double kBoundaryWeight = 0.05;
constexpr double kPaceWeight = 0.2;
constexpr double kStateLengthWeight = 0.02;
constexpr std::size_t kPaceSyllables = 4;

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

std::vector<double> syllable_timing(const SentenceChain& chain, const std::vector<StateSegment>& path,
                                    const EmissionScores& scores, const std::vector<SyllableFrames>& frames) {
    const std::size_t count = frames.size();
    std::vector<double> expected(count, 0.0), squared_z(count, 0.0), states(count, 0.0);
    for (const auto& state : chain.states)
        if (state.syllable < count && !is_pause(state.role) && !state.is_optional) expected[state.syllable] += state.median_frames;
    for (const auto& segment : path) {
        const PhoneState& state = chain.states[segment.state];
        if (state.syllable >= count || is_pause(state.role) || segment.end_frame <= segment.first_frame) continue;
        const double z = (std::log(static_cast<double>(segment.end_frame - segment.first_frame)) - std::log(state.median_frames)) /
                         state.log_sigma;
        squared_z[state.syllable] += z * z;
        states[state.syllable] += 1.0;
    }
    // Each syllable's length against its prior's: the pace it was said at, relative to its neighbours'.
    std::vector<double> pace(count, 0.0);
    for (std::size_t i = 0; i < count; ++i) {
        const double length = static_cast<double>(std::max<std::size_t>(frames[i].end_frame - frames[i].first_frame, 1));
        pace[i] = std::log(length / std::max(expected[i], 1.0));
    }
    std::vector<double> timing(count, 0.0);
    for (std::size_t i = 0; i < count; ++i) {
        const std::size_t first = i > kPaceSyllables ? i - kPaceSyllables : 0;
        std::vector<double> around(pace.begin() + static_cast<std::ptrdiff_t>(first),
                                   pace.begin() + static_cast<std::ptrdiff_t>(std::min(count, i + kPaceSyllables + 1)));
        const auto middle = around.begin() + static_cast<std::ptrdiff_t>(around.size() / 2);
        std::nth_element(around.begin(), middle, around.end());
        const double boundary = frames[i].first_frame < scores.boundary.size() ? scores.boundary[frames[i].first_frame] : 0.0;
        const double state_z = states[i] > 0.0 ? squared_z[i] / states[i] : 0.0;
        timing[i] = kBoundaryWeight * boundary - kPaceWeight * std::fabs(pace[i] - *middle) - kStateLengthWeight * state_z;
    }
    return timing;
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

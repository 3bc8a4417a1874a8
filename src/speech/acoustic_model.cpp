#include "speech/acoustic_model.hpp"

#include <algorithm>
#include <cmath>

#include "common/order_statistics.hpp"
#include "speech/avx2_clones.hpp"
#include "speech/spectral_landmarks.hpp"

namespace talkface::detail {

namespace {

constexpr double kLogTwoPi = 1.8378770664093453;
// Frames a class needs before its own statistics outweigh its group's (MAP prior weight).
constexpr double kPriorFrames = 30.0;
// Variances never fall below this share of the pooled variance: a class seen on a few similar
// frames must not become a spike that wins or loses everything.
constexpr double kVarianceFloorShare = 0.05;
// A sentence's observations read its levels above the floor against its loud frames' level, this
// percentile of them, and no lower than kLeastLevelDb: a stretch barely above the floor is quiet,
// not loud speech at a low gain.
constexpr double kLoudFramesPercentile = 0.95;
constexpr float kLeastLevelDb = 10.0f;
// The cepstra observed, c1..c12: c0 duplicates the loudness.
constexpr int kObservedCepstra = kCepstrumCount - 1;

float level_percentile(std::vector<float> values, double fraction) {
    return values.empty() ? 0.0f : percentile_of(std::move(values), fraction);
}

int broad_group(int phone_class) {
    if (phone_class == kSilence) return 0;
    if (phone_class == kBurst || phone_class == kAspiration || phone_class == kSibilant) return 1;
    return 2;
}

// Column by column, all classes at once: each class's sum takes its terms in the same order as
// class by class, so the scores are the same to the bit, but the classes' sums are independent
// lanes the compiler vectorizes (kScoreLanes doubles, three of them unused: eight SSE registers a
// column, four in the AVX2 clone, avx2_clones.hpp), and each column is read once a frame, not once
// a class. `means` and `inverse_variances` are by column, kScoreLanes a column.
constexpr std::size_t kScoreLanes = 16;
static_assert(kScoreLanes >= kPhoneClassCount);
TALKFACE_AVX2_CLONES void score_frames(const float* observations, std::size_t frame_count, const int* columns,
                                       std::size_t dims, const double* means, const double* inverse_variances,
                                       const double* log_norm, double weight, float* values) {
    for (std::size_t t = 0; t < frame_count; ++t) {
        const float* row = &observations[t * kObservationCount];
        std::array<double, kScoreLanes> sums{};
        for (std::size_t k = 0; k < dims; ++k) {
            const double value = row[columns[k]];
            const double* mean = &means[k * kScoreLanes];
            const double* inverse_variance = &inverse_variances[k * kScoreLanes];
            for (std::size_t c = 0; c < kScoreLanes; ++c) {
                const double difference = value - mean[c];
                sums[c] += difference * difference * inverse_variance[c];
            }
        }
        for (std::size_t c = 0; c < kPhoneClassCount; ++c)
            values[t * kPhoneClassCount + c] = static_cast<float>(weight * (log_norm[c] - 0.5 * sums[c]));
    }
}

}  // namespace

void observe(const FeatureTrack& track, const LoudnessProfile& loudness, const FrameSpan& span,
             std::vector<float>& result) {
    const std::size_t frames = span.length();
    std::vector<float> energy(frames), low(frames), high(frames);
    for (std::size_t i = 0; i < frames; ++i) {
        const std::size_t t = span.first_frame + i;
        energy[i] = std::max(0.0f, track.at(t, kEnergyDb) - loudness.energy_sound_floor_db);
        low[i] = std::max(0.0f, track.at(t, kLowBandDb) - loudness.low_sound_floor_db);
        high[i] = std::max(0.0f, track.at(t, kHighBandDb) - loudness.high_sound_floor_db);
    }
    // Levels relative to this sentence's loud frames: the same sound reads the same at any gain
    // and any noise level (SPEC "Alignment": loudness above the noise floor).
    const float speech_level = std::max(kLeastLevelDb, level_percentile(energy, kLoudFramesPercentile));
    const float low_level = std::max(kLeastLevelDb, level_percentile(low, kLoudFramesPercentile));
    result.assign(frames * kObservationCount, 0.0f);
    for (std::size_t i = 0; i < frames; ++i) {
        float* row = &result[i * kObservationCount];
        const std::size_t t = span.first_frame + i;
        for (int c = 0; c < kObservedCepstra; ++c) row[kCepstrum1 + c] = track.at(t, kCepstrum0 + 1 + c);
        row[kLoudness] = energy[i] / speech_level;
        row[kTilt] = (high[i] - low[i]) / speech_level;
        row[kLowBand] = low[i] / low_level;
    }
    // Regression deltas over +-2 frames, clamped at the span's edges.
    const auto last = static_cast<std::ptrdiff_t>(frames) - 1;
    for (std::ptrdiff_t i = 0; i <= last; ++i) {
        float* row = &result[static_cast<std::size_t>(i) * kObservationCount];
        auto at = [&](std::ptrdiff_t frame, int column) {
            return result[static_cast<std::size_t>(std::clamp<std::ptrdiff_t>(frame, 0, last)) * kObservationCount +
                          static_cast<std::size_t>(column)];
        };
        for (int c = 0; c < kObservedCepstra; ++c)
            row[kDeltaCepstrum1 + c] = (at(i + 1, c) - at(i - 1, c) + 2.0f * (at(i + 2, c) - at(i - 2, c))) / 10.0f;
        row[kDeltaLoudness] = (at(i + 1, kLoudness) - at(i - 1, kLoudness) +
                               2.0f * (at(i + 2, kLoudness) - at(i - 2, kLoudness))) / 10.0f;
    }
}

AcousticModel AcousticModel::hand_set() {
    // Means and spreads of (loudness, tilt, low band) per class, from what is known of the sounds:
    // closures and pauses sit at the floor; sibilants are weak below 900 Hz and strong above
    // 2.5 kHz; nasals and liquids are voiced, low-band heavy and a little weaker than vowels; /i/
    // and the apical vowel carry more high-frequency energy than /a o u/.
    struct Row { double loud, loud_sd, tilt, tilt_sd, low, low_sd; };
    const std::array<Row, kPhoneClassCount> rows{{
        {0.05, 0.10, 0.00, 0.12, 0.05, 0.10},   // silence
        {0.45, 0.22, 0.10, 0.25, 0.30, 0.22},   // burst
        {0.35, 0.18, 0.05, 0.22, 0.20, 0.18},   // aspiration, f, h
        {0.50, 0.20, 0.30, 0.22, 0.20, 0.18},   // sibilant
        {0.75, 0.15, -0.45, 0.22, 0.85, 0.15},  // nasal
        {0.80, 0.15, -0.35, 0.22, 0.85, 0.15},  // liquid
        {0.92, 0.12, -0.25, 0.22, 0.90, 0.12},  // a
        {0.90, 0.12, -0.25, 0.22, 0.90, 0.12},  // e
        {0.88, 0.12, -0.15, 0.22, 0.88, 0.12},  // i
        {0.90, 0.12, -0.35, 0.22, 0.90, 0.12},  // o
        {0.86, 0.12, -0.40, 0.22, 0.88, 0.12},  // u
        {0.88, 0.12, -0.20, 0.22, 0.88, 0.12},  // u-umlaut
        {0.85, 0.12, -0.10, 0.22, 0.85, 0.12},  // apical
    }};
    AcousticModel model;
    model.columns_ = {kLoudness, kTilt, kLowBand};
    for (int c = 0; c < kPhoneClassCount; ++c) {
        const Row& row = rows[static_cast<std::size_t>(c)];
        const double means[3] = {row.loud, row.tilt, row.low};
        const double sds[3] = {row.loud_sd, row.tilt_sd, row.low_sd};
        double log_norm = 0.0;
        for (int k = 0; k < 3; ++k) {
            model.mean_.push_back(means[k]);
            model.inverse_variance_.push_back(1.0 / (sds[k] * sds[k]));
            log_norm -= 0.5 * (kLogTwoPi + 2.0 * std::log(sds[k]));
        }
        model.log_norm_[static_cast<std::size_t>(c)] = log_norm;
    }
    return model;
}

void AcousticModel::score(const float* observations, std::size_t frame_count, EmissionScores& scores) const {
    scores.frame_count = frame_count;
    scores.values.resize(frame_count * kPhoneClassCount);
    const std::size_t dims = columns_.size();
    std::vector<double> mean_by_column(dims * kScoreLanes, 0.0),
        inverse_variance_by_column(dims * kScoreLanes, 0.0);
    for (std::size_t k = 0; k < dims; ++k) {
        for (std::size_t c = 0; c < kPhoneClassCount; ++c) {
            mean_by_column[k * kScoreLanes + c] = mean_[c * dims + k];
            inverse_variance_by_column[k * kScoreLanes + c] = inverse_variance_[c * dims + k];
        }
    }
    score_frames(observations, frame_count, columns_.data(), dims, mean_by_column.data(),
                 inverse_variance_by_column.data(), log_norm_.data(), weight_, scores.values.data());
    set_boundary_bonus(observations, frame_count, scores);
}

ModelEstimator::ModelEstimator()
    : sum_(static_cast<std::size_t>(kPhoneClassCount) * kObservationCount, 0.0),
      sum_squares_(static_cast<std::size_t>(kPhoneClassCount) * kObservationCount, 0.0) {}

void ModelEstimator::add(const std::vector<float>& observations, const std::vector<PhoneState>& states,
                         const std::vector<StateSegment>& path) {
    for (const auto& segment : path) {
        // Generic speech (a word no table reads) is any sound: it teaches no class.
        if (states[segment.state].phone_class == kGenericSpeech) continue;
        const auto c = static_cast<std::size_t>(states[segment.state].phone_class);
        for (std::size_t t = segment.first_frame; t < segment.end_frame; ++t) {
            const float* row = &observations[t * kObservationCount];
            for (std::size_t k = 0; k < kObservationCount; ++k) {
                sum_[c * kObservationCount + k] += row[k];
                sum_squares_[c * kObservationCount + k] += static_cast<double>(row[k]) * row[k];
            }
        }
        count_[c] += static_cast<double>(segment.end_frame - segment.first_frame);
    }
}

void ModelEstimator::subtract(const ModelEstimator& part) {
    for (std::size_t c = 0; c < count_.size(); ++c) count_[c] -= part.count_[c];
    for (std::size_t i = 0; i < sum_.size(); ++i) {
        sum_[i] -= part.sum_[i];
        sum_squares_[i] -= part.sum_squares_[i];
    }
}

AcousticModel ModelEstimator::estimate(double weight) const {
    constexpr std::size_t dims = kObservationCount;
    std::array<double, 3> group_count{};
    std::vector<double> group_sum(3 * dims, 0.0), group_squares(3 * dims, 0.0);
    std::vector<double> pooled_sum(dims, 0.0), pooled_squares(dims, 0.0);
    double pooled_count = 0.0;
    for (int c = 0; c < kPhoneClassCount; ++c) {
        const auto g = static_cast<std::size_t>(broad_group(c));
        group_count[g] += count_[static_cast<std::size_t>(c)];
        pooled_count += count_[static_cast<std::size_t>(c)];
        for (std::size_t k = 0; k < dims; ++k) {
            group_sum[g * dims + k] += sum_[static_cast<std::size_t>(c) * dims + k];
            group_squares[g * dims + k] += sum_squares_[static_cast<std::size_t>(c) * dims + k];
            pooled_sum[k] += sum_[static_cast<std::size_t>(c) * dims + k];
            pooled_squares[k] += sum_squares_[static_cast<std::size_t>(c) * dims + k];
        }
    }
    AcousticModel model;
    model.weight_ = weight;
    for (std::size_t k = 0; k < dims; ++k) model.columns_.push_back(static_cast<int>(k));
    const double safe_pooled = std::max(pooled_count, 1.0);
    for (int c = 0; c < kPhoneClassCount; ++c) {
        const auto ci = static_cast<std::size_t>(c);
        const auto g = static_cast<std::size_t>(broad_group(c));
        const double n = count_[ci];
        const double n_group = group_count[g];
        double log_norm = 0.0;
        for (std::size_t k = 0; k < dims; ++k) {
            const double pooled_mean = pooled_sum[k] / safe_pooled;
            const double pooled_variance = std::max(pooled_squares[k] / safe_pooled - pooled_mean * pooled_mean, 1e-6);
            // The group's statistics, themselves leaning on the pooled ones when the group is rare.
            const double group_mean = (group_sum[g * dims + k] + kPriorFrames * pooled_mean) / (n_group + kPriorFrames);
            const double group_second = (group_squares[g * dims + k] + kPriorFrames * (pooled_variance + pooled_mean * pooled_mean)) /
                                        (n_group + kPriorFrames);
            const double mean = (sum_[ci * dims + k] + kPriorFrames * group_mean) / (n + kPriorFrames);
            const double second = (sum_squares_[ci * dims + k] + kPriorFrames * group_second) / (n + kPriorFrames);
            const double variance = std::max(second - mean * mean, kVarianceFloorShare * pooled_variance);
            model.mean_.push_back(mean);
            model.inverse_variance_.push_back(1.0 / variance);
            log_norm -= 0.5 * (kLogTwoPi + std::log(variance));
        }
        model.log_norm_[ci] = log_norm;
    }
    return model;
}

}  // namespace talkface::detail

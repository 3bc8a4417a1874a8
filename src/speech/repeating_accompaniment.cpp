#include "speech/repeating_accompaniment.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "common/order_statistics.hpp"

namespace talkface::detail {

double accompaniment_period_frames(const FeatureTrack& track, float high_floor_db) {
    const std::size_t frames = track.frame_count;
    const std::size_t longest_lag = 2 * kLongestRepeatFrames;
    if (frames < 2 * longest_lag) return 0.0;
    // Onsets: how far the high band rises over the frame before, above the floor of its sound.
    std::vector<double> onset(frames, 0.0);
    float previous = std::max(track.at(0, kHighBandDb), high_floor_db);
    double mean = 0.0;
    for (std::size_t t = 1; t < frames; ++t) {
        const float level = std::max(track.at(t, kHighBandDb), high_floor_db);
        onset[t] = std::max(0.0f, level - previous);
        previous = level;
        mean += onset[t];
    }
    mean /= static_cast<double>(frames);
    double power = 0.0;
    for (double& value : onset) {
        value -= mean;
        power += value * value;
    }
    if (power <= 0.0) return 0.0;
    // The correlation at each lag, per frame compared, against the onsets' power per frame.
    std::vector<double> correlation(longest_lag + 1, 0.0);
    for (std::size_t lag = kShortestRepeatFrames; lag <= longest_lag; ++lag) {
        double sum = 0.0;
        for (std::size_t t = 0; t + lag < frames; ++t) sum += onset[t] * onset[t + lag];
        correlation[lag] = sum / static_cast<double>(frames - lag) / (power / static_cast<double>(frames));
    }
    double best = -std::numeric_limits<double>::infinity();
    std::size_t best_lag = 0;
    for (std::size_t lag = kShortestRepeatFrames; lag <= kLongestRepeatFrames; ++lag) {
        const double score = 0.5 * (correlation[lag] + correlation[2 * lag]);
        if (score > best) {
            best = score;
            best_lag = lag;
        }
    }
    if (best < kBeatCorrelation) return 0.0;
    // To a fraction of a frame: the peak at the longest multiple of the lag in reach, where a
    // frame's rounding weighs least, interpolated by a parabola.
    const std::size_t multiple = std::min<std::size_t>(3, (longest_lag - 1) / best_lag);
    const std::size_t peak = multiple * best_lag;
    const double left = correlation[peak - 1], middle = correlation[peak], right = correlation[peak + 1];
    const double curvature = left - 2.0 * middle + right;
    const double shift = curvature < 0.0 ? std::clamp(0.5 * (left - right) / curvature, -0.5, 0.5) : 0.0;
    return (static_cast<double>(peak) + shift) / static_cast<double>(multiple);
}

std::vector<bool> repeated_hits_between_pauses(const std::vector<float>& activity_db, float threshold_db,
                                               double period_frames) {
    const std::size_t frames = activity_db.size();
    std::vector<bool> repeated(frames, false);
    if (period_frames <= 0.0) return repeated;
    std::vector<float> speech_db;
    for (float db : activity_db)
        if (db >= threshold_db) speech_db.push_back(db);
    if (speech_db.empty()) return repeated;
    const float speech_median_db = lower_median(std::move(speech_db));
    const auto count = static_cast<std::ptrdiff_t>(frames);
    const auto is_explained = [&](std::size_t t) {
        if (activity_db[t] >= speech_median_db) return false;
        for (const double multiple : kRepeatMultiples) {
            float predicted = std::numeric_limits<float>::infinity();
            std::size_t predictions = 0;
            for (std::size_t k = 1; k <= kRepeatsEachSide; ++k) {
                const auto offset = static_cast<std::ptrdiff_t>(std::lround(static_cast<double>(k) * multiple * period_frames));
                for (const std::ptrdiff_t at : {static_cast<std::ptrdiff_t>(t) - offset, static_cast<std::ptrdiff_t>(t) + offset}) {
                    if (at < 1 || at + 1 >= count) continue;
                    const auto i = static_cast<std::size_t>(at);
                    predicted = std::min(predicted, std::max({activity_db[i - 1], activity_db[i], activity_db[i + 1]}));
                    ++predictions;
                }
            }
            if (predictions == 1 && predicted >= speech_median_db) continue;
            if (activity_db[t] <= predicted + kRepeatMarginDb) return true;
        }
        return false;
    };
    for (std::size_t t = 0; t < frames;) {
        if (activity_db[t] < threshold_db) {
            ++t;
            continue;
        }
        std::size_t end = t;
        bool all_explained = true;
        for (; end < frames && activity_db[end] >= threshold_db; ++end) all_explained = all_explained && is_explained(end);
        if (all_explained) std::fill(repeated.begin() + static_cast<std::ptrdiff_t>(t), repeated.begin() + static_cast<std::ptrdiff_t>(end), true);
        t = end;
    }
    return repeated;
}

}  // namespace talkface::detail

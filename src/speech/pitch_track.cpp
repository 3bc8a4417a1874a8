#include "speech/pitch_track.hpp"

#include <algorithm>
#include <cmath>

namespace talkface::detail {

namespace {

constexpr double kDecimatedRateHz = 4000.0;
constexpr std::size_t kShortestLag = 10;  // 400 Hz
constexpr std::size_t kLongestLag = 50;   // 80 Hz
// A shorter period whose correlation reaches this share of the best one's is taken instead: the
// best is often at twice the period (a period repeats at every multiple of it).
constexpr double kShorterPeriodShare = 0.85;

}  // namespace

PitchFrame PitchTracker::push(const float* samples, std::size_t count) {
    std::array<float, kHistory> fresh{};
    std::size_t fresh_count = 0;
    for (std::size_t i = 0; i < count; ++i) {
        partial_[partial_count_++] = samples[i];
        if (partial_count_ < kDecimation) continue;
        partial_count_ = 0;
        float sum = 0.0f;
        for (const float v : partial_) sum += v;
        if (fresh_count == kHistory) {
            std::copy(fresh.begin() + 1, fresh.end(), fresh.begin());
            --fresh_count;
        }
        fresh[fresh_count++] = sum;
    }
    std::copy(history_.begin() + static_cast<std::ptrdiff_t>(fresh_count), history_.end(), history_.begin());
    std::copy(fresh.begin(), fresh.begin() + static_cast<std::ptrdiff_t>(fresh_count),
              history_.end() - static_cast<std::ptrdiff_t>(fresh_count));
    constexpr std::size_t kWidth = kHistory - kLongestLag;
    std::array<float, kHistory> x{};
    float mean = 0.0f;
    for (const float v : history_) mean += v;
    mean /= static_cast<float>(kHistory);
    for (std::size_t n = 0; n < kHistory; ++n) x[n] = history_[n] - mean;
    double base = 0.0;
    for (std::size_t n = 0; n < kWidth; ++n) base += static_cast<double>(x[n]) * x[n];
    if (!(base > 1e-12)) return {};
    std::array<double, kLongestLag + 2> r{};
    double shifted = 0.0;  // the energy of x[lag, lag + kWidth)
    for (std::size_t n = kShortestLag - 1; n < kShortestLag - 1 + kWidth; ++n) shifted += static_cast<double>(x[n]) * x[n];
    for (std::size_t lag = kShortestLag - 1; lag <= kLongestLag + 1 && lag + kWidth <= kHistory; ++lag) {
        if (lag > kShortestLag - 1) {
            shifted += static_cast<double>(x[lag + kWidth - 1]) * x[lag + kWidth - 1];
            shifted -= static_cast<double>(x[lag - 1]) * x[lag - 1];
        }
        float product = 0.0f;
        for (std::size_t n = 0; n < kWidth; ++n) product += x[n] * x[n + lag];
        r[lag] = shifted > 1e-12 ? product / std::sqrt(base * shifted) : 0.0;
    }
    std::size_t best = kShortestLag;
    for (std::size_t lag = kShortestLag; lag <= kLongestLag; ++lag)
        if (r[lag] > r[best]) best = lag;
    if (!(r[best] > 0.0)) return {};
    for (std::size_t lag = kShortestLag; lag < best; ++lag)
        if (r[lag] >= kShorterPeriodShare * r[best] && r[lag] >= r[lag - 1] && r[lag] >= r[lag + 1]) {
            best = lag;
            break;
        }
    // The peak between lags by the parabola through its neighbours.
    double peak = static_cast<double>(best);
    const double left = r[best - 1], middle = r[best], right = best + 1 <= kLongestLag + 1 ? r[best + 1] : middle;
    const double curve = left - 2.0 * middle + right;
    if (curve < 0.0) peak += std::clamp(0.5 * (left - right) / curve, -0.5, 0.5);
    return {static_cast<float>(kDecimatedRateHz / peak), static_cast<float>(std::min(1.0, middle))};
}

}  // namespace talkface::detail

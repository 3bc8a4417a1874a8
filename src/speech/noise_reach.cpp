#include "speech/noise_reach.hpp"

#include <limits>
#include <utility>

#include "common/order_statistics.hpp"

namespace talkface::detail {

namespace {

// The noise's own level (steady_noise_reach): the level it stays under on nine frames in ten, where
// they are at least 10 frames. A steady noise (hiss, a fan, hum, a phone line's) holds its high
// band within 6 dB from its tenth to its ninetieth percentile (white and pink noise: 1-2 dB); music
// and drums swing by 8-100 dB, and a frame under their reach says nothing of whether a sound is
// heard there.
constexpr double kNoiseReachShare = 0.9;
constexpr std::size_t kMinNoiseFrames = 10;
constexpr float kSteadyNoiseSpreadDb = 6.0f;

}  // namespace

float steady_noise_reach(std::vector<float> levels) {
    if (levels.size() < kMinNoiseFrames || noise_spread(levels) > kSteadyNoiseSpreadDb)
        return std::numeric_limits<float>::infinity();
    return percentile_of(std::move(levels), kNoiseReachShare);
}

float noise_spread(std::vector<float> levels) {
    if (levels.size() < kMinNoiseFrames) return 0.0f;
    const float reach = percentile_of(levels, kNoiseReachShare);
    return reach - percentile_of(std::move(levels), 1.0 - kNoiseReachShare);
}

}  // namespace talkface::detail

#include "speech/changing_spectrum.hpp"

#include <algorithm>
#include <cmath>

namespace talkface::detail {

namespace {

constexpr double kBinHz = static_cast<double>(kAnalysisRateHz) / PowerSpectrum::kSize;
constexpr auto kFirstBin = static_cast<std::size_t>(kChangeBandLowHz / kBinHz) + 1;
constexpr auto kEndBin = static_cast<std::size_t>(kChangeBandHighHz / kBinHz) + 1;

}  // namespace

void ChangingSpectrum::push(const float* power) {
    std::copy(power, power + PowerSpectrum::kBins, kept_[pushed_ % kKept].begin());
    ++pushed_;
    if (pushed_ > kChangeLagFrames) {
        const std::size_t frame = pushed_ - 1 - kChangeLagFrames;
        const float* before = frame >= kChangeLagFrames ? kept_[(frame - kChangeLagFrames) % kKept].data() : nullptr;
        write(frame, before, kept_[(pushed_ - 1) % kKept].data());
    }
}

void ChangingSpectrum::finish() {
    for (std::size_t frame = written_; frame < pushed_; ++frame) {
        const float* before = frame >= kChangeLagFrames ? kept_[(frame - kChangeLagFrames) % kKept].data() : nullptr;
        write(frame, before, nullptr);
    }
}

void ChangingSpectrum::write(std::size_t frame, const float* before, const float* after) {
    const float* power = kept_[frame % kKept].data();
    double band = 0.0;
    double changing = 0.0;
    for (std::size_t k = kFirstBin; k < kEndBin; ++k) {
        band += power[k];
        // At the ends of the recording only one side is known; with neither, all of it changes.
        const float held = before != nullptr && after != nullptr ? std::min(before[k], after[k])
                           : before != nullptr                   ? before[k]
                           : after != nullptr                    ? after[k]
                                                                 : 0.0f;
        changing += std::max(0.0f, power[k] - kChangeRatio * held);
    }
    float* row = &track_.values[frame * kFeatureCount];
    row[kChangeBandDb] = static_cast<float>(power_to_db(band + kFeatureEnergyFloor));
    row[kChangingDb] = static_cast<float>(power_to_db(changing + kFeatureEnergyFloor));
    written_ = frame + 1;
}

}  // namespace talkface::detail

#include "speech/steady_tone.hpp"

#include <algorithm>
#include <cmath>

#include "speech/power_spectrum.hpp"

namespace talkface::detail {

std::vector<bool> steady_tone_frames(const FeatureTrack& track) {
    const std::size_t frames = track.frame_count;
    std::vector<bool> tone(frames, false);
    const auto lowest_bin = static_cast<float>(kLowestToneHz * PowerSpectrum::kSize / kAnalysisRateHz);
    const auto on_line = [&](std::size_t t) {
        return track.at(t, kLineShare) >= kToneLineShare && track.at(t, kLineBin) >= lowest_bin;
    };
    for (std::size_t first = 0; first < frames;) {
        if (!on_line(first)) { ++first; continue; }
        // The longest run from `first` whose bins and levels stay within their spreads.
        float low_bin = track.at(first, kLineBin), high_bin = low_bin;
        float low_db = track.at(first, kEnergyDb), high_db = low_db;
        std::size_t end = first + 1;
        for (; end < frames && on_line(end); ++end) {
            const float bin = track.at(end, kLineBin), db = track.at(end, kEnergyDb);
            if (std::max(high_bin, bin) - std::min(low_bin, bin) > kToneBinSpread ||
                std::max(high_db, db) - std::min(low_db, db) > kToneLevelSpreadDb)
                break;
            low_bin = std::min(low_bin, bin), high_bin = std::max(high_bin, bin);
            low_db = std::min(low_db, db), high_db = std::max(high_db, db);
        }
        if (end - first < kShortestToneFrames) { ++first; continue; }
        std::fill(tone.begin() + static_cast<std::ptrdiff_t>(first), tone.begin() + static_cast<std::ptrdiff_t>(end), true);
        const auto is_edge = [&](std::size_t t) {
            const float bin = track.at(t, kLineBin);
            return track.at(t, kLineShare) >= kToneEdgeLineShare && bin >= low_bin - kToneBinSpread && bin <= high_bin + kToneBinSpread;
        };
        for (std::size_t i = 1; i <= kToneEdgeFrames && i <= first && is_edge(first - i); ++i) tone[first - i] = true;
        for (std::size_t i = 0; i < kToneEdgeFrames && end + i < frames && is_edge(end + i); ++i) tone[end + i] = true;
        first = end;
    }
    return tone;
}

}  // namespace talkface::detail

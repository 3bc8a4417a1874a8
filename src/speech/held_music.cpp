#include "speech/held_music.hpp"

#include <algorithm>
#include <cmath>

#include "common/order_statistics.hpp"

namespace talkface::detail {

std::vector<float> changing_shares(const FeatureTrack& track) {
    const std::size_t frames = track.frame_count;
    // Running sums of the band's power and of its changing part, for the share over any window.
    std::vector<double> band(frames + 1, 0.0);
    std::vector<double> changing(frames + 1, 0.0);
    for (std::size_t t = 0; t < frames; ++t) {
        band[t + 1] = band[t] + db_to_power(track.at(t, kChangeBandDb));
        changing[t + 1] = changing[t] + db_to_power(track.at(t, kChangingDb));
    }
    std::vector<float> share(frames);
    for (std::size_t t = 0; t < frames; ++t) {
        const std::size_t first = t >= kHeldMusicHalfWindow ? t - kHeldMusicHalfWindow : 0;
        const std::size_t end = std::min(frames, t + kHeldMusicHalfWindow + 1);
        share[t] = static_cast<float>((changing[end] - changing[first]) / (band[end] - band[first] + kFeatureEnergyFloor));
    }
    return share;
}

std::vector<bool> held_music_frames(const FeatureTrack& track, const std::vector<float>& share,
                                    const std::vector<float>& activity_db, float threshold_db) {
    const std::size_t frames = track.frame_count;
    std::vector<bool> held(frames, false);
    std::vector<float> quiet_share;
    std::vector<float> speech_db;
    for (std::size_t t = 0; t < frames; ++t) {
        if (activity_db[t] >= threshold_db) speech_db.push_back(activity_db[t]);
        else if (track.at(t, kChangeBandDb) > kDigitalSilenceDb) quiet_share.push_back(share[t]);  // frames of digital silence hold no change to judge
    }
    if (quiet_share.empty() || speech_db.empty() || lower_median(quiet_share) >= kNoiseChangeShare) return held;
    const float speech_median_db = lower_median(speech_db);
    for (std::size_t t = 0; t < frames; ++t)
        held[t] = share[t] < kHeldMusicChangeShare && activity_db[t] < speech_median_db;
    return held;
}

float loud_change_share(const FeatureTrack& track, const std::vector<float>& share,
                        const std::vector<float>& activity_db, float threshold_db, std::size_t first,
                        std::size_t end) {
    std::vector<float> loud;
    for (std::size_t t = first; t < end; ++t)
        if (activity_db[t] >= threshold_db && track.at(t, kChangeBandDb) > kDigitalSilenceDb)
            loud.push_back(share[t]);
    return loud.empty() ? 0.0f : lower_median(std::move(loud));
}

}  // namespace talkface::detail

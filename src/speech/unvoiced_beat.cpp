#include "speech/unvoiced_beat.hpp"

#include "speech/held_music.hpp"

namespace talkface::detail {

double loud_voiced_share(const FeatureTrack& track, const std::vector<float>& activity_db, float threshold_db,
                         std::size_t first, std::size_t end) {
    std::size_t loud = 0, voiced = 0;
    for (std::size_t t = first; t < end; ++t) {
        if (!is_loud_sounding_frame(track, activity_db, threshold_db, t)) continue;
        ++loud;
        if (track.at(t, kLowBandDb) > track.at(t, kHighBandDb) && track.at(t, kLineShare) < kLoneLineShare)
            ++voiced;
    }
    return loud == 0 ? 0.0 : static_cast<double>(voiced) / static_cast<double>(loud);
}

}  // namespace talkface::detail

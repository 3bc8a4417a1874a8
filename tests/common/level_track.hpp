// A feature track made of whole-band levels alone, as the tests of what reads them build it by hand
// (a room's tails and falls: sentence_chains_test, room_fall_test).
#ifndef TALKFACE_TESTS_LEVEL_TRACK_HPP
#define TALKFACE_TESTS_LEVEL_TRACK_HPP

#include <cstddef>
#include <vector>

#include "speech/frame_features.hpp"

namespace talkface::test {

// A feature track whose whole-band level per frame is `levels_db` (the other columns 0).
inline detail::FeatureTrack track_of(const std::vector<float>& levels_db) {
    detail::FeatureTrack track;
    track.frame_count = levels_db.size();
    track.duration_s = static_cast<double>(levels_db.size()) * detail::kFrameStepS;
    track.values.assign(levels_db.size() * detail::kFeatureCount, 0.0f);
    for (std::size_t t = 0; t < levels_db.size(); ++t)
        track.values[t * detail::kFeatureCount + detail::kEnergyDb] = levels_db[t];
    return track;
}

}  // namespace talkface::test

#endif

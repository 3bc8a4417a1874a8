#include "speech/lifted_noise.hpp"

#include <algorithm>

#include "common/order_statistics.hpp"

namespace talkface::detail {

namespace {

// Per frame, `column`'s kLiftFloorPercentile over the frames within kLiftHalfFrames, taken at the
// middle of each stride and held over it.
std::vector<float> moving_floor(const FeatureTrack& track, int column) {
    const std::size_t frames = track.frame_count;
    std::vector<float> floor(frames);
    std::vector<float> window;
    for (std::size_t t = 0; t < frames; t += kLiftStrideFrames) {
        const std::size_t middle = std::min(frames - 1, t + kLiftStrideFrames / 2);
        const std::size_t first = middle >= kLiftHalfFrames ? middle - kLiftHalfFrames : 0;
        const std::size_t end = std::min(frames, middle + kLiftHalfFrames + 1);
        window.clear();
        for (std::size_t i = first; i < end; ++i) window.push_back(track.at(i, column));
        const std::size_t stride_end = std::min(frames, t + kLiftStrideFrames);
        std::fill(floor.begin() + static_cast<std::ptrdiff_t>(t),
                  floor.begin() + static_cast<std::ptrdiff_t>(stride_end),
                  percentile_of(window, kLiftFloorPercentile));
    }
    return floor;
}

}  // namespace

std::array<float, 3> bands_above_floors(const FeatureTrack& track, std::size_t t, float low_floor_db,
                                        float mid_floor_db, float high_floor_db) {
    return {track.at(t, kLowBandDb) - low_floor_db, track.at(t, kMidBandDb) - mid_floor_db,
            track.at(t, kHighBandDb) - high_floor_db};
}

bool keeps_floor_shape(const std::array<float, 3>& above_db) {
    const auto [lowest, highest] = std::minmax_element(above_db.begin(), above_db.end());
    return *highest - *lowest < kLiftShapeDb;
}

std::vector<float> noise_lift_db(const FeatureTrack& track, float low_floor_db, float mid_floor_db,
                                 float high_floor_db, float speech_level_db, std::size_t min_run_frames,
                                 const FrameSpan& voice) {
    const std::size_t frames = track.frame_count;
    std::vector<float> lift(frames, 0.0f);
    if (std::min({low_floor_db, mid_floor_db, high_floor_db}) <= kDigitalSilenceDb) return lift;
    const std::vector<float> low = moving_floor(track, kLowBandDb);
    const std::vector<float> mid = moving_floor(track, kMidBandDb);
    const std::vector<float> high = moving_floor(track, kHighBandDb);
    for (std::size_t t = voice.first_frame; t < std::min(frames, voice.end_frame); ++t) {
        const std::array<float, 3> above =
            bands_above_floors(track, t, low_floor_db, mid_floor_db, high_floor_db);
        if (*std::max_element(above.begin(), above.end()) > speech_level_db - kLiftBelowSpeechDb ||
            !keeps_floor_shape(above))
            continue;
        lift[t] =
            std::max(0.0f, std::min({low[t] - low_floor_db, mid[t] - mid_floor_db, high[t] - high_floor_db}));
    }
    for (std::size_t t = 0; t < frames;) {
        if (lift[t] <= 0.0f) {
            ++t;
            continue;
        }
        std::size_t end = t;
        while (end < frames && lift[end] > 0.0f) ++end;
        if (end - t < min_run_frames)
            std::fill(lift.begin() + static_cast<std::ptrdiff_t>(t),
                      lift.begin() + static_cast<std::ptrdiff_t>(end), 0.0f);
        t = end;
    }
    return lift;
}

}  // namespace talkface::detail

#include "speech/lifted_lead_in.hpp"

#include <algorithm>
#include <array>
#include <vector>

#include "common/order_statistics.hpp"

namespace talkface::detail {

namespace {

// The lead-in's noise breaks the floor's shape a frame or two at a time (its own ripple: p-fast-
// combo's street noise), now and then a few (kLastingUnevenShare); a voice's first sound breaks it
// for longer. Ended by the level alone, the lead-in took in a line's quiet first syllables where
// the gain held them under the lifted noise (p-fast-combo tuning: 明天 546 ms late).
constexpr std::size_t kShapeBreakFrames = 3;
// A voice's uneven bands last: its first sound holds them out of the floor's shape through most of
// a pause's length of frames from the break, where street noise (brown and pink, through an Opus
// codec) breaks the shape for three to five frames at a time and comes back to it. Ended at the
// first break, the lead-in ended 10 or more frames short of the line in 17 of short_kinds_bench's
// 38 p-fast-combo tuning lines (9 of them inside its first pause's length, so none was found), and
// the line's first syllables were spread over the noise left (救我 490 ms early; bench/README.md,
// session 31). Shares from 0.5 to 1 read 54.9-56.8% within 50 ms there (tuning), but at 1 (every
// frame) 明天早上見吧's quiet 明 was left in the lead-in.
constexpr double kLastingUnevenShare = 0.75;

}  // namespace

std::optional<FrameSpan> lifted_lead_in(const FeatureTrack& track, float low_floor_db, float mid_floor_db,
                                        float high_floor_db, std::size_t min_run_frames) {
    const std::size_t frames = track.frame_count;
    if (frames <= min_run_frames ||
        std::min({low_floor_db, mid_floor_db, high_floor_db}) <= kDigitalSilenceDb)
        return std::nullopt;
    const auto above = [&](std::size_t t) {
        return bands_above_floors(track, t, low_floor_db, mid_floor_db, high_floor_db);
    };
    const auto loudest = [&](std::size_t t) {
        const std::array<float, 3> bands = above(t);
        return *std::max_element(bands.begin(), bands.end());
    };
    std::vector<float> levels;
    for (std::size_t t = 0; t < min_run_frames; ++t) levels.push_back(loudest(t));
    const float noise_db = percentile_of(levels, 0.5);
    // Whether the frames from `first` on break the shape as a voice does: through kLastingUnevenShare
    // of the next `min_run_frames`.
    const auto stays_uneven = [&](std::size_t first) {
        const std::size_t stop = std::min(frames, first + min_run_frames);
        std::size_t uneven = 0;
        for (std::size_t t = first; t < stop; ++t) uneven += keeps_floor_shape(above(t)) ? 0 : 1;
        return static_cast<double>(uneven) >= kLastingUnevenShare * static_cast<double>(stop - first);
    };
    std::size_t end = 0, uneven = 0;
    bool is_shape_break = false;
    for (; end < frames && loudest(end) < noise_db + kLiftBelowSpeechDb; ++end) {
        uneven = keeps_floor_shape(above(end)) ? 0 : uneven + 1;
        if (uneven == kShapeBreakFrames && stays_uneven(end + 1 - kShapeBreakFrames)) {
            end -= kShapeBreakFrames - 1;
            is_shape_break = true;
            break;
        }
    }
    // Where the level ended it, it rose on the first vowel: a quiet initial before it stays under
    // the lifted noise's level and breaks the floor's shape for too few frames to end the lead-in
    // alone, and left in the lead-in it put the first syllable that late (short_kinds_bench's
    // p-fast-combo, tuning: 走, GG, 在嗎, 集合推塔 50-90 ms; bench/README.md, session 32). The frames
    // just before the rise that break the shape are the voice's.
    if (!is_shape_break && end < frames)
        while (end > 0 && !keeps_floor_shape(above(end - 1))) --end;
    if (end < min_run_frames || end == frames) return std::nullopt;
    std::array<std::vector<float>, 3> bands;
    std::size_t flat = 0;
    for (std::size_t t = 0; t < end; ++t) {
        const std::array<float, 3> frame = above(t);
        for (std::size_t b = 0; b < 3; ++b) bands[b].push_back(frame[b]);
        if (keeps_floor_shape(frame)) ++flat;
    }
    std::array<float, 3> medians{};
    for (std::size_t b = 0; b < 3; ++b) medians[b] = percentile_of(bands[b], 0.5);
    if (!keeps_floor_shape(medians) || 2 * flat < end) return std::nullopt;
    return FrameSpan{0, end};
}

}  // namespace talkface::detail

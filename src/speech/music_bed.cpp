#include "speech/music_bed.hpp"

#include "common/order_statistics.hpp"
#include "speech/unvoiced_beat.hpp"

namespace talkface::detail {

namespace {

// Where the running count of held loud frames less changing ones, from `stretch`'s start, peaks;
// its start where no prefix holds more than it changes.
std::size_t voice_entry(const std::vector<float>& share, const std::vector<float>& activity_db,
                        float threshold_db, const FrameSpan& stretch) {
    std::ptrdiff_t vote = 0, best = 0;
    std::size_t entry = stretch.first_frame;
    for (std::size_t t = stretch.first_frame; t < stretch.end_frame; ++t) {
        if (activity_db[t] < threshold_db) continue;
        vote += share[t] < kHeldMusicChangeShare ? 1 : -1;
        if (vote > best) best = vote, entry = t + 1;
    }
    return entry;
}

// The voice that `stretch` ends with after music, and the pauses the music fills after its entry.
std::optional<VoiceUnderMusic> voice_after_music(const FeatureTrack& track, const std::vector<float>& share,
                                                 const std::vector<float>& activity_db, float threshold_db,
                                                 const FrameSpan& stretch, std::size_t min_pause_frames) {
    const std::size_t entry = voice_entry(share, activity_db, threshold_db, stretch);
    const std::size_t end = stretch.end_frame;
    if (entry == stretch.first_frame || end < entry + kVoiceUnderMusicMinFrames ||
        loud_change_share(track, share, activity_db, threshold_db, entry, end) < kNoiseChangeShare ||
        loud_voiced_share(track, activity_db, threshold_db, entry, end) < kVoiceVoicedShare)
        return std::nullopt;
    std::vector<float> music_db;
    for (std::size_t t = stretch.first_frame; t < entry; ++t)
        if (activity_db[t] >= threshold_db) music_db.push_back(activity_db[t]);
    const float music_level_db = lower_median(std::move(music_db));
    const auto is_music = [&](std::size_t t) {
        return share[t] < kHeldMusicChangeShare && activity_db[t] <= music_level_db;
    };
    VoiceUnderMusic bed;
    bed.entry = entry;
    bed.stretch = stretch;
    for (std::size_t t = entry; t < end;) {
        if (!is_music(t)) {
            ++t;
            continue;
        }
        std::size_t run_end = t;
        while (run_end < end && is_music(run_end)) ++run_end;
        if (run_end - t >= min_pause_frames) bed.pauses.push_back({t, run_end});
        t = run_end;
    }
    return bed;
}

}  // namespace

std::optional<VoiceUnderMusic> find_voice_under_music(
    const FeatureTrack& track, const std::vector<float>& share, const std::vector<float>& activity_db,
    float threshold_db, const std::vector<FrameSpan>& pauses, const FrameSpan& speech, const EdgeMusic& edge,
    std::size_t min_pause_frames) {
    const std::size_t leading = edge.leading;
    if (leading > 0) {
        auto bed = voice_after_music(track, share, activity_db, threshold_db,
                                     stretch_before(pauses, speech, leading - 1), min_pause_frames);
        if (bed) {
            bed->leading = leading - 1;
            return bed;
        }
    }
    if (leading >= edge.trailing) return std::nullopt;
    const FrameSpan stretch = stretch_before(pauses, speech, leading);
    auto bed = voice_after_music(track, share, activity_db, threshold_db, stretch, min_pause_frames);
    const std::size_t voice_end =
        edge.trailing < pauses.size() ? pauses[edge.trailing].first_frame : speech.end_frame;
    if (!bed || bed->entry < speech.first_frame + kEdgeMusicMinFrames ||
        !is_music_beside_voice(
            loud_change_share(track, share, activity_db, threshold_db, stretch.first_frame, bed->entry),
            loud_change_share(track, share, activity_db, threshold_db, bed->entry, voice_end)))
        return std::nullopt;
    bed->leading = leading;
    return bed;
}

}  // namespace talkface::detail

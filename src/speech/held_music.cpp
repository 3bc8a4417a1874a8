#include "speech/held_music.hpp"

#include <algorithm>
#include <cmath>

#include "common/order_statistics.hpp"
#include "speech/unvoiced_beat.hpp"

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
        if (is_loud_sounding_frame(track, activity_db, threshold_db, t)) loud.push_back(share[t]);
    return loud.empty() ? 0.0f : lower_median(std::move(loud));
}

FrameSpan stretch_before(const std::vector<FrameSpan>& pauses, const FrameSpan& speech, std::size_t k) {
    return {k > 0 ? pauses[k - 1].end_frame : speech.first_frame,
            k < pauses.size() ? pauses[k].first_frame : speech.end_frame};
}

namespace {

// The count of pauses that music before the voice takes in: up to the last pause before which
// every stretch holds its notes (`is_held`) and which lies kEdgeMusicMinFrames or more into the
// speech; 0 where none does.
std::size_t pauses_in_opening_music(const std::vector<FrameSpan>& pauses, const FrameSpan& speech,
                                    const std::function<bool(const FrameSpan&)>& is_held) {
    std::size_t leading = 0;
    for (std::size_t k = 0; k < pauses.size() && is_held(stretch_before(pauses, speech, k)); ++k)
        if (pauses[k].first_frame >= speech.first_frame + kEdgeMusicMinFrames) leading = k + 1;
    return leading;
}

// The first pause that music after the voice takes in, as pauses_in_opening_music from the end,
// never among the first `leading`; pauses.size() where there is none.
std::size_t first_pause_of_closing_music(const std::vector<FrameSpan>& pauses, const FrameSpan& speech,
                                         std::size_t leading,
                                         const std::function<bool(const FrameSpan&)>& is_held) {
    std::size_t trailing = pauses.size();
    for (std::size_t k = pauses.size(); k > leading && is_held(stretch_before(pauses, speech, k)); --k)
        if (speech.end_frame >= pauses[k - 1].end_frame + kEdgeMusicMinFrames) trailing = k - 1;
    return trailing;
}

// `held` with each edge's music kept only where it is music beside the voice left between the two
// (`is_beside(music, voice)`).
EdgeMusic music_beside_voice(const std::vector<FrameSpan>& pauses, const FrameSpan& speech, EdgeMusic held,
                             const std::function<bool(const FrameSpan&, const FrameSpan&)>& is_beside) {
    const std::size_t none = pauses.size();
    if (held.leading == 0 && held.trailing == none) return held;
    const FrameSpan voice{held.leading > 0 ? pauses[held.leading - 1].end_frame : speech.first_frame,
                          held.trailing < none ? pauses[held.trailing].first_frame : speech.end_frame};
    if (held.leading > 0 && !is_beside({speech.first_frame, pauses[held.leading - 1].first_frame}, voice))
        held.leading = 0;
    if (held.trailing < none && !is_beside({pauses[held.trailing].end_frame, speech.end_frame}, voice))
        held.trailing = none;
    return held;
}

}  // namespace

EdgeMusic find_edge_music(const FeatureTrack& track, const std::vector<float>& share,
                          const std::vector<float>& activity_db, float threshold_db,
                          const std::vector<FrameSpan>& pauses, const FrameSpan& speech,
                          const std::function<bool(const FrameSpan&)>& is_not_speech) {
    const auto change_of = [&](const FrameSpan& stretch) {
        return loud_change_share(track, share, activity_db, threshold_db, stretch.first_frame,
                                 stretch.end_frame);
    };
    // A kit's hits change as a voice does, but are not voiced (unvoiced_beat.hpp).
    const auto voicing_of = [&](const FrameSpan& stretch) {
        return loud_voiced_share(track, activity_db, threshold_db, stretch.first_frame, stretch.end_frame);
    };
    const auto is_held = [&](const FrameSpan& stretch) {
        return is_not_speech(stretch) || change_of(stretch) < kHeldMusicChangeShare ||
               voicing_of(stretch) < kBeatVoicedShare;
    };
    EdgeMusic held;
    held.leading = pauses_in_opening_music(pauses, speech, is_held);
    held.trailing = first_pause_of_closing_music(pauses, speech, held.leading, is_held);
    return music_beside_voice(pauses, speech, held, [&](const FrameSpan& music, const FrameSpan& voice) {
        return is_music_beside_voice(change_of(music), change_of(voice)) ||
               is_beat_beside_voice(voicing_of(music), voicing_of(voice));
    });
}

}  // namespace talkface::detail

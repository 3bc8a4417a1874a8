// Music that holds its notes through the pauses (issue 13): chords, a pad, a piano's decay under
// a voice at 15-20 dB are as loud, band by band, as the quieter half of the speech, so loudness
// alone takes the pauses between sentences for speech, and the cutter misses sentence ends. What
// tells them apart is change (changing_spectrum.hpp): a voice changes most of its power every few
// tens of milliseconds, a held note hardly any. Noise changes half of its power whatever its
// colour, so where the quiet of a recording changes as noise does, nothing here applies, and a
// recording under steady noise is cut as before.
#ifndef TALKFACE_SPEECH_HELD_MUSIC_HPP
#define TALKFACE_SPEECH_HELD_MUSIC_HPP

#include <functional>
#include <vector>

#include "speech/frame_features.hpp"
#include "speech/sentence_cutter.hpp"

namespace talkface::detail {

// A frame counts as held music when, over the frames within kHeldMusicHalfWindow of it, less
// than kHeldMusicChangeShare of the band's power changes, and it is quieter than the median speech
// frame (a vowel held on one pitch is among the loudest frames of its sentence; the music under a
// voice at 15-20 dB is not). 150 ms either way: longer than a steady vowel, shorter than the
// 0.4 s and more that separate two sentences.
constexpr std::size_t kHeldMusicHalfWindow = 15;
constexpr double kHeldMusicChangeShare = 0.35;
// Noise changes 0.5 of its power (changing_spectrum.hpp); quiet that changes less than this is
// held sound: music, or a hum.
constexpr double kNoiseChangeShare = 0.45;

// Per frame of `track`: the share of the change band's power that changes over the frames within
// kHeldMusicHalfWindow of it (a voice most of it, noise half, held notes little).
std::vector<float> changing_shares(const FeatureTrack& track);

// Whether frame t is loud (its activity at or above `threshold_db`) with some sound in the change
// band: the frames whose change and voicing are judged (digital silence holds none to judge).
inline bool is_loud_sounding_frame(const FeatureTrack& track, const std::vector<float>& activity_db,
                                   float threshold_db, std::size_t t) {
    return activity_db[t] >= threshold_db && track.at(t, kChangeBandDb) > kDigitalSilenceDb;
}

// The lower median of `share` (changing_shares) over the frames in [first, end) that are loud and
// sounding (is_loud_sounding_frame); 0 where no frame is.
float loud_change_share(const FeatureTrack& track, const std::vector<float>& share,
                        const std::vector<float>& activity_db, float threshold_db, std::size_t first,
                        std::size_t end);

// Whether loud frames whose median share (loud_change_share) is `music_share` are music set apart
// from a voice whose own is `voice_share`: the music holds its notes (under kHeldMusicChangeShare),
// the voice changes as a voice does (kNoiseChangeShare or more), and the music changes less than
// kMusicToVoiceChange of what the voice does: espeak-ng's slow speech holds its vowels, and a first
// version without this rule and kEdgeMusicMinFrames took one of its last sentences for music
// (bench/README.md, session 26), where a piano, a pad or a sung line alone reads 0.07-0.35 and a
// person's speech 0.61-0.95 (session 25).
constexpr double kMusicToVoiceChange = 0.5;
inline bool is_music_beside_voice(double music_share, double voice_share) {
    return music_share < kHeldMusicChangeShare && voice_share >= kNoiseChangeShare &&
           music_share < kMusicToVoiceChange * voice_share;
}

// Music set apart from a recording's speech lasts 3 s or more (the shortest jingle): a slow voice
// holding a vowel, or a last word with the music ringing on after it, is shorter.
constexpr std::size_t kEdgeMusicMinFrames = 300;

// The stretch of `speech` between `pauses` (in order, inside it) before pause k: from the end of
// pause k - 1 (the speech's start for k = 0) to pause k (the speech's end for k = pauses.size()).
FrameSpan stretch_before(const std::vector<FrameSpan>& pauses, const FrameSpan& speech, std::size_t k);

// Music before the voice comes in or after it ends (a podcast's jingle, a video's intro or outro:
// issue 13), as the pauses that set it apart: the speech left between them lies after pause
// leading - 1 (none where leading is 0) and before pause trailing (none where it is the pauses'
// count).
struct EdgeMusic {
    std::size_t leading = 0;
    std::size_t trailing = 0;
};

// The edge music of a recording whose speech (loud frames) spans `speech` and is cut by `pauses`
// (in order, inside it): the stretches between pauses at an edge that each hold their notes (their
// loud_change_share under kHeldMusicChangeShare), are a kit's unvoiced hits (loud_voiced_share under
// kBeatVoicedShare, unvoiced_beat.hpp) or are no speech already (`is_not_speech`: a quiet note, a
// click), kEdgeMusicMinFrames or more of them together, where they are music or a beat beside the
// speech left between them (is_music_beside_voice, is_beat_beside_voice). {0, pauses.size()} where
// there is none.
EdgeMusic find_edge_music(const FeatureTrack& track, const std::vector<float>& share,
                          const std::vector<float>& activity_db, float threshold_db,
                          const std::vector<FrameSpan>& pauses, const FrameSpan& speech,
                          const std::function<bool(const FrameSpan&)>& is_not_speech);

// Per frame of `track`: whether it is held music, given its changing shares (changing_shares), the
// loudness profile's smoothed activity and its speech threshold. All false when the recording's
// quiet frames (below the threshold, with any sound in the band) change as noise does, or when it
// has none.
std::vector<bool> held_music_frames(const FeatureTrack& track, const std::vector<float>& share,
                                    const std::vector<float>& activity_db, float threshold_db);

}  // namespace talkface::detail

#endif

// Music that plays on under a voice's first words (a podcast's bed, issue 13): a pad or a piano
// before the voice that goes on, fading, under its first seconds. No pause parts the music from
// the voice, so the stretch between pauses that holds the music's end holds the first words too,
// and the music fills the pauses between the first sentences, as loud as the voice. Held notes
// still tell the music (held_music.hpp): the voice comes in where they give way to change.
#ifndef TALKFACE_SPEECH_MUSIC_BED_HPP
#define TALKFACE_SPEECH_MUSIC_BED_HPP

#include <cstddef>
#include <optional>
#include <vector>

#include "speech/frame_features.hpp"
#include "speech/held_music.hpp"
#include "speech/sentence_cutter.hpp"

namespace talkface::detail {

struct VoiceUnderMusic {
    std::size_t entry = 0;          // the frame where the voice comes in
    std::size_t leading = 0;        // the pauses before it, which the music takes in
    std::vector<FrameSpan> pauses;  // the pauses after it that the music fills (before pause `leading`)
    FrameSpan stretch;  // the stretch between pauses that holds the music, then the voice under it
};

// What follows the voice's entry is a voice where it lasts kVoiceUnderMusicMinFrames or more (a
// sentence's first words: on bench/make_intros.py's jingles the last 0.5 s, a struck note and a
// drum's hit fading out together, read as a voice), changes as a voice does (kNoiseChangeShare or
// more) and is voiced (unvoiced_beat.hpp's kVoiceVoicedShare or more).
constexpr std::size_t kVoiceUnderMusicMinFrames = 100;

// The voice under a bed in the recording whose speech (loud frames) spans `speech`, cut by `pauses`
// (in order, inside it), with the edge music `edge` (find_edge_music, on the same pauses and span):
// in the last stretch the opening music takes in, or else in the first stretch left where music of
// kEdgeMusicMinFrames or more from the speech's start is music beside the voice after it
// (is_music_beside_voice; a short intro, under a longer voice, kept that stretch from being taken
// in). The voice comes in where the running count of the stretch's held loud frames (at or above
// `threshold_db` of `activity_db`; a changing share under kHeldMusicChangeShare) less its changing
// ones peaks; its pauses are the runs of `min_pause_frames` or more after the entry that hold their
// notes and are no louder than the music alone was (the lower median of its loud frames): the bed
// only fades under the voice, and the voice's own frames change. Nothing where no stretch ends
// with a voice after music.
std::optional<VoiceUnderMusic> find_voice_under_music(
    const FeatureTrack& track, const std::vector<float>& share, const std::vector<float>& activity_db,
    float threshold_db, const std::vector<FrameSpan>& pauses, const FrameSpan& speech, const EdgeMusic& edge,
    std::size_t min_pause_frames);

}  // namespace talkface::detail

#endif

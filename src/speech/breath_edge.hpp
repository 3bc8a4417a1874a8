// A breath before a line or after it (issues 12 and 13): a user's short line recorded on a headset
// starts with the in-breath and may end with the out-breath. A breath is as loud as the quieter
// speech, and the band-ratio voicing (unvoiced_beat.hpp) reads the short kinds' breaths 0.21-0.68
// voiced, a voice 0.74-1.0 (bench/README.md, session 28): its noise lies over 400-3000 Hz, in the
// low band as much as in the high. What it lacks is power where a voice's fundamental and second
// harmonic lie, under kFundamentalTopHz. The cutter has no spectrum, but each frame's cepstra are
// the DCT of its mel bands' log levels, and the difference between two groups of bands is a fixed
// sum over the cepstra (no new feature, twelve multiply-adds a frame).
#ifndef TALKFACE_SPEECH_BREATH_EDGE_HPP
#define TALKFACE_SPEECH_BREATH_EDGE_HPP

#include <cstddef>
#include <optional>
#include <vector>

#include "speech/frame_features.hpp"
#include "speech/sentence_cutter.hpp"

namespace talkface::detail {

// The mean level of frame t's mel bands centred under kFundamentalTopHz (100-360 Hz) less that of
// the rest of its low band (those centred under kLowBandHighHz, 265-990 Hz), dB, as its cepstra
// smooth them.
float fundamental_rise_db(const FeatureTrack& track, std::size_t t);

// A frame whose fundamental_rise_db is this or more has a fundamental. On the short kinds' four
// voices (bench/short_kinds_bench.py, the breath kind's lines) every loud frame of a line lies
// above it (their 1st percentile -10 dB), and 88% of a breath's under it (its median -22 dB: the
// hiss under the breath's band).
constexpr float kFundamentalBelowLowBandDb = -15.0f;

// The share of the loud, sounding frames in [first, end) (held_music.hpp's is_loud_sounding_frame,
// as loud_voiced_share's) that have a fundamental. 0 where no frame is loud.
double loud_fundamental_share(const FeatureTrack& track, const std::vector<float>& activity_db,
                              float threshold_db, std::size_t first, std::size_t end);

// A frame whose kLineShare is this or more holds a harmonic: a voiced frame's power gathers in its
// harmonics' lines, a breath's noise spreads over its band, and voiced frames keep their lines
// through a telephone band. The short kinds' breaths (bench/short_kinds_bench.py: breath and
// breath-after on a headset, p-breath through five narrowband codecs) read a median 0.15 (0.17
// through the codecs) and 99% under 0.27 (0.37); at this bar each line's loud frames hold one 0.73
// or more of the time (0.65 through the phone kinds' codecs), each breath's at most 0.14 (0.27)
// (bench/README.md, session 30). A breath's noise in a narrower band (400-1500 Hz) shows lines.
constexpr float kHarmonicLineShare = 0.25f;

// The share of the loud, sounding frames in [first, end) (as loud_fundamental_share's) that hold a
// harmonic (kHarmonicLineShare). 0 where no frame is loud.
double loud_harmonic_share(const FeatureTrack& track, const std::vector<float>& activity_db,
                           float threshold_db, std::size_t first, std::size_t end);

// Loud frames holding a harmonic (kHarmonicLineShare) this many in a row are a vowel's, whatever
// share of the stretch they make: a breath's noise shows a line at most 4 frames in a row through
// the narrowband codecs (bench/ p-breath), 2 on a headset; a phone's gain control lifts the noise
// before the first word into the same stretch as the word (bench/ p-fast-combo tuning-010: 36
// frames of noise, then 16 of 天's harmonics).
constexpr std::size_t kVowelHarmonicFrames = 6;

// A stretch shorter than this is not judged by its fundamental. A breath's noise lasts 0.25 s or
// more: the short kinds' shortest reads 13 frames loud. Music's onset at a file's start and its
// last notes' tail read 7-8 frames in music-kinds' m-sung (tuning-004, tuning-006), set apart by a
// pause and holding no syllable; taken off, they moved the sentences' spans and their syllables by
// 10-80 ms (bench/README.md, session 29).
constexpr std::size_t kFewestBreathFrames = 10;

// Whether the sound of `stretch` is a breath beside the voice of `voice` (`loudness`'s activity and
// threshold tell the loud frames): where it is kFewestBreathFrames long or more, it has no
// fundamental and the voice has one where the recording keeps a fundamental at all, and elsewhere
// it holds no harmonic and the voice does (loud_harmonic_share) and it holds no vowel
// (kVowelHarmonicFrames); or, with `by_voicing_too` (before the first words: after the last,
// music's quieter tail reads unvoiced too), it is never voiced by the band ratio
// (loud_voiced_share) and the voice is. The bars are a beat's beside a voice
// (is_beat_beside_voice). Through a telephone band a voice's fundamental is gone, and a syllable
// whose first formant lies low (espeak-ng's 我 in bench/ telephone tuning-011) reads as having none
// beside the rest of the line, which keeps a little; its harmonics stay. After the last words the
// harmonics drop the out-breath through a telephone band and on espeak-ng's voice (bench/ short
// kinds p-breath, breath-after), but not a gain control's lifted noise, in the floors' band shape
// up to the recording's end (or from its start): no speech either, it is left to the lift
// (lifted_noise.hpp); dropped, it moved p-fast-combo's lines whose first syllables lie in the
// lifted noise before them, and refused one (held-out 等我上個廁所: the text fit 0.11 per frame over
// the swapped halves, 0.12 needed; bench/README.md, session 31). An out-breath in the floors'
// shape, with a pause's hiss after it, is dropped (session 32).
bool is_breath_beside_voice(const FeatureTrack& track, const LoudnessProfile& loudness,
                            const FrameSpan& stretch, const FrameSpan& voice, bool by_voicing_too);

// Quiet frames (under `loudness`'s threshold) this many or more set a breath apart from the
// words after it, short of a pause. A stop's closure inside a word (an s before it, English st,
// sp, sk: 30-70 ms) reads at most 5 quiet frames once smoothed; the breaths of the short kinds,
// ending 50-200 ms before the line, 8 or more.
constexpr std::size_t kBreathGapFrames = 6;

// The quiet after the sound at the start of [first, end): its first quiet frames, where they are
// kBreathGapFrames or more and sound follows them; nullopt where there are none. The sound before
// them may be a breath or a click set apart from the words, closer to them than a pause.
std::optional<FrameSpan> find_gap_after_first_sound(const LoudnessProfile& loudness, std::size_t first,
                                                    std::size_t end);

// The breath at the start of [first, end): its sound up to find_gap_after_first_sound's quiet, where
// it is a breath beside the sound after it (is_breath_beside_voice, by the fundamental only: a
// sibilant reads unvoiced by the band ratio); nullopt where there is none. The words start at the
// first speech frame after it.
std::optional<FrameSpan> find_close_breath(const FeatureTrack& track, const LoudnessProfile& loudness,
                                           std::size_t first, std::size_t end);

}  // namespace talkface::detail

#endif

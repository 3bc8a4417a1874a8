// The part of the spectrum that changes: a voice's harmonics glide with its pitch and its formants
// move from sound to sound, while music holds its partials on fixed frequencies for a note's whole
// length (a chord, a pad, a piano's decay). Per frame, in the band where a voice's formants and
// harmonics lie: its power, and the power by which each bin exceeds kChangeRatio times what the
// same bin holds both kChangeLagFrames before and after (the least of the two). Held notes and
// their decays drop out, a syllable's onsets, glides and consonants stay; noise (random in each
// bin) keeps half its power, whatever its colour. held_music.hpp reads it (bench/README.md,
// session 11, "Music that holds its notes").
#ifndef TALKFACE_SPEECH_CHANGING_SPECTRUM_HPP
#define TALKFACE_SPEECH_CHANGING_SPECTRUM_HPP

#include <array>
#include <cstddef>

#include "speech/frame_features.hpp"
#include "speech/power_spectrum.hpp"

namespace talkface::detail {

// 30 ms: a piano's or a snare's decay loses less than kChangeRatio over it, a voice's harmonic at
// 1 kHz moves a bin when the pitch moves 3% (a tone's contour does that in 30 ms).
constexpr std::size_t kChangeLagFrames = 3;
constexpr float kChangeRatio = 2.0f;  // 3 dB
// Above a bass and a kick drum (steady low sines that would read as held under any voice), below
// the frication that noise and cymbals fill.
constexpr double kChangeBandLowHz = 300.0;
constexpr double kChangeBandHighHz = 5000.0;

// Fills the kChangeBandDb and kChangingDb columns of a track's frames, which arrive one at a time: each frame's
// columns are written kChangeLagFrames frames later, when the power spectrum after it is known.
class ChangingSpectrum {
public:
    explicit ChangingSpectrum(FeatureTrack& track) : track_(track) {}

    // The power spectrum of the frame just appended to the track.
    void push(const float* power);
    // Writes the last frames' columns, comparing them with the frames before only.
    void finish();

private:
    static constexpr std::size_t kKept = 2 * kChangeLagFrames + 1;
    void write(std::size_t frame, const float* before, const float* after);

    FeatureTrack& track_;
    std::array<std::array<float, PowerSpectrum::kBins>, kKept> kept_{};
    std::size_t pushed_ = 0;
    std::size_t written_ = 0;
};

}  // namespace talkface::detail

#endif

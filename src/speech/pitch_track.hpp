// A voice's pitch frame by frame, for the tone of a syllable (lenient alignment, issue 13: a changed
// word whose sounds the broad classes hear alike, 场大 said where the text has 沙发, differs in its
// tones). Measured only where asked (analyze_audio's with_pitch): the normalised cross-correlation
// of the last 40 ms, taken down to 4 kHz, at lags of 80-400 Hz.
#ifndef TALKFACE_SPEECH_PITCH_TRACK_HPP
#define TALKFACE_SPEECH_PITCH_TRACK_HPP

#include <array>
#include <cstddef>

namespace talkface::detail {

struct PitchFrame {
    float hz = 0.0f;       // the period's frequency; 0 where no period was found
    float voicing = 0.0f;  // the normalised cross-correlation at that period, 0..1
};

class PitchTracker {
public:
    // One frame's `count` new samples at 16 kHz (its hop; the first frame's whole window), the
    // latest ones last: the pitch of the 40 ms up to its end.
    PitchFrame push(const float* samples, std::size_t count);

private:
    static constexpr std::size_t kDecimation = 4;  // 16 kHz to 4 kHz
    static constexpr std::size_t kHistory = 160;   // 40 ms at 4 kHz
    std::array<float, kHistory> history_{};        // oldest first
    std::array<float, kDecimation> partial_{};     // samples of a decimated one not yet complete
    std::size_t partial_count_ = 0;
};

}  // namespace talkface::detail

#endif

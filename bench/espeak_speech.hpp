// Mandarin speech from espeak-ng with the time each syllable starts, by SPEC "Alignment".
#ifndef TALKFACE_BENCH_ESPEAK_SPEECH_HPP
#define TALKFACE_BENCH_ESPEAK_SPEECH_HPP

#include <cstddef>
#include <string>
#include <vector>

#include <talkface/timeline.hpp>

namespace talkface_bench {

/// A syllable's ground truth inside one spoken sentence, in samples from the sentence's first sound.
struct SpokenSyllable {
    std::size_t start = 0;   ///< where its initial starts (closure start for a stop after speech)
    std::size_t end = 0;     ///< the next syllable's start, or the last sound before a pause
    bool after_pause = false;  ///< starts after silence: the start is the first sound (a stop's burst)
};

/// One sentence as espeak-ng spoke it, trimmed to its first and last sound.
struct SpokenSentence {
    std::vector<float> samples;  ///< mono, -1..1, at EspeakVoice::sample_rate_hz()
    std::vector<SpokenSyllable> syllables;
};

/// The cmn-latn-pinyin voice of espeak-ng, synchronous. One per process: espeak-ng is global state.
class EspeakVoice {
public:
    /// \throws std::runtime_error if espeak-ng or its Mandarin voice cannot be loaded.
    EspeakVoice();
    ~EspeakVoice();
    EspeakVoice(const EspeakVoice&) = delete;
    EspeakVoice& operator=(const EspeakVoice&) = delete;

    int sample_rate_hz() const { return sample_rate_hz_; }

    /// Speaks `syllables` (numbered pinyin, one espeak-ng word each; a comma after each
    /// pause_after) at `rate_wpm` words a minute and `pitch` 0..100.
    /// \throws std::runtime_error naming `where` if espeak-ng did not speak one word per syllable.
    SpokenSentence speak(const std::vector<talkface::Syllable>& syllables, int rate_wpm, int pitch,
                         const std::string& where) const;

private:
    int sample_rate_hz_ = 0;
};

}  // namespace talkface_bench

#endif

// Any bytes as 16-bit audio at 8 kHz for the transcript of tests/data/speech/one_sentence (whose
// clip the seed corpus holds): either talkface::Error, or a timeline in order inside the audio.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <vector>

#include "talkface/errors.hpp"
#include "talkface/speech_aligner.hpp"
#include "talkface/transcript.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    static const talkface::Timeline transcript = talkface::read_transcript("小朋友們在公園裡放風箏。");
    constexpr int kRateHz = 8000;
    std::vector<float> samples(size / 2);
    for (std::size_t i = 0; i < samples.size(); ++i)
        samples[i] = static_cast<float>(static_cast<std::int16_t>(data[2 * i] | (data[2 * i + 1] << 8))) / 32768.0f;
    talkface::Timeline timeline;
    try {
        timeline = talkface::SpeechAligner().align(
            talkface::AudioView{samples.data(), samples.size(), 1, kRateHz}, transcript);
    } catch (const talkface::Error&) {
        return 0;
    }
    const double duration_s = static_cast<double>(samples.size()) / kRateHz;
    double previous_end_s = 0.0;
    for (const auto& syllable : timeline.syllables) {
        if (!(syllable.start_s >= previous_end_s - 1e-9 && syllable.end_s >= syllable.start_s &&
              syllable.end_s <= duration_s + 1e-9 && syllable.confidence >= 0.0 && syllable.confidence <= 1.0))
            std::abort();
        previous_end_s = syllable.end_s;
    }
    return 0;
}

// A breath before a short line (issues 12 and 13: a line recorded on a headset): its noise is as
// loud as the quieter speech and a pause shorter than a second sets it apart, so it was read as
// the first syllable's start. It is never voiced, and every syllable has a voiced vowel: the
// speech starts after it, and the first syllable's search does not reach into it.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdint>
#include <vector>

#include "audio/audio_source.hpp"
#include "audio/decoded_audio.hpp"
#include "common/speech_clips.hpp"
#include "talkface/speech_aligner.hpp"
#include "talkface/transcript.hpp"

using namespace talkface;

namespace {

constexpr double kPi = 3.14159265358979323846;

// An in-breath of `seconds` at `rate_hz`: noise over 500-4000 Hz (many sines of random phase), its
// loudness rising and falling (a Hann window), peak `amplitude`.
std::vector<float> breath(double seconds, int rate_hz, double amplitude) {
    std::uint32_t state = 12345u;
    const auto uniform = [&] {
        return static_cast<double>((state = state * 1664525u + 1013904223u) >> 8) / 16777216.0;
    };
    const auto count = static_cast<std::size_t>(seconds * rate_hz);
    std::vector<double> sound(count, 0.0);
    for (int k = 0; k < 200; ++k) {
        const double hz = 500.0 + 3500.0 * uniform(), phase = 2.0 * kPi * uniform();
        for (std::size_t i = 0; i < count; ++i)
            sound[i] += std::sin(2.0 * kPi * hz * static_cast<double>(i) / rate_hz + phase);
    }
    double peak = 0.0;
    for (const double v : sound) peak = std::max(peak, std::abs(v));
    std::vector<float> out(count);
    for (std::size_t i = 0; i < count; ++i) {
        const double window =
            0.5 - 0.5 * std::cos(2.0 * kPi * static_cast<double>(i) / static_cast<double>(count - 1));
        out[i] = static_cast<float>(amplitude * window * sound[i] / peak);
    }
    return out;
}

}  // namespace

TEST_SUITE("speech") {
    TEST_CASE("a breath before a short line is not its first syllable") {
        auto source = detail::open_audio_file(test::clip_path("bare_line.flac"));
        const int rate_hz = source->sample_rate_hz();
        const std::vector<float> line = test::read_all(*source);
        float line_peak = 0.0f;
        for (const float v : line) line_peak = std::max(line_peak, std::abs(v));
        // A headset's hiss, a breath half as loud as the line's peak, 0.1 s of hiss, the line (好).
        std::vector<float> samples(static_cast<std::size_t>(0.05 * rate_hz), 0.0f);
        const std::vector<float> inhale = breath(0.35, rate_hz, 0.5 * line_peak);
        samples.insert(samples.end(), inhale.begin(), inhale.end());
        samples.resize(samples.size() + static_cast<std::size_t>(0.1 * rate_hz), 0.0f);
        const double line_start_s = static_cast<double>(samples.size()) / rate_hz;
        samples.insert(samples.end(), line.begin(), line.end());
        samples.resize(samples.size() + static_cast<std::size_t>(0.3 * rate_hz), 0.0f);
        test::add_headset_hiss(samples);
        const Timeline aligned = SpeechAligner().align(AudioView{samples.data(), samples.size(), 1, rate_hz},
                                                       load_transcript(test::clip_path("bare_line.txt")));
        REQUIRE(aligned.syllables.size() == 1);
        CHECK(aligned.syllables[0].start_s >= line_start_s - 0.03);
    }
}

// A beep before the speech (issue 13, bench/README.md sweep session 17): a phone's or a recorder's
// two short tones are no syllable's, for espeak-ng's voice and a person's; a steady tone's frames
// are found, a voice's are not.
#include <doctest/doctest.h>

#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

#include "common/clip_audio.hpp"
#include "speech/frame_features.hpp"
#include "speech/steady_tone.hpp"

using namespace talkface;

namespace {

constexpr double kPi = 3.14159265358979323846;

// `clip` after `pad_s` of digital silence, with a notification beep from `beep_s` on: two 80 ms
// tones of 880 Hz at -12 dBFS, 60 ms apart (bench/sweep_bench.py's).
test::ClipSamples with_beep(const test::ClipSamples& clip, double pad_s, double beep_s) {
    test::ClipSamples out{std::vector<float>(static_cast<std::size_t>(pad_s * clip.rate_hz), 0.0f), clip.rate_hz};
    out.values.insert(out.values.end(), clip.values.begin(), clip.values.end());
    for (const double start_s : {beep_s, beep_s + 0.14}) {
        if (start_s < 0.0) continue;  // no beep
        const auto first = static_cast<std::size_t>(start_s * clip.rate_hz);
        for (std::size_t i = 0; i < static_cast<std::size_t>(0.08 * clip.rate_hz); ++i)
            out.values[first + i] += static_cast<float>(0.25 * std::sin(2 * kPi * 880.0 * static_cast<double>(i) / clip.rate_hz));
    }
    return out;
}

std::size_t count_true(const std::vector<bool>& flags, std::size_t first, std::size_t end) {
    std::size_t count = 0;
    for (std::size_t t = first; t < end && t < flags.size(); ++t) count += flags[t] ? 1 : 0;
    return count;
}

}  // namespace

TEST_SUITE("speech") {
    TEST_CASE("a beep's frames are a steady tone, a voice held on one pitch and a chord are not") {
        const int rate = detail::kAnalysisRateHz;
        // 0.1 s of silence, the beep's two tones at 0.1-0.18 and 0.24-0.32 s, silence to 0.5 s.
        const test::ClipSamples beep = with_beep({std::vector<float>(static_cast<std::size_t>(0.4 * rate), 0.0f), rate}, 0.1, 0.1);
        const std::vector<bool> tone = detail::steady_tone_frames(test::features_of(beep.values, rate));
        CHECK(count_true(tone, 11, 17) == 6);   // inside each tone
        CHECK(count_true(tone, 25, 31) == 6);
        CHECK(count_true(tone, 0, 8) == 0);     // the silence before, between (20-22) and after
        CHECK(count_true(tone, 20, 22) == 0);
        CHECK(count_true(tone, 36, 50) == 0);
        // A voice held on one pitch, its fundamental boosted by a low first formant (一 yi1 at 250 Hz,
        // harmonics to 4 kHz falling 18 dB an octave: 0.98 of the power on the fundamental, as
        // bench/'s w-clean holds it for 6 frames), and a chord of three sines: neither is a tone.
        std::vector<float> voice(static_cast<std::size_t>(rate), 0.0f), chord(static_cast<std::size_t>(rate), 0.0f);
        for (std::size_t i = 0; i < voice.size(); ++i) {
            const double t = static_cast<double>(i) / rate;
            double value = 0.0;
            for (int k = 1; 250.0 * k < 4000.0; ++k) value += std::sin(2 * kPi * 250.0 * k * t) / (k * k * k);
            voice[i] = static_cast<float>(0.2 * value);
            for (const double hz : {440.0, 554.4, 659.3}) chord[i] += static_cast<float>(0.1 * std::sin(2 * kPi * hz * t));
        }
        CHECK(count_true(detail::steady_tone_frames(test::features_of(voice, rate)), 0, 100) == 0);
        CHECK(count_true(detail::steady_tone_frames(test::features_of(chord, rate)), 0, 100) == 0);
    }

    TEST_CASE("a beep just before the speech is no syllable's: espeak-ng's voice against the truth") {
        // two_sentences.wav's speech starts at 0.3 s: the beep from 0 s ends 80 ms before it, and
        // padded by 0.5 s, from 0.2 s it ends 0.38 s before it, set apart by a pause. On 7a4d98a
        // the first syllables lay on the beep (0, 0.23 s; 0.18, 0.29 s).
        const test::ClipSamples clip = test::clip_samples("two_sentences.wav");
        const std::vector<double> truth = test::true_starts("two_sentences");
        for (const auto& [pad_s, beep_s] : {std::pair{0.0, 0.0}, std::pair{0.5, 0.2}}) {
            CAPTURE(pad_s);
            const std::vector<double> starts = test::aligned_starts(with_beep(clip, pad_s, beep_s), "two_sentences.txt");
            REQUIRE(starts.size() == truth.size());
            for (std::size_t i = 0; i < 3; ++i) CHECK(std::abs(starts[i] - (truth[i] + pad_s)) < 0.05);
        }
    }

    TEST_CASE("a beep just before the speech is no syllable's: a person's short line as it aligns without it") {
        // short_line.flac (gcin-voice speaker 3, 你好) aligns at 0.29 s; on 7a4d98a the beep took
        // its first syllable (0.01 s; padded, 0.18 s).
        const test::ClipSamples clip = test::clip_samples("short_line.flac");
        for (const auto& [pad_s, beep_s] : {std::pair{0.0, 0.0}, std::pair{0.5, 0.2}}) {
            CAPTURE(pad_s);
            const std::vector<double> plain = test::aligned_starts(with_beep(clip, pad_s, -1.0), "short_line.txt");
            const std::vector<double> beeped = test::aligned_starts(with_beep(clip, pad_s, beep_s), "short_line.txt");
            REQUIRE(beeped.size() == plain.size());
            for (std::size_t i = 0; i < plain.size(); ++i) CHECK(std::abs(beeped[i] - plain[i]) < 0.03);
        }
    }
}

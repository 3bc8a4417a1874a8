// Noise a phone's gain control lifts before a line (issues 12 and 13): the gain is high from the
// recording's start until the first loud syllable pulls it down, so the hiss before the line stands
// far over the hiss after it, the recording's floor, and the line's first syllables were spread over
// it from the recording's start. The lifted hiss keeps the floor's shape; the line starts where a
// voice's uneven bands do.
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

TEST_SUITE("speech") {
    TEST_CASE("a line after hiss a gain control lifted starts where the line does") {
        auto source = detail::open_audio_file(test::clip_path("comma_pause.flac"));
        const std::vector<float> clip = test::read_all(*source);
        constexpr int kRateHz = 16000;
        // 0.3 s of white hiss 18 dB over the headset's, then the line (its first 0.25 s of silence
        // left out, 请 at 0.05 s) at a fifth of its level, then 0.3 s of the headset's hiss alone.
        constexpr double kLeadInS = 0.3;
        const float lifted = 1e-3f * std::pow(10.0f, 18.0f / 20.0f);
        std::uint32_t state = 12345u;
        std::vector<float> samples;
        for (int i = 0; i < static_cast<int>(kLeadInS * kRateHz); ++i)
            samples.push_back(
                lifted *
                (static_cast<float>((state = state * 1664525u + 1013904223u) >> 8) / 8388608.0f - 1.0f));
        for (std::size_t i = static_cast<std::size_t>(0.25 * kRateHz); i < clip.size(); ++i)
            samples.push_back(0.2f * clip[i]);
        samples.resize(samples.size() + static_cast<std::size_t>(0.3 * kRateHz), 0.0f);
        test::add_headset_hiss(samples);
        const Timeline aligned = SpeechAligner().align(AudioView{samples.data(), samples.size(), 1, kRateHz},
                                                       load_transcript(test::clip_path("comma_pause.txt")));
        REQUIRE(aligned.syllables.size() == 13);
        CHECK(std::abs(aligned.syllables[0].start_s - (kLeadInS + 0.05)) < 0.05);
        CHECK(std::abs(aligned.syllables[1].start_s - (kLeadInS + 0.32093)) < 0.05);
    }
}

// A short line among quieter voices (issues 12 and 13: a game's line recorded with others talking
// in the room): the other voice fills the recording from its start with no pause before the line,
// so the line's syllable was placed at the recording's start; another voice after it, to the
// recording's end, drew its last syllable out to the end. The line is the loud voice; the quieter
// one before or after it, which never comes near its level, is no syllable's.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "audio/audio_source.hpp"
#include "audio/decoded_audio.hpp"
#include "common/speech_clips.hpp"
#include "talkface/speech_aligner.hpp"
#include "talkface/transcript.hpp"

using namespace talkface;

namespace {

std::vector<float> read_clip(const char* name) {
    auto source = detail::open_audio_file(test::clip_path(name));
    return test::read_all(*source);
}

float peak_of(const std::vector<float>& samples) {
    float peak = 0.0f;
    for (const float v : samples) peak = std::max(peak, std::abs(v));
    return peak;
}

// Where `samples` first and last rise above 5% of their peak.
std::size_t first_sound(const std::vector<float>& samples) {
    const float peak = peak_of(samples);
    return static_cast<std::size_t>(
        std::find_if(samples.begin(), samples.end(), [&](float v) { return std::abs(v) > 0.05f * peak; }) -
        samples.begin());
}
std::size_t end_of_sound(const std::vector<float>& samples) {
    const float peak = peak_of(samples);
    return static_cast<std::size_t>(
        std::find_if(samples.rbegin(), samples.rend(), [&](float v) { return std::abs(v) > 0.05f * peak; })
            .base() -
        samples.begin());
}

}  // namespace

TEST_SUITE("speech") {
    TEST_CASE("a short line after a quieter voice starts where the line does") {
        const std::vector<float> line = read_clip("bare_line.flac");
        const std::vector<float> other = read_clip("comma_pause.flac");
        constexpr int kRateHz = 16000;
        // The other voice's first 0.5 s of speech, 14 dB under the line's peak, from the recording's
        // first sample; 0.08 s of hiss; the line (好); 0.3 s of hiss.
        const float other_peak = peak_of(other);
        const std::size_t sounding = first_sound(other);
        const float gain = std::pow(10.0f, -14.0f / 20.0f) * peak_of(line) / other_peak;
        std::vector<float> samples;
        for (std::size_t i = sounding; i < std::min(other.size(), sounding + kRateHz / 2); ++i)
            samples.push_back(gain * other[i]);
        samples.resize(samples.size() + static_cast<std::size_t>(0.08 * kRateHz), 0.0f);
        const double line_start_s = static_cast<double>(samples.size()) / kRateHz;
        samples.insert(samples.end(), line.begin(), line.end());
        samples.resize(samples.size() + static_cast<std::size_t>(0.3 * kRateHz), 0.0f);
        test::add_headset_hiss(samples);
        const Timeline aligned = SpeechAligner().align(AudioView{samples.data(), samples.size(), 1, kRateHz},
                                                       load_transcript(test::clip_path("bare_line.txt")));
        REQUIRE(aligned.syllables.size() == 1);
        CHECK(std::abs(aligned.syllables[0].start_s - line_start_s) < 0.05);
    }

    TEST_CASE("a short line before a quieter voice ends where the line does") {
        const std::vector<float> line = read_clip("short_line.flac");
        const std::vector<float> other = read_clip("comma_pause.flac");
        constexpr int kRateHz = 16000;
        // 0.3 s of hiss; the line (你好); 0.08 s of hiss; the other voice's first 0.5 s of speech, 14 dB
        // under the line's peak, to the recording's last sample.
        const float gain = std::pow(10.0f, -14.0f / 20.0f) * peak_of(line) / peak_of(other);
        std::vector<float> samples(static_cast<std::size_t>(0.3 * kRateHz), 0.0f);
        const double line_end_s = static_cast<double>(samples.size() + end_of_sound(line)) / kRateHz;
        samples.insert(samples.end(), line.begin(), line.end());
        samples.resize(samples.size() + static_cast<std::size_t>(0.08 * kRateHz), 0.0f);
        const std::size_t sounding = first_sound(other);
        for (std::size_t i = sounding; i < std::min(other.size(), sounding + kRateHz / 2); ++i)
            samples.push_back(gain * other[i]);
        test::add_headset_hiss(samples);
        const Timeline aligned = SpeechAligner().align(AudioView{samples.data(), samples.size(), 1, kRateHz},
                                                       load_transcript(test::clip_path("short_line.txt")));
        REQUIRE(aligned.syllables.size() == 2);
        CHECK(std::abs(aligned.syllables[1].end_s - line_end_s) < 0.05);
    }
}

// The damage a WAV's samples show (pcm_damage.hpp): a sample a changed byte moved off the wave, a
// block of zeros cut into the sound; not a voice's own loud noise, nor a pause it fades into.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "audio/pcm_damage.hpp"

using namespace talkface::detail;

namespace {

constexpr int kRateHz = 16000;

// A vowel at 150 Hz with its harmonics to 3 kHz, falling 12 dB an octave as a voice's do, at about
// -6 dBFS, and a little noise.
std::vector<float> vowel(std::size_t frames) {
    std::mt19937 random(7);
    std::normal_distribution<float> noise(0.0f, 0.002f);
    std::vector<float> samples(frames);
    for (std::size_t i = 0; i < frames; ++i) {
        double value = 0.0;
        for (int harmonic = 1; harmonic <= 20; ++harmonic)
            value += 0.5 / (harmonic * harmonic) *
                     std::sin(2.0 * M_PI * 150.0 * harmonic * static_cast<double>(i) / kRateHz);
        samples[i] = static_cast<float>(value) + noise(random);
    }
    return samples;
}

PcmDamageFinder found_in(const std::vector<float>& samples, std::size_t block) {
    PcmDamageFinder finder(kRateHz);
    for (std::size_t at = 0; at < samples.size(); at += block)
        finder.push(samples.data() + at, std::min(block, samples.size() - at));
    finder.finish();
    return finder;
}

}  // namespace

TEST_CASE("a sample moved off the wave is a click, at its frame, however the stream is pushed") {
    std::vector<float> samples = vowel(kRateHz);
    CHECK(found_in(samples, 4096).clicks().empty());
    for (const std::size_t at : {3000, 8001, 12345}) samples[at] += 0.5f;
    for (const std::size_t block : {1, 333, 4096, 65536}) {
        const PcmDamageFinder finder = found_in(samples, block);
        REQUIRE(finder.clicks().size() == 3);
        CHECK(finder.clicks()[0].first_frame == 3000);
        CHECK(finder.clicks()[1].first_frame == 8001);
        CHECK(finder.clicks()[2].first_frame == 12345);
        CHECK(finder.cut_zeros().empty());
    }
}

TEST_CASE("loud noise, as a fricative is, holds no click") {
    std::mt19937 random(11);
    std::normal_distribution<float> noise(0.0f, 0.3f);
    std::vector<float> samples(10 * kRateHz);
    for (float& sample : samples) sample = std::max(-1.0f, std::min(1.0f, noise(random)));
    CHECK(found_in(samples, 4096).clicks().empty());
}

TEST_CASE("a block of zeros cut into the sound is found, a pause faded into is not") {
    std::vector<float> samples = vowel(kRateHz);
    std::vector<float> faded = samples;
    for (std::size_t i = 6000; i < 8048; ++i) samples[i] = 0.0f;
    const PcmDamageFinder finder = found_in(samples, 1000);
    REQUIRE(finder.cut_zeros().size() == 1);
    CHECK(finder.cut_zeros()[0].first_frame == 6000);
    CHECK(finder.cut_zeros()[0].end_frame == 8048);
    CHECK(describe_pcm_damage(finder, kRateHz).at(0).find("exact digital zeros at 0.375-0.503 s") !=
          std::string::npos);
    // 10 ms fades either side of the same zeros: a pause an editor or a synthesizer made.
    for (std::size_t i = 0; i < 160; ++i) {
        faded[6000 - 160 + i] *= static_cast<float>(160 - i) / 160.0f;
        faded[8048 + i] *= static_cast<float>(i) / 160.0f;
    }
    for (std::size_t i = 6000; i < 8048; ++i) faded[i] = 0.0f;
    CHECK(found_in(faded, 1000).cut_zeros().empty());
}

TEST_CASE("zeros cut into a sound far below the voice, as a gate shuts on a noise floor, are no damage") {
    std::vector<float> samples = vowel(kRateHz);
    for (std::size_t i = 8000; i < samples.size(); ++i) samples[i] *= 0.05f;
    for (std::size_t i = 10000; i < 12048; ++i) samples[i] = 0.0f;
    CHECK(found_in(samples, 1000).cut_zeros().empty());
}

TEST_CASE("zeros cut into the sound are named as an editor's silence as well as damage") {
    // An editor's "silence" over a word (a name bleeped) cuts the wave to exact zeros mid-wave on
    // both sides, as a zeroed block of bytes does: the samples cannot tell the two apart, so the note
    // names both, and does not call a file silenced on purpose damaged.
    std::vector<float> samples = vowel(kRateHz);
    std::fill(samples.begin() + 6000, samples.begin() + 8048, 0.0f);
    const std::vector<std::string> notes = describe_pcm_damage(found_in(samples, 4096), kRateHz);
    REQUIRE_FALSE(notes.empty());
    CHECK(notes[0].find(
              "exact digital zeros at 0.375-0.503 s, as an editor's silence put over the sound leaves "
              "it, or a block of the file's bytes zeroed by a copy or a disk, or a stream's lost "
              "packets") != std::string::npos);
    CHECK(notes[0].find("silenced on purpose, the file is as it should be") != std::string::npos);
}

TEST_CASE("a sound ramped into a pause in half a millisecond, as espeak-ng ends its sounds, is no cut") {
    std::vector<float> samples = vowel(kRateHz);
    // The zeros start after the loudest sample near 0.375 s, the 8 samples before them falling from
    // there to 1/81 of it, more slowly near zero, and the next sound starts mid-wave, as espeak-ng's
    // do around its pauses.
    const auto loudest = std::max_element(samples.begin() + 6000, samples.begin() + 6100,
                                          [](float a, float b) { return std::fabs(a) < std::fabs(b); });
    const std::size_t first_zero = static_cast<std::size_t>(loudest - samples.begin()) + 9;
    const float from = *loudest;
    for (std::size_t k = 1; k <= 8; ++k) samples[first_zero - k] = from * static_cast<float>(k * k) / 81.0f;
    std::vector<float> cut = samples;
    std::fill(samples.begin() + static_cast<std::ptrdiff_t>(first_zero),
              samples.begin() + static_cast<std::ptrdiff_t>(first_zero + 2048), 0.0f);
    for (const std::size_t block : {1, 333, 4096}) CHECK(found_in(samples, block).cut_zeros().empty());
    // The same zeros six samples earlier cut the ramp at 0.6 of its height: cut on both sides.
    std::fill(cut.begin() + static_cast<std::ptrdiff_t>(first_zero - 6),
              cut.begin() + static_cast<std::ptrdiff_t>(first_zero + 2048), 0.0f);
    CHECK(found_in(cut, 4096).cut_zeros().size() == 1);
}

#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "audio/audio_source.hpp"
#include "common/test_paths.hpp"
#include "speech/frame_features.hpp"
#include "speech/xorshift.hpp"
#include "talkface/speech_aligner.hpp"

using namespace talkface;
using namespace talkface::detail;

namespace {

FeatureTrack features_of(const std::vector<float>& samples) {
    const auto source = open_audio_view(AudioView{samples.data(), samples.size(), 1, kAnalysisRateHz});
    return analyze_audio(*source, {});
}

// 0.5 s of a vowel-like tone, 0.5 s of digital silence, 0.5 s of the tone again.
std::vector<float> tone_silence_tone() {
    std::vector<float> samples(static_cast<std::size_t>(1.5 * kAnalysisRateHz), 0.0f);
    for (std::size_t i = 0; i < samples.size(); ++i) {
        if (i >= samples.size() / 3 && i < 2 * samples.size() / 3) continue;
        const double t = static_cast<double>(i) / kAnalysisRateHz;
        samples[i] = static_cast<float>(0.3 * std::sin(2.0 * M_PI * 220.0 * t) + 0.1 * std::sin(2.0 * M_PI * 660.0 * t));
    }
    return samples;
}

// 1 s of a voice's harmonics of 120 Hz, those from `lowest_hz` to 3400 Hz, of falling strength.
std::vector<float> harmonics_from(double lowest_hz) {
    std::vector<float> samples(kAnalysisRateHz, 0.0f);
    for (double f = 120.0; f <= 3400.0; f += 120.0) {
        if (f < lowest_hz) continue;
        for (std::size_t i = 0; i < samples.size(); ++i)
            samples[i] += static_cast<float>(
                0.3 * 120.0 / f * std::sin(2.0 * M_PI * f * static_cast<double>(i) / kAnalysisRateHz));
    }
    return samples;
}

}  // namespace

TEST_SUITE("frame features") {
    TEST_CASE("the fundamental's share of the low band: a voice's most, none through a telephone band") {
        CHECK(features_of(harmonics_from(0.0)).fundamental_share > 0.5);
        CHECK(features_of(harmonics_from(300.0)).fundamental_share < 0.01);
        CHECK(FeatureTrack{}.fundamental_share == 1.0);
    }

    TEST_CASE("digital silence keeps its level but its spectrum's shape varies, not one constant cepstrum") {
        const FeatureTrack track = features_of(tone_silence_tone());
        // Frames well inside the silence (60-90 of 150).
        double sum = 0.0, squares = 0.0;
        const std::size_t first = 60, end = 90;
        for (std::size_t t = first; t < end; ++t) {
            const double c1 = track.at(t, kCepstrum0 + 1);
            sum += c1;
            squares += c1 * c1;
            // The levels are the audio's own (the loudness profile and the checks read them): digital
            // silence stays at the energy floor; only the spectrum's shape is taken of the dithered frame.
            CHECK(track.at(t, kEnergyDb) < track.at(10, kEnergyDb) - 60.0f);
            CHECK(track.at(t, kEnergyDb) < -95.0f);
        }
        const double count = static_cast<double>(end - first);
        const double variance = squares / count - (sum / count) * (sum / count);
        // Digital silence gave every one of these frames the same cepstrum (variance 0): the silence
        // class learned a spike there, and a path holding the faintest sound in a pause lost to it.
        CHECK(variance > 0.01);
    }

    TEST_CASE("a DC offset is no sound: the levels, the spectrum and the peak are those without it") {
        // A cheap recorder's offset of 0.3 of full scale leaked through the window into the energy
        // band (from 60 Hz) and lifted every frame's peak by 0.3: the pauses read as loud as speech.
        std::vector<float> faint = tone_silence_tone();
        for (std::size_t i = 0; i < faint.size(); ++i)
            faint[i] = 0.5f * faint[i] + 1e-3f * static_cast<float>(std::sin(0.37 * static_cast<double>(i)));  // a room
        std::vector<float> offset = faint;
        for (float& sample : offset) sample += 0.3f;
        const FeatureTrack plain = features_of(faint);
        const FeatureTrack shifted = features_of(offset);
        REQUIRE(plain.frame_count == shifted.frame_count);
        float loudest_db = -1e9f;
        for (std::size_t t = 0; t < plain.frame_count; ++t) loudest_db = std::max(loudest_db, plain.at(t, kEnergyDb));
        // Frames whose window lies inside the file (the first and last are padded with zeros, where
        // an offset is a step).
        for (std::size_t t = 2; t + 2 < plain.frame_count; ++t) {
            CAPTURE(t);
            // The offset is followed, not known: what it leaves moves the faint frames' levels by
            // at most 2 dB (the offset itself lifted them by tens of dB).
            for (const int level : {kEnergyDb, kLowBandDb, kMidBandDb, kHighBandDb})
                CHECK(std::fabs(shifted.at(t, level) - plain.at(t, level)) < 2.0f);
            // The spectrum's shape where there is sound to shape it (a faint frame's cepstra follow
            // the dither).
            for (int c = 0; c < kCepstrumCount && plain.at(t, kEnergyDb) > loudest_db - 20.0f; ++c)
                CHECK(std::fabs(shifted.at(t, kCepstrum0 + c) - plain.at(t, kCepstrum0 + c)) < 0.03f * (10.0f + std::fabs(plain.at(t, kCepstrum0 + c))));
            CHECK(std::fabs(shifted.at(t, kPeakAmplitude) - plain.at(t, kPeakAmplitude)) < 2e-3f);
        }
    }

    TEST_CASE("a clipped voice keeps its levels under its loudest: full scale reads as loud as it was") {
        // Speaker 3's short line 40 dB too loud, clipped at full scale as a recorder clips it: its
        // loud frames read the clip's level, the median frame of its speech 2.5 dB under the 95th
        // percentile where the voice's own is 7.2 dB under, and the first pass (loudness, tilt,
        // low band) took weak sounds for vowels. Restored, 8.9 dB.
        const auto source = open_audio_file(test::source_path("tests/data/speech/short_line.flac"));
        std::vector<float> voice(source->frame_count());
        voice.resize(source->read(voice.data(), voice.size()));
        std::vector<float> clipped(voice.size());
        std::transform(voice.begin(), voice.end(), clipped.begin(),
                       [](float v) { return std::clamp(100.0f * v, -1.0f, 1.0f); });
        const FeatureTrack own = features_of(voice);
        const FeatureTrack hard = features_of(clipped);
        // The speech: the frames within 40 dB of the voice's loudest.
        float loudest = -100.0f;
        for (std::size_t t = 0; t < own.frame_count; ++t) loudest = std::max(loudest, own.at(t, kEnergyDb));
        std::vector<float> own_levels, hard_levels;
        for (std::size_t t = 0; t < own.frame_count; ++t) {
            if (own.at(t, kEnergyDb) < loudest - 40.0f) continue;
            own_levels.push_back(own.at(t, kEnergyDb));
            hard_levels.push_back(hard.at(t, kEnergyDb));
        }
        auto median_under_loud = [](std::vector<float> levels) {
            std::sort(levels.begin(), levels.end());
            return levels[levels.size() * 95 / 100] - levels[levels.size() / 2];
        };
        CHECK(std::fabs(median_under_loud(hard_levels) - median_under_loud(own_levels)) <= 3.0f);
    }

    TEST_CASE(
        "silence left out is passed unread where the source can seek, the features as if it were read") {
        // 3 s of a converter's silence (a thousandth of a bit of 16) at 44.1 kHz, whose rate is no
        // multiple of the analysis rate, then the tone: 2 s of it left out, as silence_to_skip
        // leaves hours out. Read through, every frame of the silence is resampled and dropped.
        constexpr int kRateHz = 44100;
        std::vector<float> samples(3 * kRateHz);
        std::uint32_t seed = 5;
        for (float& sample : samples)
            sample =
                static_cast<float>(static_cast<int>((seed = seed * 1664525u + 1013904223u) >> 16) - 32768) *
                1e-9f;
        for (std::size_t i = 0; i < 3 * kRateHz / 2; ++i) {
            const double t = static_cast<double>(i) / kRateHz;
            samples.push_back(static_cast<float>(0.3 * std::sin(2.0 * M_PI * 220.0 * t)));
        }
        // A source that counts the frames it gives, and passes skip_to() on only where told to.
        class CountingSource final : public AudioSource {
        public:
            CountingSource(const std::vector<float>& samples, bool can_seek)
                : view_(open_audio_view(AudioView{samples.data(), samples.size(), 1, kRateHz})),
                  can_seek_(can_seek) {}
            int sample_rate_hz() const override { return kRateHz; }
            std::size_t frame_count() const override { return view_->frame_count(); }
            const std::string& name() const override { return view_->name(); }
            std::size_t frames_given = 0;

        private:
            std::size_t read_frames(float* mono, std::size_t max_frames) override {
                const std::size_t got = view_->read(mono, max_frames);
                frames_given += got;
                return got;
            }
            bool seek_frames(std::size_t frame) override { return can_seek_ && view_->skip_to(frame); }
            std::unique_ptr<AudioSource> view_;
            bool can_seek_;
        };
        const std::size_t skipped = 2 * kAnalysisRateHz;
        CountingSource read_through(samples, false);
        CountingSource seeking(samples, true);
        const FeatureTrack all = analyze_audio(read_through, {}, false, skipped);
        const FeatureTrack passed = analyze_audio(seeking, {}, false, skipped);
        CHECK(read_through.frames_given == samples.size());
        CHECK(seeking.frames_given <= samples.size() - kRateHz);
        CHECK(passed.frame_count == all.frame_count);
        CHECK(passed.duration_s == doctest::Approx(all.duration_s).epsilon(1e-12));
        CHECK(passed.peak_amplitude == all.peak_amplitude);
        REQUIRE(passed.values.size() == all.values.size());
        float most_apart = 0.0f;
        for (std::size_t i = 0; i < all.values.size(); ++i)
            most_apart = std::max(most_apart, std::fabs(passed.values[i] - all.values[i]));
        CHECK(most_apart <= 1e-3f);
    }

    TEST_CASE("the dither repeats: the same audio gives the same features") {
        const auto samples = tone_silence_tone();
        CHECK(features_of(samples).values == features_of(samples).values);
    }

    TEST_CASE("xorshift64 jumped 800 steps lands where 800 steps do, from any state") {
        const XorshiftJump jump(800);
        std::uint64_t start = 0x9E3779B97F4A7C15ull;
        for (int trial = 0; trial < 20; ++trial) {
            CAPTURE(trial);
            std::uint64_t stepped = start;
            for (int n = 0; n < 800; ++n) stepped = xorshift64(stepped);
            CHECK(jump.apply(start) == stepped);
            start = xorshift64(stepped ^ 0x5851F42D4C957F2Dull);
        }
    }

    TEST_CASE("two xorshift64 states stepped as a pair step as each does alone, in either form") {
        // FastXorshiftPair is the vector form on GCC and Clang; the portable form is built here too,
        // so that what a compiler without the vector extension (MSVC) runs is tested on every build.
        std::uint64_t a = 1, b = 0xFFFFFFFFFFFFFFFFull;
        XorshiftPair portable(a, b);
        FastXorshiftPair fast(a, b);
        for (int n = 0; n < 1000; ++n) {
            a = xorshift64(a);
            b = xorshift64(b);
            portable.step();
            fast.step();
            CAPTURE(n);
            REQUIRE(portable.first() == a);
            REQUIRE(portable.second() == b);
            REQUIRE(fast.first() == a);
            REQUIRE(fast.second() == b);
        }
    }

    TEST_CASE("two frames' dither draws are one sequence's, the same in the portable and the fast form") {
        constexpr std::size_t kSamples = 400;  // the features' window: 2 x 400 draws a frame
        constexpr XorshiftJump jump(2 * kSamples);
        using Draws = std::array<std::array<std::array<std::uint32_t, kSamples>, 2>, 2>;
        for (std::uint64_t state : {0x9E3779B97F4A7C15ull, 1ull, 0xFFFFFFFFFFFFFFFFull}) {
            CAPTURE(state);
            Draws portable{}, fast{};
            const std::uint64_t portable_next = draw_two_frames<XorshiftPair>(state, jump, portable);
            const std::uint64_t fast_next = draw_two_frames<FastXorshiftPair>(state, jump, fast);
            CHECK(portable == fast);
            CHECK(portable_next == fast_next);
            // One draw after another: frame 0's 800, then frame 1's, then where frame 2 starts.
            std::uint64_t stepped = state;
            bool same = true;
            for (std::size_t frame = 0; frame < 2; ++frame) {
                for (std::size_t i = 0; i < kSamples; ++i) {
                    for (std::size_t k = 0; k < 2; ++k) {
                        stepped = xorshift64(stepped);
                        same = same && portable[frame][k][i] == static_cast<std::uint32_t>(stepped >> 40);
                    }
                }
            }
            CHECK(same);
            CHECK(portable_next == stepped);
        }
    }
}

// Dropouts (issue 13, bench/README.md sweep sessions 17-18): runs of exact zeros where a stream lost
// packets, inside speech, are drawn over and the syllables keep their times; a fade into a closure is
// no dropout, and a drum's cut between its hits, outside the speech, is left as it is.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <fstream>
#include <string>
#include <vector>

#include "common/clip_audio.hpp"
#include "common/test_paths.hpp"
#include "speech/dropout_concealment.hpp"
#include "speech/dropout_finder.hpp"
#include "speech/frame_features.hpp"

using namespace talkface;

namespace {

constexpr double kPi = 3.14159265358979323846;

// `clip` with `length_s` of exact zeros from `phase_s` into every whole second.
test::ClipSamples with_dropouts(test::ClipSamples clip, double phase_s, double length_s) {
    const auto rate = static_cast<double>(clip.rate_hz);
    for (double start_s = phase_s; start_s * rate < static_cast<double>(clip.values.size()); start_s += 1.0) {
        const auto first = static_cast<std::size_t>(start_s * rate);
        const auto end = std::min(clip.values.size(), static_cast<std::size_t>((start_s + length_s) * rate));
        std::fill(clip.values.begin() + static_cast<std::ptrdiff_t>(first),
                  clip.values.begin() + static_cast<std::ptrdiff_t>(end), 0.0f);
    }
    return clip;
}

// tests/data/speech/FILE with 60 ms dropouts from `phase_s` into every second aligns each syllable
// within 50 ms of where the clip without them does.
void check_near_clean(const std::string& file, double phase_s) {
    CAPTURE(file);
    const std::string name = file.substr(0, file.find('.'));
    const test::ClipSamples clip = test::clip_samples(file);
    const std::vector<double> clean = test::aligned_starts(clip, name + ".txt");
    const std::vector<double> cut = test::aligned_starts(with_dropouts(clip, phase_s, 0.06), name + ".txt");
    REQUIRE(cut.size() == clean.size());
    for (std::size_t i = 0; i < clean.size(); ++i) {
        CAPTURE(i);
        CHECK(std::abs(cut[i] - clean[i]) < 0.05);
    }
}

// two_sentences.wav, with `with_dropout` a dropout inside its first syllables' speech, and 1.5 s
// after it a drum's hits 20 dB under the voice: 50 ms of noise decaying by e every 30 ms, cut to
// zeros mid-wave for 40 ms before the next (bench/ m-drums' synthetic kit leaves such cuts).
test::ClipSamples drums_after_speech(bool with_dropout) {
    test::ClipSamples audio = test::clip_samples("two_sentences.wav");
    const auto rate = static_cast<double>(audio.rate_hz);
    float loudest = 0.0f;
    for (const float value : audio.values) loudest = std::max(loudest, std::fabs(value));
    const std::size_t speech_end = audio.values.size();
    audio.values.resize(speech_end + static_cast<std::size_t>(1.5 * rate), 0.0f);
    const auto hit = static_cast<std::size_t>(0.05 * rate), gap = static_cast<std::size_t>(0.04 * rate);
    std::uint32_t state = 12345u;
    for (std::size_t first = speech_end + static_cast<std::size_t>(0.5 * rate);
         first + hit < audio.values.size(); first += hit + gap)
        for (std::size_t i = 0; i < hit; ++i) {
            state = state * 1664525u + 1013904223u;
            const double noise = static_cast<double>(state >> 8) / 16777216.0 - 0.5;
            audio.values[first + i] =
                static_cast<float>(0.06 * loudest * noise * std::exp(-static_cast<double>(i) / rate / 0.03));
        }
    if (!with_dropout) return audio;
    const auto dropout_first = static_cast<std::size_t>(0.70 * rate);
    std::fill(audio.values.begin() + static_cast<std::ptrdiff_t>(dropout_first),
              audio.values.begin() +
                  static_cast<std::ptrdiff_t>(dropout_first + static_cast<std::size_t>(0.06 * rate)),
              0.0f);
    return audio;
}

}  // namespace

TEST_SUITE("speech") {
    TEST_CASE("a fade into a closure is no dropout, the same zeros cutting the wave are") {
        // 200 Hz at half of full scale, 60 ms of zeros from 0.2 s, faded out and in over 10 ms, or cut.
        const int rate = detail::kAnalysisRateHz;
        for (const bool is_faded : {true, false}) {
            CAPTURE(is_faded);
            std::vector<float> samples(static_cast<std::size_t>(0.5 * rate));
            const std::size_t first = static_cast<std::size_t>(0.2 * rate),
                              end = static_cast<std::size_t>(0.26 * rate);
            const auto fade = static_cast<std::size_t>(0.01 * rate);
            for (std::size_t i = 0; i < samples.size(); ++i) {
                double gain = i >= first && i < end ? 0.0 : 1.0;
                if (is_faded && i < first)
                    gain = std::min(1.0, static_cast<double>(first - i) / static_cast<double>(fade));
                if (is_faded && i >= end)
                    gain = std::min(1.0, static_cast<double>(i - end) / static_cast<double>(fade));
                samples[i] = static_cast<float>(
                    0.5 * gain * std::sin(2 * kPi * 200.0 * static_cast<double>(i) / rate + 1.0));
            }
            detail::DropoutFinder finder;
            finder.push(samples.data(), samples.size());
            const std::vector<detail::Dropout> found = finder.finish();
            if (is_faded) {
                CHECK(found.empty());
            } else {
                REQUIRE(found.size() == 1);
                CHECK(found[0].first_sample == first);
                CHECK(found[0].end_sample == end);
            }
        }
    }

    TEST_CASE("dropouts inside espeak-ng's speech: the clip aligns near its own clean times") {
        // 60 ms of zeros from a phase into every second, as a call that lost packets: on ca87fb8
        // syllables next to a dropout were taken to its edges, 0.11-0.20 s off their clean times.
        for (const auto& [file, phase_s] :
             {std::pair{"one_sentence.wav", 0.1}, std::pair{"run_together.flac", 0.0},
              std::pair{"comma_pause.flac", 0.4}})
            check_near_clean(file, phase_s);
    }

    TEST_CASE("dropouts at a syllable's start or end: the clip aligns near its own clean times") {
        // Speech on one side of the dropout only; on 2d28134 (speech on both sides asked) the
        // syllables next to it were taken to its edges, 60-70 ms off their clean times.
        for (const auto& [file, phase_s] :
             {std::pair{"two_sentences.wav", 0.0}, std::pair{"comma_pause.flac", 0.7}})
            check_near_clean(file, phase_s);
    }

    TEST_CASE("an AMR phone's pause frame is no dropout, the same zeros in a caller's samples are") {
        // AMR-NB as a phone stores it: 20 ms frames of 12.2 kb/s (type 7, their bits random: a
        // noise), one comfort-noise (SID, type 8) frame at 1 s, which the reader reads as zeros,
        // cutting the noise on both sides, and 1 s more of noise.
        std::string bytes = "#!AMR\n";
        std::uint32_t seed = 7;
        const auto frame = [&](char header, std::size_t size) {
            bytes += header;
            for (std::size_t i = 0; i < size; ++i)
                bytes += static_cast<char>((seed = seed * 1664525u + 1013904223u) >> 24);
        };
        for (int i = 0; i < 50; ++i) frame('\x3C', 31);
        frame('\x44', 5);
        for (int i = 0; i < 50; ++i) frame('\x3C', 31);
        const std::string path = test::output_path("pause_frame.amr");
        std::ofstream(path, std::ios::binary) << bytes;

        const auto source = detail::open_audio_file(path);
        const detail::FeatureTrack from_file = detail::analyze_audio(*source, {});
        REQUIRE(source->codec_pauses().size() == 1);
        CHECK(source->codec_pauses()[0].start_s == doctest::Approx(1.0));
        CHECK(source->codec_pauses()[0].end_s == doctest::Approx(1.02));
        CHECK(from_file.dropouts.empty());

        const auto again = detail::open_audio_file(path);
        const detail::FeatureTrack from_memory =
            test::features_of(test::read_all(*again), again->sample_rate_hz());
        REQUIRE(from_memory.dropouts.size() == 1);
        // 8 kHz read at 16 kHz: the zeros' edges move by a sample or two.
        CHECK(std::abs(static_cast<double>(from_memory.dropouts[0].first_sample) - 16000.0) <= 4.0);
        CHECK(std::abs(static_cast<double>(from_memory.dropouts[0].end_sample) - 16320.0) <= 4.0);
    }

    TEST_CASE("a drum's cuts outside the speech are left as they are, a dropout inside it is drawn over") {
        const test::ClipSamples audio = drums_after_speech(true);
        const auto rate = static_cast<double>(audio.rate_hz);
        const std::size_t speech_end = test::clip_samples("two_sentences.wav").values.size();
        detail::FeatureTrack track = test::features_of(audio.values, audio.rate_hz);
        const detail::FeatureTrack found = track;
        detail::conceal_dropouts(track);
        std::size_t drum_cuts = 0;
        for (const detail::Dropout& dropout : found.dropouts) {
            const double start_s = static_cast<double>(dropout.first_sample) / detail::kAnalysisRateHz;
            CAPTURE(start_s);
            const std::size_t frame = dropout.first_sample / detail::kHopSamples + 2;
            const bool is_changed = track.at(frame, detail::kEnergyDb) != found.at(frame, detail::kEnergyDb);
            if (start_s * rate > static_cast<double>(speech_end)) {
                ++drum_cuts;
                CHECK_FALSE(is_changed);
            } else {
                CHECK(std::abs(start_s - 0.70) < 0.001);
                CHECK(is_changed);
            }
        }
        CHECK(drum_cuts >= 10);
        CHECK(found.dropouts.size() == drum_cuts + 1);
    }

    TEST_CASE(
        "conceal_dropouts gives the loudness of the track as it leaves it, measured again only where it drew "
        "over frames") {
        for (const bool with_dropout : {false, true}) {
            CAPTURE(with_dropout);
            const test::ClipSamples audio = drums_after_speech(with_dropout);
            detail::FeatureTrack track = test::features_of(audio.values, audio.rate_hz);
            const detail::LoudnessProfile before = detail::measure_loudness(track);
            const detail::LoudnessProfile given = detail::conceal_dropouts(track);
            const detail::LoudnessProfile after = detail::measure_loudness(track);
            CHECK(given.activity_db == after.activity_db);
            CHECK(given.speech_first_frame == after.speech_first_frame);
            CHECK(given.speech_end_frame == after.speech_end_frame);
            CHECK(given.speech_level_db == after.speech_level_db);
            CHECK(given.pauses.size() == after.pauses.size());
            CHECK((before.activity_db != after.activity_db) == with_dropout);
        }
    }
}

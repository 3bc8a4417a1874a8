// Noise a phone's gain control lifts before a line (issues 12 and 13): the gain is high from the
// recording's start until the first loud syllable pulls it down, so the hiss before the line stands
// far over the hiss after it, the recording's floor, and the line's first syllables were spread over
// it from the recording's start. The lifted hiss keeps the floor's shape; the line starts where a
// voice's uneven bands do, and they last, where noise's own bursts break the shape a few frames at
// a time.
#include <doctest/doctest.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "audio/audio_source.hpp"
#include "audio/decoded_audio.hpp"
#include "common/speech_clips.hpp"
#include "speech/lifted_lead_in.hpp"
#include "talkface/speech_aligner.hpp"
#include "talkface/transcript.hpp"

using namespace talkface;

namespace {

constexpr int kRateHz = 16000;
constexpr double kPi = 3.14159265358979323846;

// White hiss 18 dB over the headset's, `seconds` long, plus `rumble(t_s)` times its level.
template <typename Rumble>
std::vector<float> lifted_hiss(double seconds, const Rumble& rumble) {
    const float lifted = 1e-3f * std::pow(10.0f, 18.0f / 20.0f);
    std::uint32_t state = 12345u;
    std::vector<float> samples;
    for (int i = 0; i < static_cast<int>(seconds * kRateHz); ++i)
        samples.push_back(lifted *
                          (static_cast<float>((state = state * 1664525u + 1013904223u) >> 8) / 8388608.0f -
                           1.0f + rumble(static_cast<double>(i) / kRateHz)));
    return samples;
}

// Checks that the line comes where it is after `lead_in_s` of `samples`: the line (its first 0.25 s
// of silence left out, 请 at 0.05 s) at a fifth of its level, then 0.3 s of the headset's hiss alone.
void check_line_after(std::vector<float> samples, double lead_in_s) {
    auto source = detail::open_audio_file(test::clip_path("comma_pause.flac"));
    const std::vector<float> clip = test::read_all(*source);
    for (std::size_t i = static_cast<std::size_t>(0.25 * kRateHz); i < clip.size(); ++i)
        samples.push_back(0.2f * clip[i]);
    samples.resize(samples.size() + static_cast<std::size_t>(0.3 * kRateHz), 0.0f);
    test::add_headset_hiss(samples);
    const Timeline aligned = SpeechAligner().align(AudioView{samples.data(), samples.size(), 1, kRateHz},
                                                   load_transcript(test::clip_path("comma_pause.txt")));
    REQUIRE(aligned.syllables.size() == 13);
    CHECK(std::abs(aligned.syllables[0].start_s - (lead_in_s + 0.05)) < 0.05);
    CHECK(std::abs(aligned.syllables[1].start_s - (lead_in_s + 0.32093)) < 0.05);
}

constexpr float kFloorDb = -60.0f;
constexpr std::size_t kPauseFrames = 20;
constexpr std::size_t kLeadInFrames = 50;

// A track of the lifted noise (every band 15 dB over its floor) for kLeadInFrames frames, then the
// frames of `initial` (low, mid, high band above the floors), then a vowel's, its low band loudest.
detail::FeatureTrack lead_in_then(const std::vector<std::array<float, 3>>& initial) {
    std::vector<std::array<float, 3>> frames(kLeadInFrames, {15.0f, 15.0f, 15.0f});
    frames.insert(frames.end(), initial.begin(), initial.end());
    frames.resize(frames.size() + 2 * kPauseFrames, {30.0f, 25.0f, 15.0f});
    detail::FeatureTrack track;
    track.frame_count = frames.size();
    track.values.assign(track.frame_count * detail::kFeatureCount, 0.0f);
    for (std::size_t t = 0; t < frames.size(); ++t) {
        float* frame = &track.values[t * detail::kFeatureCount];
        frame[detail::kLowBandDb] = kFloorDb + frames[t][0];
        frame[detail::kMidBandDb] = kFloorDb + frames[t][1];
        frame[detail::kHighBandDb] = kFloorDb + frames[t][2];
    }
    return track;
}

std::size_t lead_in_end(const detail::FeatureTrack& track) {
    const auto lead_in = detail::lifted_lead_in(track, kFloorDb, kFloorDb, kFloorDb, kPauseFrames);
    REQUIRE(lead_in.has_value());
    return lead_in->end_frame;
}

}  // namespace

TEST_SUITE("speech") {
    TEST_CASE("a line after hiss a gain control lifted starts where the line does") {
        constexpr double kLeadInS = 0.3;
        check_line_after(lifted_hiss(kLeadInS, [](double) { return 0.0f; }), kLeadInS);
    }

    TEST_CASE("a line after lifted hiss with bursts of rumble starts where the line does") {
        // A 40 ms burst of low rumble (four tones in the low band, 4-5 dB over the hiss there, as
        // street noise's through a phone) every 0.1 s from 0.05 s: each holds the bands out of the
        // floor's shape for three or four frames. Ended at the first, the lead-in was no pause long,
        // and 请 came 240 ms early.
        constexpr double kLeadInS = 0.6;
        constexpr double kFirstBurstS = 0.05;
        constexpr double kBurstS = 0.04;
        constexpr double kBurstEveryS = 0.1;
        constexpr double kRumbleShare = 0.14;
        const auto rumble = [&](double t_s) {
            if (t_s < kFirstBurstS || std::fmod(t_s - kFirstBurstS, kBurstEveryS) >= kBurstS) return 0.0f;
            double sum = 0.0;
            for (const double hz : {200.0, 350.0, 500.0, 650.0}) sum += std::sin(2.0 * kPi * hz * t_s);
            return static_cast<float>(kRumbleShare * sum);
        };
        check_line_after(lifted_hiss(kLeadInS, rumble), kLeadInS);
    }

    TEST_CASE("a lifted lead-in ends where the voice's first uneven frames begin, before its level rises") {
        // A quiet initial under the lifted noise: its frication lifts the high band 5 dB over the
        // others for two frames (out of the floor's shape, too few to end the lead-in alone) and stays
        // under the noise's level plus kLiftBelowSpeechDb; the vowel after it rises past that. Ended at
        // the vowel, the initial was left in the lead-in and the first syllable came late (session 31:
        // p-fast-combo's 走, GG, 在嗎 40-90 ms).
        CHECK(lead_in_end(lead_in_then({{15.0f, 15.0f, 20.0f}, {15.0f, 15.0f, 20.0f}})) == kLeadInFrames);
        // Frames that keep the floor's shape before the vowel are the noise's.
        CHECK(lead_in_end(lead_in_then({{16.0f, 16.0f, 16.0f}, {16.0f, 16.0f, 16.0f}})) == kLeadInFrames + 2);
    }
}

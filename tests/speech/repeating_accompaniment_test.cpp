// A drum kit under a voice (issue 13): its hits in the pauses are as loud as the quieter speech and
// change as a voice does, but they repeat with the beat. The repeat is found in a kit's onsets and
// not in noise or in speech alone, and the pauses between sentences under the kit at SNR 15 dB are
// found whole. A kit alone before the voice and after it, as loud as the voice, is no speech
// (unvoiced_beat.hpp). One syllable a whole number of bars away is no repeat of the beat.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "audio/audio_source.hpp"
#include "audio/decoded_audio.hpp"
#include "common/six_sentences.hpp"
#include "common/speech_clips.hpp"
#include "speech/frame_features.hpp"
#include "speech/repeating_accompaniment.hpp"
#include "speech/sentence_cutter.hpp"
#include "talkface/speech_aligner.hpp"

using namespace talkface;

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kEighthS = 0.29;

detail::FeatureTrack features_of(const std::vector<float>& samples, int rate_hz) {
    const auto source = detail::open_audio_view(AudioView{samples.data(), samples.size(), 1, rate_hz});
    return detail::analyze_audio(*source, {});
}

// Uniform noise in [-1, 1) from a fixed seed.
struct Noise {
    std::uint32_t state;
    float next() { return static_cast<float>((state = state * 1664525u + 1013904223u) >> 8) / 8388608.0f - 1.0f; }
};

// A drum kit of mean power 1: on every eighth note (kEighthS) a hi-hat's click of high noise, a kick
// (a falling sine) on the first and fifth of each bar's eight, a snare (noise and a 185 Hz body) on
// the third and seventh. Nothing of it is held, and its pauses between hits are shorter than a
// sentence's.
std::vector<float> drums(std::size_t count, int rate_hz) {
    std::vector<float> kit(count, 0.0f);
    Noise noise{7};
    const auto hit_length = static_cast<std::size_t>(0.25 * rate_hz);
    for (std::size_t eighth = 0; static_cast<double>(eighth) * kEighthS * rate_hz < static_cast<double>(count); ++eighth) {
        const auto first = static_cast<std::size_t>(static_cast<double>(eighth) * kEighthS * rate_hz);
        const bool is_kick = eighth % 4 == 0, is_snare = eighth % 4 == 2;
        double phase = 0.0;
        float last = 0.0f;
        for (std::size_t j = 0; j < hit_length && first + j < count; ++j) {
            const double since = static_cast<double>(j) / rate_hz;
            const float white = noise.next();
            double value = 0.3 * (white - last) * std::exp(-since / 0.02);
            last = white;
            if (is_kick) {
                phase += 2 * kPi * (50.0 + 70.0 * std::exp(-since / 0.03)) / rate_hz;
                value += std::sin(phase) * std::exp(-since / 0.12);
            }
            if (is_snare) value += (0.7 * white + 0.3 * std::sin(2 * kPi * 185.0 * since)) * std::exp(-since / 0.08);
            kit[first + j] += static_cast<float>(value);
        }
    }
    double power = 0.0;
    for (const float v : kit) power += static_cast<double>(v) * v;
    const double gain = 1.0 / std::sqrt(power / static_cast<double>(count));
    for (float& v : kit) v = static_cast<float>(v * gain);
    return kit;
}

}  // namespace

TEST_SUITE("speech") {
    TEST_CASE("a drum kit's onsets repeat with its beat, noise's and a voice's do not") {
        const test::SixSentences six = test::six_sentences();
        const int rate = six.rate_hz;
        const std::vector<float>& speech = six.samples;
        std::vector<float> noise(speech.size());
        Noise source{99};
        for (float& v : noise) v = 0.1f * source.next();
        const std::vector<float> mixed = test::mixed_at_snr(speech, drums(speech.size(), rate), rate, 15.0);
        REQUIRE(!mixed.empty());

        // The hi-hat's eighths, or a whole number of them, to a fraction of a frame.
        const double period = detail::accompaniment_period_frames(features_of(mixed, rate), -100.0f);
        const double eighths = period / (kEighthS * detail::kFramesPerSecond);
        CHECK(eighths >= 1.0);
        CHECK(std::abs(eighths - std::round(eighths)) * kEighthS * detail::kFramesPerSecond < 0.5);
        CHECK(detail::accompaniment_period_frames(features_of(noise, rate), -100.0f) == 0.0);
        CHECK(detail::accompaniment_period_frames(features_of(speech, rate), -100.0f) == 0.0);
    }

    TEST_CASE("one syllable a whole number of bars away is no beat's repeat") {
        // A period of 100 frames: the run at frames 300-309, quieter than the speech, has pauses
        // one and two periods away, and four periods on (the fourth multiple's only prediction
        // inside 900 frames) frame 700, a syllable of the speech at 650-749. On main that one
        // frame explained the run as a hit of the beat.
        constexpr float kThresholdDb = 10.0f;
        std::vector<float> activity(900, 5.0f);
        std::fill(activity.begin() + 300, activity.begin() + 310, 15.0f);
        std::fill(activity.begin() + 650, activity.begin() + 750, 25.0f);
        const std::vector<bool> repeated =
            detail::repeated_hits_between_pauses(activity, kThresholdDb, 100.0);
        CHECK(std::none_of(repeated.begin() + 300, repeated.begin() + 310, [](bool hit) { return hit; }));

        // The same run four periods from a hit as quiet as itself (699-711), the speech elsewhere:
        // the one prediction is the beat's, and explains it.
        std::fill(activity.begin() + 650, activity.begin() + 750, 5.0f);
        std::fill(activity.begin() + 699, activity.begin() + 712, 15.0f);
        std::fill(activity.begin() + 800, activity.begin() + 900, 25.0f);
        const std::vector<bool> hit = detail::repeated_hits_between_pauses(activity, kThresholdDb, 100.0);
        CHECK(std::all_of(hit.begin() + 300, hit.begin() + 310, [](bool is_hit) { return is_hit; }));
    }

    TEST_CASE("the pauses between sentences under a drum kit are found whole") {
        // SNR 15 dB against the speech's active level: the kit's hits in the pauses (1.69-2.59 s
        // of each copy, 4.15 s to the next copy's 0.3 s) are as loud as the quieter speech.
        const test::SixSentences six = test::six_sentences();
        const std::vector<float> mixed = test::mixed_at_snr(six.samples, drums(six.samples.size(), six.rate_hz), six.rate_hz, 15.0);
        REQUIRE(!mixed.empty());

        const detail::LoudnessProfile loudness = detail::measure_loudness(features_of(mixed, six.rate_hz));
        for (const auto& [start_s, end_s] : six.gaps) {
            CAPTURE(start_s);
            // One pause over half the gap or more: by loudness and change alone the hits cut it in
            // pieces. The hits next to the speech stay with it.
            CHECK(test::is_found_whole(loudness.pauses, start_s, end_s, 0.5));
        }
    }

    TEST_CASE("a drum kit alone before the voice and after it, as loud as the voice, is no speech") {
        // A video's intro: 8 s of the kit 3 dB under the speech's active level, then the six
        // sentences, then 4 s of the kit again. On main its hits changed as a voice does and were
        // taken for speech: the speech ran from the recording's start to its end.
        const test::SixSentences six = test::six_sentences();
        const int rate = six.rate_hz;
        const std::vector<float> speech = test::with_silent_edges(six, 8.0, 4.0);
        const auto intro = static_cast<std::size_t>(8 * rate);
        std::vector<float> kit = drums(speech.size(), rate);
        std::fill(kit.begin() + static_cast<std::ptrdiff_t>(intro),
                  kit.begin() + static_cast<std::ptrdiff_t>(intro + six.samples.size()), 0.0f);
        const std::vector<float> mixed = test::mixed_at_snr(speech, kit, rate, 3.0);
        REQUIRE(!mixed.empty());

        const detail::LoudnessProfile loudness = detail::measure_loudness(features_of(mixed, rate));
        const double voice_end_s = 8.0 + static_cast<double>(six.samples.size()) / rate;
        CHECK(test::start_error_s(loudness, 8.0) <= 0.1);
        CHECK(static_cast<double>(loudness.speech_end_frame) * detail::kFrameStepS <= voice_end_s);
    }
}

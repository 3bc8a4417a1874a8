// Noise a phone's gain control lifts in the pauses (issues 12 and 13): the gain drops under each
// syllable, so the noise right after one is the recording's floor, and recovers in a pause, where
// the same noise stands 9-12 dB above that floor, as loud as quiet speech (bench/README.md,
// session 27). Lifted alike in every band, it keeps the floor's shape and reads as a pause; sound
// as loud whose bands stand unevenly above their floors is a voice's and stays speech. The lift
// stays out of a sung intro the edge-music rule sets apart (session 28).
#include <doctest/doctest.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

#include "audio/audio_source.hpp"
#include "common/six_sentences.hpp"
#include "common/speech_clips.hpp"
#include "speech/frame_features.hpp"
#include "speech/lifted_noise.hpp"
#include "speech/sentence_cutter.hpp"

using namespace talkface::detail;

namespace {

constexpr double kPi = 3.14159265358979323846;

constexpr std::size_t kSentenceFrames = 200, kPauseFrames = 100;

// Two sentences of syllables 20 frames long, each a vowel (the low band 30 dB above its floor,
// the mid 20, the high 10) and 5 frames of the noise at the floor under the gain the vowel pulled
// down, with `pause(t)` (each band's level, frame t of the pause) between them. The change band
// changes as noise does, so no music is held.
template <typename Pause>
FeatureTrack agc_track(Pause pause) {
    FeatureTrack track;
    track.frame_count = 2 * kSentenceFrames + kPauseFrames;
    track.values.assign(track.frame_count * kFeatureCount, 0.0f);
    for (std::size_t t = 0; t < track.frame_count; ++t) {
        std::array<float, 3> bands{0.0f, 0.0f, 0.0f};
        if (t >= kSentenceFrames && t < kSentenceFrames + kPauseFrames)
            bands = pause(t - kSentenceFrames);
        else if (t % 20 < 15)
            bands = {30.0f, 20.0f, 10.0f};
        float* frame = &track.values[t * kFeatureCount];
        frame[kLowBandDb] = bands[0];
        frame[kMidBandDb] = bands[1];
        frame[kHighBandDb] = bands[2];
        frame[kEnergyDb] = bands[0];
        frame[kChangeBandDb] = bands[1];
        frame[kChangingDb] = bands[1] - 3.0f;
    }
    return track;
}

// Whether a pause of the profile lies inside the stretch between the sentences.
bool has_pause_between(const LoudnessProfile& loudness) {
    for (const FrameSpan& pause : loudness.pauses)
        if (pause.first_frame >= kSentenceFrames && pause.end_frame <= kSentenceFrames + kPauseFrames)
            return true;
    return false;
}

// A sung line of mean power 1, as bench/make_music_kinds.py's: phrases of 3 s, each six legato
// notes of 0.5 s gliding into each other, with a breath of 0.4 s between them; a vowel's
// formants shape the harmonics, vibrato 5.5 Hz.
std::vector<float> sung_line(std::size_t count, int rate_hz) {
    const double scale[] = {0, 2, 4, 7, 9, 12, 14, 9, 4, 7, 2};
    const double formants[][2] = {{700, 110}, {1150, 130}, {2600, 180}, {3300, 250}};
    std::vector<float> line(count, 0.0f);
    double phase = 0.0, power = 0.0, previous_hz = 392.0;
    for (std::size_t i = 0; i < count; ++i) {
        const double t = static_cast<double>(i) / rate_hz;
        const double in_phrase = std::fmod(t, 3.4);
        const auto note = static_cast<std::size_t>(t / 3.4) * 6 + static_cast<std::size_t>(in_phrase / 0.5);
        const double target_hz = 392.0 * std::pow(2.0, scale[note % 11] / 12.0);
        const double into_note = std::fmod(in_phrase, 0.5);
        const double hz =
            (into_note < 0.06 ? previous_hz + (target_hz - previous_hz) * into_note / 0.06 : target_hz) *
            (1.0 + 0.015 * std::sin(2 * kPi * 5.5 * t));
        if (into_note >= 0.06) previous_hz = target_hz;
        phase += 2 * kPi * hz / rate_hz;
        const double swell = std::min({1.0, in_phrase / 0.08, std::max(0.0, 3.0 - in_phrase) / 0.08});
        double value = 0.0;
        for (int h = 1; h < 30 && h * hz < 7500.0; ++h) {
            double gain = 0.02;
            for (const auto& formant : formants)
                gain += 1.0 / (1.0 + std::pow((h * hz - formant[0]) / formant[1], 2.0));
            value += gain / std::pow(h, 0.7) * std::sin(h * phase);
        }
        line[i] = static_cast<float>(swell * value);
        power += line[i] * static_cast<double>(line[i]);
    }
    const double gain = 1.0 / std::sqrt(power / static_cast<double>(count));
    for (float& v : line) v = static_cast<float>(v * gain);
    return line;
}

// How far from the first syllable the speech is found to start in 12 s of the sung line 3 dB
// under the speech's active level, fading out over 0.5 s before the six sentences, after 1 s of
// silence (the recording's floors digital silence).
double sung_intro_start_error_s() {
    const talkface::test::SixSentences six = talkface::test::six_sentences();
    const int rate = six.rate_hz;
    const std::vector<float> speech = talkface::test::with_silent_edges(six, 12.0, 0.0);
    const auto intro = static_cast<std::size_t>(12 * rate), fade = static_cast<std::size_t>(rate / 2);
    std::vector<float> music = sung_line(speech.size(), rate);
    for (std::size_t i = 0; i < music.size(); ++i) {
        if (i >= intro || i < static_cast<std::size_t>(rate))
            music[i] = 0.0f;
        else if (i + fade >= intro)
            music[i] *= static_cast<float>(intro - i) / static_cast<float>(fade);
    }
    const std::vector<float> mixed = talkface::test::mixed_at_snr(speech, music, rate, 3.0);
    const auto source = open_audio_view(talkface::AudioView{mixed.data(), mixed.size(), 1, rate});
    return talkface::test::start_error_s(measure_loudness(analyze_audio(*source, {})), 12.0);
}

}  // namespace

TEST_SUITE("speech") {
    TEST_CASE("noise a gain control lifts in a pause reads as the pause") {
        // The gain recovering: 9 dB over the floor at the pause's start, 12 dB at its end, every band alike.
        const FeatureTrack track = agc_track([](std::size_t t) {
            const float lift = 9.0f + 3.0f * static_cast<float>(t) / static_cast<float>(kPauseFrames);
            return std::array<float, 3>{lift + static_cast<float>(t % 3), lift,
                                        lift + static_cast<float>(t % 2)};
        });
        const LoudnessProfile loudness = measure_loudness(track);
        CHECK(has_pause_between(loudness));
        const std::vector<float> lift =
            noise_lift_db(track, loudness.low_floor_db, loudness.mid_floor_db, loudness.high_floor_db,
                          loudness.speech_level_db, 12, {0, track.frame_count});
        CHECK(lift[kSentenceFrames + kPauseFrames / 2] > 8.0f);
        CHECK(lift[kSentenceFrames / 2] == 0.0f);
        // Outside the voice's span (music the edge rules set apart) nothing is lifted.
        const std::vector<float> outside =
            noise_lift_db(track, loudness.low_floor_db, loudness.mid_floor_db, loudness.high_floor_db,
                          loudness.speech_level_db, 12, {0, kSentenceFrames});
        CHECK(outside[kSentenceFrames + kPauseFrames / 2] == 0.0f);
    }

    TEST_CASE("sound as loud whose bands stand unevenly above their floors stays speech") {
        const FeatureTrack track = agc_track([](std::size_t t) {
            return std::array<float, 3>{12.0f + static_cast<float>(t % 3), 6.0f, 0.0f};
        });
        CHECK_FALSE(has_pause_between(measure_loudness(track)));
    }

    TEST_CASE("a sung intro over digital silence is no speech: its quiet notes are no lifted noise") {
        // The floors are digital silence, where the bands' shape is no noise's and every
        // quiet note keeps it: with session 27's lift the intro went into the first sentence
        // (the speech found 11.29 s early).
        CHECK(sung_intro_start_error_s() <= 0.1);
    }
}

// Noise a phone's gain control lifts in the pauses (issues 12 and 13): the gain drops under each
// syllable, so the noise right after one is the recording's floor, and recovers in a pause, where
// the same noise stands 9-12 dB above that floor, as loud as quiet speech (bench/README.md,
// session 27). Lifted alike in every band, it keeps the floor's shape and reads as a pause; sound
// as loud whose bands stand unevenly above their floors is a voice's and stays speech.
#include <doctest/doctest.h>

#include <array>
#include <cstddef>
#include <vector>

#include "speech/frame_features.hpp"
#include "speech/lifted_noise.hpp"
#include "speech/sentence_cutter.hpp"

using namespace talkface::detail;

namespace {

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
        const std::vector<float> lift = noise_lift_db(track, loudness.low_floor_db, loudness.mid_floor_db,
                                                      loudness.high_floor_db, loudness.speech_level_db, 12);
        CHECK(lift[kSentenceFrames + kPauseFrames / 2] > 8.0f);
        CHECK(lift[kSentenceFrames / 2] == 0.0f);
    }

    TEST_CASE("sound as loud whose bands stand unevenly above their floors stays speech") {
        const FeatureTrack track = agc_track([](std::size_t t) {
            return std::array<float, 3>{12.0f + static_cast<float>(t % 3), 6.0f, 0.0f};
        });
        CHECK_FALSE(has_pause_between(measure_loudness(track)));
    }
}

// Music played on under the first words (a bed) taken out of the features the models read
// (bed_removal.hpp, issue 13).
#include <doctest/doctest.h>

#include <cmath>

#include "speech/bed_removal.hpp"
#include "speech/late_reverb.hpp"

using namespace talkface::detail;

namespace {

constexpr double kNoiseDb = -60.0, kBedDb = -30.0, kVoiceDb = -20.0;
constexpr std::size_t kMusicFirst = 20, kVoiceEntry = 100, kBedEnd = 180, kFrames = 200;
// The voice under the bed, a run of three syllables with no gap: the bed shows through before and after it.
constexpr std::size_t kVoiceFirst = 120, kVoiceEnd = 150;

double power_of(double db) {
    return std::pow(10.0, db / 10.0);
}

// A recording's frames of flat spectra (c0 = 24 times the mel bands' log power, the other
// cepstra 0): noise in the pauses at its edges, a bed alone from kMusicFirst, the voice under it
// over [kVoiceFirst, kVoiceEnd).
FeatureTrack voice_under_bed() {
    FeatureTrack track;
    track.frame_count = kFrames;
    track.values.assign(track.frame_count * kFeatureCount, 0.0f);
    for (std::size_t t = 0; t < kFrames; ++t) {
        const bool is_music = t >= kMusicFirst && t < kBedEnd;
        const bool is_voice = t >= kVoiceFirst && t < kVoiceEnd;
        const double heard =
            power_of(kNoiseDb) + (is_music ? power_of(kBedDb) : 0.0) + (is_voice ? power_of(kVoiceDb) : 0.0);
        float* row = &track.values[t * kFeatureCount];
        row[kCepstrum0] = static_cast<float>(kMelFilters * std::log(heard));
        for (const int column : {kEnergyDb, kLowBandDb, kMidBandDb, kHighBandDb})
            row[column] = static_cast<float>(10.0 * std::log10(heard));
    }
    return track;
}

LoudnessProfile bed_found() {
    LoudnessProfile loudness;
    loudness.pauses = {{0, kMusicFirst}, {kBedEnd, kFrames}};
    loudness.music_before_voice = {kMusicFirst, kVoiceEntry};
    loudness.voice_under_music = {kVoiceEntry, kBedEnd};
    return loudness;
}

}  // namespace

TEST_SUITE("bed removal") {
    TEST_CASE(
        "the bed taken out under the voice leaves the voice, the bed 10 dB under itself and the music before "
        "it as heard") {
        const FeatureTrack heard = voice_under_bed();
        REQUIRE(has_music_bed(bed_found()));
        const FeatureTrack voice = without_music_bed(heard, bed_found());
        REQUIRE(voice.frame_count == heard.frame_count);
        for (std::size_t t = 0; t < kFrames; ++t) {
            CAPTURE(t);
            const bool is_under = t >= kVoiceEntry && t < kBedEnd;
            const bool is_voice = t >= kVoiceFirst && t < kVoiceEnd;
            // The voice's frames less the bed that shows through within 200 ms of them; the bed
            // after the voice's entry no lower than kDryFloorDb under itself (above the pauses'
            // noise); the music alone before the entry and the pauses as heard.
            const double expected_db = !is_under  ? heard.at(t, kEnergyDb)
                                       : is_voice ? kVoiceDb
                                                  : heard.at(t, kEnergyDb) - kDryFloorDb;
            for (const int column : {kEnergyDb, kLowBandDb, kMidBandDb, kHighBandDb})
                CHECK(voice.at(t, column) == doctest::Approx(expected_db).epsilon(1e-4));
            CHECK(voice.at(t, kCepstrum0) ==
                  doctest::Approx(kMelFilters * std::log(power_of(expected_db))).epsilon(1e-4));
            for (int c = 1; c < kCepstrumCount; ++c) CHECK(std::fabs(voice.at(t, kCepstrum0 + c)) < 1e-3);
        }
    }

    TEST_CASE("a recording without a bed has none to take out") {
        CHECK_FALSE(has_music_bed(LoudnessProfile{}));
    }
}

// A room's late ringing read at a recording's sentence ends and taken out of its features
// (late_reverb.hpp, issue 12).
#include <doctest/doctest.h>

#include <cmath>
#include <vector>

#include "speech/late_reverb.hpp"

using namespace talkface::detail;

namespace {

constexpr double kDecayDbPerFrame = 0.8;
// A voice held at power V leaves ringing of kVoiceShare V / (1 - decay) where it stops: 18 dB under it.
constexpr double kVoiceShare = 0.0026;
constexpr float kVoiceDb = -20.0f;
constexpr std::size_t kVoiceFirst = 10, kVoiceEnd = 70, kSpeechEnd = 100;

double power_of(double db) {
    return std::pow(10.0, db / 10.0);
}

// A voice of kVoiceDb in every band over [kVoiceFirst, kVoiceEnd) of 120 frames, in a room that
// rings as late_reverb.hpp follows it: decaying kDecayDbPerFrame a frame, each frame's voice adding
// kVoiceShare of its power. The spectrum is flat: c0 = 24 times the mel bands' log power, the
// other cepstra 0.
FeatureTrack voice_in_room() {
    const double decay = power_of(-kDecayDbPerFrame);
    FeatureTrack track;
    track.frame_count = 120;
    track.values.assign(track.frame_count * kFeatureCount, 0.0f);
    double ringing = 0.0, voice_before = 0.0;
    for (std::size_t t = 0; t < track.frame_count; ++t) {
        ringing = decay * ringing + kVoiceShare * voice_before;
        const double voice = t >= kVoiceFirst && t < kVoiceEnd ? power_of(kVoiceDb) : 0.0;
        const double heard = voice + ringing + 1e-10;
        float* row = &track.values[t * kFeatureCount];
        row[kCepstrum0] = static_cast<float>(kMelFilters * std::log(heard));
        for (const int column : {kEnergyDb, kLowBandDb, kMidBandDb, kHighBandDb})
            row[column] = static_cast<float>(10.0 * std::log10(heard));
        voice_before = voice;
    }
    return track;
}

std::vector<SentenceChain> chains_ending_in_tails(std::size_t count) {
    std::vector<SentenceChain> chains(count);
    for (SentenceChain& chain : chains) {
        chain.speech = {kVoiceFirst, kSpeechEnd};
        chain.tail_frames = kSpeechEnd - kVoiceEnd;
        chain.ends_in_tail = true;
    }
    return chains;
}

}  // namespace

TEST_SUITE("late reverb") {
    TEST_CASE(
        "a room's decay and the voice's share in its ringing are read from the tails its sentence ends ring "
        "on in") {
        const auto room = measure_room_ringing(voice_in_room(), chains_ending_in_tails(3));
        REQUIRE(room.has_value());
        CHECK(room->decay_db_per_frame == doctest::Approx(kDecayDbPerFrame).epsilon(0.001));
        // Read against the frames as heard, whose ringing lies 18 dB under the voice: 1.6% low.
        CHECK(room->voice_share == doctest::Approx(kVoiceShare).epsilon(0.02));
    }

    TEST_CASE("without sentence ends that ring on there is no room to read") {
        std::vector<SentenceChain> chains = chains_ending_in_tails(2);
        for (SentenceChain& chain : chains) chain.ends_in_tail = false;
        CHECK_FALSE(measure_room_ringing(voice_in_room(), chains).has_value());
    }

    TEST_CASE("the ringing taken out leaves the voice, and the tail 10 dB under the frame") {
        const FeatureTrack recorded = voice_in_room();
        const FeatureTrack dry = without_late_ringing(recorded, RoomRinging{kDecayDbPerFrame, kVoiceShare});
        REQUIRE(dry.frame_count == recorded.frame_count);
        for (std::size_t t = kVoiceFirst; t < kSpeechEnd; ++t) {
            CAPTURE(t);
            for (const int column : {kEnergyDb, kLowBandDb, kMidBandDb, kHighBandDb}) {
                CAPTURE(column);
                // The voice held ever louder than its ringing is heard as itself; the ringing
                // alone, after it, is floored.
                const double expected_db = t < kVoiceEnd ? kVoiceDb : recorded.at(t, column) - kDryFloorDb;
                CHECK(dry.at(t, column) == doctest::Approx(expected_db).epsilon(1e-4));
            }
            const double expected_c0 = t < kVoiceEnd
                                           ? kMelFilters * std::log(power_of(kVoiceDb))
                                           : recorded.at(t, kCepstrum0) - kMelFilters * std::log(10.0);
            CHECK(dry.at(t, kCepstrum0) == doctest::Approx(expected_c0).epsilon(1e-4));
            for (int c = 1; c < kCepstrumCount; ++c) CHECK(std::fabs(dry.at(t, kCepstrum0 + c)) < 1e-3);
        }
        // Before the voice only the floor rings, under 0.1 dB of it.
        CHECK(std::fabs(dry.at(kVoiceFirst - 1, kEnergyDb) - recorded.at(kVoiceFirst - 1, kEnergyDb)) < 0.1);
    }
}

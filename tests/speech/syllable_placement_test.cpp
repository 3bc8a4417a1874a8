// Where a voiced join starts (issue 12): a syllable whose initial is voiced (m n l r, none) runs on
// from the vowel before; the path's boundary lies where the two sounds fit alike, the middle of
// the transition, and the syllable starts where the transition does; one with no initial (y- w-,
// a vowel) at the level's valley between the two vowels.
#include <doctest/doctest.h>

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "common/chain_state.hpp"
#include "speech/hsmm.hpp"
#include "speech/syllable_placement.hpp"

using namespace talkface::detail;

namespace {

// Emissions where every class scores -20 but a and i: a scores 0 and i `rise` (a frame's rise,
// from a towards i).
void add_frame(EmissionScores& emissions, float rise) {
    for (int c = 0; c < kPhoneClassCount; ++c)
        emissions.values.push_back(c == kVowelA ? 0.0f : c == kVowelI ? rise : -20.0f);
    ++emissions.frame_count;
}

// A feature track of `frames` frames whose whole-band level is `level_db(frame)`.
FeatureTrack level_track(std::size_t frames, const std::function<float(std::size_t)>& level_db) {
    FeatureTrack track;
    track.frame_count = frames;
    track.duration_s = static_cast<double>(frames) * kFrameStepS;
    track.values.assign(frames * kFeatureCount, 0.0f);
    for (std::size_t t = 0; t < frames; ++t) track.values[t * kFeatureCount + kEnergyDb] = level_db(t);
    return track;
}

// Two nuclei at -20 dB with a valley between them at frame `valley` (of the track), `depth_db`
// under them, its sides falling and rising over 4 frames.
FeatureTrack two_nuclei(std::size_t valley, float depth_db) {
    return level_track(60, [=](std::size_t t) {
        const double distance = t > valley ? static_cast<double>(t - valley) : static_cast<double>(valley - t);
        return -20.0f - (distance < 4.0 ? depth_db * static_cast<float>(1.0 - distance / 4.0) : 0.0f);
    });
}

// 了一 as a chain and its path: silence (frames 0-9), 了's l (10-14) and e (15-19), 一's i (20-39),
// silence (40-49). Every class scores -20 on a frame but the path's own (0); on the e, i scores
// `i_on_e[t]` as well, and e -10 on the i. `le` is 了's pinyin.
struct LightJoin {
    std::vector<talkface::Syllable> syllables;
    SentenceChain chain;
    std::vector<StateSegment> path;
    EmissionScores scores;
    FeatureTrack track;

    LightJoin(const std::string& le, const std::vector<float>& i_on_e) {
        syllables.resize(2);
        syllables[0].text = "了";
        syllables[0].pinyin = le;
        syllables[1].text = "一";
        syllables[1].pinyin = "yi1";
        const PhoneClass classes[] = {kSilence, kLiquid, kVowelE, kVowelI, kSilence};
        const StateRole roles[] = {StateRole::edge_silence, StateRole::initial, StateRole::final,
                                   StateRole::final, StateRole::edge_silence};
        const std::size_t of_syllable[] = {0, 0, 0, 1, 1}, frames[] = {10, 5, 5, 20, 10};
        std::size_t frame = 0;
        for (std::size_t s = 0; s < 5; ++s) {
            chain.states.push_back(talkface::test::chain_state(
                classes[s], roles[s], of_syllable[s], static_cast<double>(frames[s]), 100, s == 0 || s == 4));
            path.push_back({s, frame, frame + frames[s]});
            for (std::size_t t = 0; t < frames[s]; ++t, ++frame)
                for (int c = 0; c < kPhoneClassCount; ++c) {
                    float score = c == classes[s] ? 0.0f : -20.0f;
                    if (classes[s] == kVowelE && c == kVowelI) score = i_on_e[t];
                    if (classes[s] == kVowelI && c == kVowelE) score = -10.0f;
                    scores.values.push_back(score);
                }
        }
        scores.frame_count = frame;
        for (const auto& syllable : syllables) chain.syllables.push_back(&syllable);
        chain.syllable_indices = {0, 1};
        chain.speech = chain.searched = chain.limit = {0, frame};
        track = level_track(frame, [](std::size_t) { return -20.0f; });
    }

    // Where place_syllables starts 一, in frames.
    double yi_start_frames() const {
        talkface::Timeline result;
        result.syllables = syllables;
        std::vector<SyllableEvidence> evidence(syllables.size());
        place_syllables(chain, 0, path, {}, scores, track, result, evidence);
        return result.syllables[1].start_s / kFrameStepS;
    }
};

}  // namespace

TEST_SUITE("speech") {
    TEST_CASE("a voiced join starts where the sound begins to turn, not where the two sounds fit alike") {
        // 啊衣: 16 frames of a, 8 of a linear turn to i (frames 16-23, the rise from -10 to +10,
        // crossing 0 between frames 19 and 20), 16 of i. The path's boundary is at the crossing.
        EmissionScores emissions;
        for (int t = 0; t < 16; ++t) add_frame(emissions, -10.0f);
        for (int t = 0; t < 8; ++t) add_frame(emissions, -10.0f + 20.0f * (static_cast<float>(t) + 0.5f) / 8.0f);
        for (int t = 0; t < 16; ++t) add_frame(emissions, 10.0f);
        const StateSegment before{0, 0, 20}, first{1, 20, 40};
        const std::size_t start = voiced_join_start(before, kVowelA, first, kVowelI, emissions);
        CAPTURE(start);
        // A quarter of the way up the turn (frame 18): 20 ms after its first frame, 20 ms before the crossing.
        CHECK(start >= 16);
        CHECK(start <= 18);
    }

    TEST_CASE("a voiced join the classes do not bear out stays where the path put it") {
        // The frames after the boundary fit a no worse than those before it (the duration priors
        // put it there): there is no turn towards i to follow back.
        EmissionScores emissions;
        for (int t = 0; t < 20; ++t) add_frame(emissions, 5.0f);
        for (int t = 0; t < 20; ++t) add_frame(emissions, -5.0f);
        const StateSegment before{0, 0, 20}, first{1, 20, 40};
        CHECK(voiced_join_start(before, kVowelA, first, kVowelI, emissions) == 20);
    }

    TEST_CASE("a syllable with no initial starts at the valley between its vowel and the one before") {
        // 是一: the path puts 一 at frame 25 of the chain (frame 30 of the track), three frames
        // after the valley where the level is 10 dB under both vowels.
        const FeatureTrack track = two_nuclei(27, 10.0f);
        CHECK(syllable_valley_start(track, 5, 1, 25) == 22);
        // Where the path put it already.
        CHECK(syllable_valley_start(track, 5, 1, 22) == 22);
        // Seven frames back (after a short syllable the path starts the next one late): a valley
        // this deep is still taken, one of 5 dB only within six frames.
        CHECK(syllable_valley_start(track, 5, 1, 29) == 22);
        CHECK(syllable_valley_start(two_nuclei(27, 5.0f), 5, 1, 25) == 22);
        CHECK(syllable_valley_start(two_nuclei(27, 5.0f), 5, 1, 29) == 29);
        // Twenty frames back at most: a valley 21 frames before is not looked at, and the search's
        // first frame, still on the valley's rising side, is no valley.
        CHECK(syllable_valley_start(track, 5, 1, 43) == 43);
        // A valley right after the start would move the syllable later: it stays.
        CHECK(syllable_valley_start(track, 5, 1, 21) == 21);
    }

    TEST_CASE("a far valley lies after the nucleus before it, even where the next syllable is louder") {
        // 包忘: 包's vowel at -20 dB, a valley 10 dB deep at frame 22, then 忘 rising 2 dB a frame
        // past -20 dB; the path put 忘 at frame 31, nine frames after the valley. 忘's own rise
        // into frame 31 is louder than 包: 包's nucleus is the loudest frame before that rise.
        const FeatureTrack louder_after = level_track(60, [](std::size_t t) {
            if (t < 18) return -20.0f;
            if (t <= 26) return -30.0f + 2.5f * static_cast<float>(t > 22 ? t - 22 : 22 - t);
            return -20.0f + 2.0f * static_cast<float>(t - 26);
        });
        CHECK(syllable_valley_start(louder_after, 0, 1, 31) == 22);
        // 有一: 有's weak y (-26 dB) dips to -34 dB before its ou (-20 dB), which runs flat into 一.
        // That dip is 有's own onset, before its nucleus: 一 stays where the path put it.
        const FeatureTrack own_onset = level_track(60, [](std::size_t t) {
            if (t < 5) return -26.0f;
            if (t < 8) return t == 6 ? -34.0f : -30.0f;
            return -20.0f;
        });
        CHECK(syllable_valley_start(own_onset, 0, 1, 25) == 25);
    }

    TEST_CASE("after a nasal's flat floor a syllable with no initial starts where the level begins to rise") {
        // 公園: ng holds 12 dB under the vowels for frames 18-23 of the track, wavering by 0.3 dB, then
        // 園 rises. The path put 園 at frame 26 (chain frame 24, offset 2); the floor's lowest frame
        // in the search is track frame 21, its last 23 (chain frame 21).
        const FeatureTrack track = level_track(60, [](std::size_t t) {
            if (t < 18 || t > 23) return -20.0f;
            return t % 2 == 0 ? -32.0f : -32.3f;
        });
        CHECK(syllable_valley_start(track, 2, 1, 24) == 21);
    }

    TEST_CASE("a syllable with no initial stays where a shallow dip or the syllable before's vowel leaves it") {
        // 2 dB is a vowel's own wavering, not a boundary.
        CHECK(syllable_valley_start(two_nuclei(27, 2.0f), 5, 1, 25) == 25);
        // The valley lies before the first frame it may move to (the vowel before starts there).
        CHECK(syllable_valley_start(two_nuclei(27, 10.0f), 5, 23, 25) == 25);
        // A level that only rises holds no valley.
        const FeatureTrack rising = level_track(60, [](std::size_t t) { return -40.0f + static_cast<float>(t) * 0.5f; });
        CHECK(syllable_valley_start(rising, 5, 1, 25) == 25);
        // The search stays inside the track: a start near its end.
        CHECK(syllable_valley_start(two_nuclei(27, 10.0f), 5, 1, 54) == 54);
    }

    TEST_CASE("after an apical vowel a syllable started in a held sound starts at the turn before it") {
        // 是一: the landmarks' bonus falls from 是's onset (frames 0-3), holds at 0 over its vowel,
        // rises and falls again where it turns into 一's i (frames 15-18), and holds over the i.
        EmissionScores scores;
        scores.frame_count = 40;
        scores.boundary.assign(41, 0.0f);
        const float onset[] = {3.0f, 2.0f, 1.0f}, turn[] = {0.4f, 1.5f, 1.8f, 0.6f};
        for (std::size_t t = 0; t < 3; ++t) scores.boundary[t] = onset[t];
        for (std::size_t t = 0; t < 4; ++t) scores.boundary[15 + t] = turn[t];
        // The path started 一 at frame 30, inside the i: it starts where the turn rises.
        CHECK(apical_vowel_turn(scores, 0, 30) == 15);
        // At the turn the path's own start stands.
        CHECK(apical_vowel_turn(scores, 0, 17) == 17);
        // The vowel's own onset is no turn, nor a ripple of the held vowel.
        CHECK(apical_vowel_turn(scores, 5, 14) == 14);
        scores.boundary[16] = 0.3f;
        scores.boundary[17] = 0.2f;
        scores.boundary[15] = scores.boundary[18] = 0.0f;
        CHECK(apical_vowel_turn(scores, 0, 30) == 30);
    }

    TEST_CASE("after a light vowel the next sound fits throughout, the next syllable starts with it") {
        // A light 了 said quickly and weakly: its e is only the turn into 一's i, which fits each of
        // its frames as well (of the rise towards i no step to walk back over). 一 starts with it.
        const std::vector<float> turn = {0.0f, 0.5f, 0.5f, 0.5f, 0.5f};
        CHECK(LightJoin("le5", turn).yi_start_frames() == doctest::Approx(15.0));
        // 了 with a tone of its own is heard apart; one e frame the i fits worse is a vowel of its own.
        CHECK(LightJoin("le4", turn).yi_start_frames() == doctest::Approx(20.0));
        CHECK(LightJoin("le5", {0.5f, 0.5f, -0.5f, 0.5f, 0.5f}).yi_start_frames() == doctest::Approx(20.0));
    }
}

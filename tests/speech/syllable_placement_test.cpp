// Where a voiced join starts (issue 12): a syllable whose initial is voiced (m n l r, none) runs on
// from the vowel before; the path's boundary lies where the two sounds fit alike, the middle of
// the transition, and the syllable starts where the transition does; one with no initial (y- w-,
// a vowel) at the level's valley between the two vowels.
#include <doctest/doctest.h>

#include <cmath>
#include <cstddef>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "common/chain_state.hpp"
#include "speech/hsmm.hpp"
#include "speech/phone_chain.hpp"
#include "speech/syllable_placement.hpp"
#include "talkface/timeline.hpp"

using namespace talkface::detail;
using talkface::Syllable;
using talkface::Timeline;

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

// Two syllables as a chain and its path: each state's class, role, syllable and frames in order,
// an edge silence first and last. Every class scores -20 on a frame but the path's own (0); every
// column of the feature track is -20 dB.
struct MadeJoin {
    struct Part {
        PhoneClass phone_class;
        StateRole role;
        std::size_t syllable;
        std::size_t frames;
    };
    std::vector<talkface::Syllable> syllables;
    SentenceChain chain;
    std::vector<StateSegment> path;
    EmissionScores scores;
    FeatureTrack track;

    MadeJoin(const std::vector<std::string>& pinyins, const std::vector<Part>& parts) {
        for (const std::string& pinyin : pinyins) {
            syllables.emplace_back();
            syllables.back().pinyin = pinyin;
        }
        std::size_t frame = 0;
        for (const Part& part : parts) {
            const bool is_edge = part.role == StateRole::edge_silence;
            chain.states.push_back(talkface::test::chain_state(
                part.phone_class, part.role, part.syllable, static_cast<double>(part.frames), 100, is_edge));
            path.push_back({chain.states.size() - 1, frame, frame + part.frames});
            for (std::size_t t = 0; t < part.frames; ++t, ++frame)
                for (int c = 0; c < kPhoneClassCount; ++c)
                    scores.values.push_back(c == part.phone_class ? 0.0f : -20.0f);
        }
        scores.frame_count = frame;
        for (const auto& syllable : syllables) chain.syllables.push_back(&syllable);
        for (std::size_t i = 0; i < syllables.size(); ++i) chain.syllable_indices.push_back(i);
        chain.speech = chain.searched = chain.limit = {0, frame};
        track = level_track(frame, [](std::size_t) { return -20.0f; });
        for (float& value : track.values) value = -20.0f;
    }

    float& score(std::size_t frame, int phone_class) {
        return scores.values[frame * kPhoneClassCount + static_cast<std::size_t>(phone_class)];
    }

    // The syllables as place_syllables places them (times in frames: start_s / kFrameStepS).
    std::vector<talkface::Syllable> placed() const {
        talkface::Timeline result;
        result.syllables = syllables;
        std::vector<SyllableEvidence> evidence(syllables.size());
        place_syllables(chain, 0, path, {}, scores, track, result, evidence);
        return result.syllables;
    }
};

// 了一: silence (frames 0-9), 了's l (10-14) and e (15-19), 一's i (20-39), silence (40-49). On the
// e, i scores `i_on_e[t]`, and e -10 on the i. `le` is 了's pinyin. Where 一 starts, in frames.
double light_join_start(const std::string& le, const std::vector<float>& i_on_e) {
    MadeJoin join({le, "yi1"}, {{kSilence, StateRole::edge_silence, 0, 10},
                                {kLiquid, StateRole::initial, 0, 5},
                                {kVowelE, StateRole::final, 0, 5},
                                {kVowelI, StateRole::final, 1, 20},
                                {kSilence, StateRole::edge_silence, 1, 10}});
    for (std::size_t t = 0; t < 5; ++t) join.score(15 + t, kVowelI) = i_on_e[t];
    for (std::size_t t = 20; t < 40; ++t) join.score(t, kVowelE) = -10.0f;
    return join.placed()[1].start_s / kFrameStepS;
}

// 安心 (an1 xin1, its coda left out): silence (frames 0-14), 安's a (15-34), 心's x (35-49) and i
// (50-64), silence (65-79). The high band is noise's, -5 and -4.5 dB by turns (its reach in the
// pauses: -4.5), but on the vowels (-2 dB) and on the x from frame 35 + `unheard` on (+5 dB): the
// sibilant's first `unheard` frames, and 安's tail, sound like the noise.
MadeJoin sibilant_join(std::size_t unheard) {
    MadeJoin join({"an1", "xin1"}, {{kSilence, StateRole::edge_silence, 0, 15},
                                    {kVowelA, StateRole::final, 0, 20},
                                    {kSibilant, StateRole::initial, 1, 15},
                                    {kVowelI, StateRole::final, 1, 15},
                                    {kSilence, StateRole::edge_silence, 1, 15}});
    for (std::size_t t = 0; t < join.track.frame_count; ++t) {
        const bool is_vowel = (t >= 15 && t < 35) || (t >= 50 && t < 65);
        const bool is_frication = t >= 35 + unheard && t < 50;
        join.track.values[t * kFeatureCount + kHighBandDb] = is_vowel       ? -2.0f
                                                             : is_frication ? 5.0f
                                                             : t % 2 == 0   ? -5.0f
                                                                            : -4.5f;
    }
    return join;
}

// 大哥 (da4 ge1): silence (frames 0-14), 大's a (15-34), 哥's closure (35-46), burst (47-48) and e
// (49-63), silence (64-78). The whole band is the noise's, -41 and -40 dB by turns (its reach in
// the pauses: -40), but on the vowels (-10 dB), the burst (-15 dB) and on the closure's first
// `tail` frames, where 大's tail sounds over the noise (-34 dB).
MadeJoin closure_join(std::size_t tail) {
    MadeJoin join({"da4", "ge1"}, {{kSilence, StateRole::edge_silence, 0, 15},
                                   {kVowelA, StateRole::final, 0, 20},
                                   {kSilence, StateRole::closure, 1, 12},
                                   {kBurst, StateRole::initial, 1, 2},
                                   {kVowelE, StateRole::final, 1, 15},
                                   {kSilence, StateRole::edge_silence, 1, 15}});
    for (std::size_t t = 0; t < join.track.frame_count; ++t) {
        const bool is_vowel = (t >= 15 && t < 35) || (t >= 49 && t < 64);
        join.track.values[t * kFeatureCount + kEnergyDb] = is_vowel                   ? -10.0f
                                                           : t >= 47 && t < 49        ? -15.0f
                                                           : t >= 35 && t < 35 + tail ? -34.0f
                                                           : t % 2 == 0               ? -41.0f
                                                                                      : -40.0f;
    }
    return join;
}

// A syllable alone after a pause (`pinyin`, an initial and a), searched from frame 100 of a
// 200-frame track whose level is `level_db(frame)`, on a path that holds the edge silence for
// frames 0-10 of the search, the initial for 10 to `vowel`, a from `vowel` to 50 and the edge
// silence to 60: where place_syllables starts it, in frames of the search.
std::size_t placed_start(const char* pinyin, PhoneClass initial, std::size_t vowel,
                         const std::function<float(std::size_t)>& level_db) {
    Timeline transcript;
    transcript.sentences.push_back({});
    Syllable syllable;
    syllable.pinyin = pinyin;
    transcript.syllables.push_back(syllable);
    SentenceChain chain;
    chain.end_sentence = 1;
    chain.searched = {100, 160};
    chain.syllables = {&transcript.syllables[0]};
    chain.syllable_indices = {0};
    chain.states = build_phone_chain(chain.syllables, 60, 40);
    REQUIRE(chain.states.size() == 4);
    REQUIRE(chain.states[1].phone_class == initial);
    const std::vector<StateSegment> path = {{0, 0, 10}, {1, 10, vowel}, {2, vowel, 50}, {3, 50, 60}};
    EmissionScores scores;
    scores.frame_count = 60;
    scores.values.assign(60 * kPhoneClassCount, -1.0f);
    const FeatureTrack track = level_track(200, level_db);
    Timeline result = transcript;
    std::vector<SyllableEvidence> evidence(1);
    place_syllables(chain, 0, path, {}, scores, track, result, evidence);
    return static_cast<std::size_t>(std::lround(result.syllables[0].start_s / kFrameStepS)) -
           chain.searched.first_frame;
}
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
        CHECK(light_join_start("le5", turn) == doctest::Approx(15.0));
        // 了 with a tone of its own is heard apart; one e frame the i fits worse is a vowel of its own.
        CHECK(light_join_start("le4", turn) == doctest::Approx(20.0));
        CHECK(light_join_start("le5", {0.5f, 0.5f, -0.5f, 0.5f, 0.5f}) == doctest::Approx(20.0));
    }

    TEST_CASE("a sibilant whose first frames sound like the noise starts halfway to its heard frication") {
        // The path starts 心's x at frame 35; its frication rises above the noise's reach at 43.
        // Which of frames 35-42 were 安's decaying tail and which the x's weak onset is not heard:
        // the x starts halfway (39), where 安 ends.
        const auto placed = sibilant_join(8).placed();
        CHECK(placed[1].start_s / kFrameStepS == doctest::Approx(39.0));
        CHECK(placed[0].end_s == doctest::Approx(placed[1].start_s));
        // Frication heard from the path's start, or never above the noise (a weak one): the path's start.
        CHECK(sibilant_join(0).placed()[1].start_s / kFrameStepS == doctest::Approx(35.0));
        CHECK(sibilant_join(15).placed()[1].start_s / kFrameStepS == doctest::Approx(35.0));
    }

    TEST_CASE("a frame of the noise over its reach is not yet the sibilant's frication") {
        // The noise passes its reach one frame in ten: at frame 36, and at 40 and 41, two running.
        // The frication is heard from 43, where the high band stays over the reach: 心 starts halfway
        // (39), not halfway to frame 36 (35).
        MadeJoin join = sibilant_join(8);
        for (const std::size_t t : {36, 40, 41}) join.track.values[t * kFeatureCount + kHighBandDb] = -3.0f;
        CHECK(join.placed()[1].start_s / kFrameStepS == doctest::Approx(39.0));
        // A run of frication that starts on the sibilant's last frame still counts, though it runs on
        // into the vowel.
        FeatureTrack track = level_track(30, [](std::size_t) { return -20.0f; });
        for (float& value : track.values) value = -20.0f;
        for (std::size_t t = 19; t < 30; ++t) track.values[t * kFeatureCount + kHighBandDb] = 5.0f;
        CHECK(sibilant_onset(track, 0, 10, 20, -4.5f) == 14);
    }

    TEST_CASE("a sibilant's onset is looked for only where the noise's reach is measured") {
        FeatureTrack track = level_track(30, [](std::size_t) { return -20.0f; });
        for (float& value : track.values) value = -20.0f;
        for (std::size_t t = 20; t < 30; ++t) track.values[t * kFeatureCount + kHighBandDb] = 5.0f;
        CHECK(sibilant_onset(track, 0, 10, 30, -4.5f) == 15);
        CHECK(sibilant_onset(track, 0, 10, 20, -4.5f) == 10);
        CHECK(sibilant_onset(track, 0, 10, 30, std::numeric_limits<float>::infinity()) == 10);
        // The path's pauses hold fewer than 10 frames: no reach.
        const MadeJoin join = sibilant_join(8);
        std::vector<StateSegment> no_pauses(join.path.begin() + 1, join.path.end() - 1);
        CHECK(pause_noise_reach(join.track, join.chain, no_pauses, kHighBandDb) ==
              std::numeric_limits<float>::infinity());
        CHECK(pause_noise_reach(join.track, join.chain, join.path, kHighBandDb) == doctest::Approx(-4.5f));
        // Drums in the pauses, 15 dB apart: no steady noise to hear the frication against.
        MadeJoin drums = sibilant_join(8);
        for (std::size_t t = 0; t < drums.track.frame_count; ++t)
            if (t < 15 || t >= 65)
                drums.track.values[t * kFeatureCount + kHighBandDb] = t % 3 == 0 ? -5.0f : -20.0f;
        CHECK(pause_noise_reach(drums.track, drums.chain, drums.path, kHighBandDb) ==
              std::numeric_limits<float>::infinity());
        CHECK(drums.placed()[1].start_s / kFrameStepS == doctest::Approx(35.0));
    }

    TEST_CASE("a closure after a vowel in noise starts where the vowel's tail is no longer over the noise") {
        auto ge_start = [](const MadeJoin& join) { return join.placed()[1].start_s / kFrameStepS; };
        // The path starts 哥's closure at frame 35; 大's tail sounds over the noise's reach to frame 38.
        const MadeJoin heard = closure_join(4);
        CHECK(ge_start(heard) == doctest::Approx(39.0));
        CHECK(heard.placed()[0].end_s / kFrameStepS == doctest::Approx(39.0));
        // The tail under the reach from the path's start on, or over it up to the burst (a voiced
        // closure): the path's start.
        CHECK(ge_start(closure_join(0)) == doctest::Approx(35.0));
        CHECK(ge_start(closure_join(12)) == doctest::Approx(35.0));
        // Pauses of digital silence: no noise to hear the tail over.
        MadeJoin edited = closure_join(4);
        for (std::size_t t = 0; t < edited.track.frame_count; ++t)
            if (t < 15 || t >= 64) edited.track.values[t * kFeatureCount + kEnergyDb] = -100.0f;
        CHECK(ge_start(edited) == doctest::Approx(35.0));
        // A room's closure, scored as any sound (room_closures.hpp): its tail is the room's.
        MadeJoin room = closure_join(4);
        room.chain.states[2].phone_class = kGenericSpeech;
        CHECK(ge_start(room) == doctest::Approx(35.0));
    }

    TEST_CASE(
        "a sentence's first initial held over a room's tail before it starts where its own sound rises") {
        // The sentence before rings on into the pause, falling from -20 dB by 1.5 dB a frame
        // (frames 10-23 of the search); m rises out of it at frame 24 (-15 dB), a follows at 26.
        // The path gave m the tail too: 16 frames, past its prior's 6 times exp(2 x 0.45).
        const auto room = [](std::size_t t) {
            if (t < 110) return -50.0f;
            if (t < 124) return -20.0f - 1.5f * static_cast<float>(t - 110);
            return t < 126 ? -15.0f : 0.0f;
        };
        CHECK(placed_start("ma1", kNasal, 26, room) == 23);
        // A nasal held that long from its own onset (the level rising, never below its first
        // frame) starts where the path put it.
        const auto held = [](std::size_t t) {
            return t < 110 ? -50.0f : t < 126 ? -15.0f + 0.2f * static_cast<float>(t - 110) : 0.0f;
        };
        CHECK(placed_start("ma1", kNasal, 26, held) == 10);
        // An m of 12 frames is one the prior allows: the path's start stands, whatever lies under it.
        CHECK(placed_start("ma1", kNasal, 22, room) == 10);
        // An affricate after a pause opens with its burst, its frication weaker at first: the dip
        // after the burst is its own, and 扎 starts at the burst however long the path holds it.
        const auto burst = [](std::size_t t) {
            if (t < 110) return -50.0f;
            if (t < 112) return -10.0f;
            return t < 126 ? -30.0f + static_cast<float>(t - 112) : 0.0f;
        };
        CHECK(placed_start("zha1", kSibilant, 26, burst) == 10);
    }

    TEST_CASE("an initial after a comma's pause that starts late leaves the syllable before as it ended") {
        // 啊，媽: silence (frames 0-9), a (10-24), the comma's pause (25-34), m (35-50) and a
        // (51-65), silence (66-75). A room's tail falls through m's first frames to frame 48,
        // where m rises out of it; m's prior (6 frames) is far shorter than the 16 the path gave.
        MadeJoin comma({"a1", "ma1"}, {{kSilence, StateRole::edge_silence, 0, 10},
                                       {kVowelA, StateRole::final, 0, 15},
                                       {kSilence, StateRole::comma_pause, 0, 10},
                                       {kNasal, StateRole::initial, 1, 16},
                                       {kVowelA, StateRole::final, 1, 15},
                                       {kSilence, StateRole::edge_silence, 1, 10}});
        comma.chain.states[3].median_frames = 6.0;
        comma.chain.states[3].log_sigma = 0.45;
        for (std::size_t t = 35; t < 49; ++t)
            comma.track.values[t * kFeatureCount + kEnergyDb] = -20.0f - 1.5f * static_cast<float>(t - 35);
        const std::vector<Syllable> placed = comma.placed();
        CHECK(placed[1].start_s / kFrameStepS == doctest::Approx(48.0));
        // The pause lies between them: 啊 still ends where its vowel did, not where 媽 now starts.
        CHECK(placed[0].end_s / kFrameStepS == doctest::Approx(25.0));
    }
}

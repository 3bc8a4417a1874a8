// The mouth over a stretch the speech does not say as written (issue 13): mouth_key_frames follows
// TextMismatch::loudness there (louder, more open; silence, closed) in place of the syllables'
// shapes, and keeps the syllables' shapes where no loudness was measured.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "talkface/animation.hpp"
#include "talkface/errors.hpp"
#include "talkface/face_model.hpp"
#include "talkface/lip_sync.hpp"

using namespace talkface;

namespace {

Syllable syllable(const char* text, const char* pinyin, double start_s, double end_s) {
    return {text, pinyin, 0, start_s, end_s, std::nullopt, 1.0, false, false};
}

Sentence sentence(const char* text, double start_s, double end_s) { return {text, start_s, end_s, false}; }

// How far the lips part in a shape, pixels of the default face.
double opening(MouthShape shape) {
    const MouthControls controls = mouth_controls(FaceModel::default_face(), shape);
    return controls.down.y - controls.up.y;
}

// 好 at 0.4-0.6 s, then the two syllables of 学校 (what the text says) over 0.6-1.4 s, where the
// speech says something else; then 吗 at 1.4-1.6 s.
Timeline timeline_with_stretch(std::vector<double> loudness) {
    Timeline timeline;
    timeline.sentences = {sentence("好学校吗", 0.4, 1.6)};
    timeline.syllables = {syllable("好", "hao3", 0.4, 0.6), syllable("学", "xue2", 0.6, 1.0),
                          syllable("校", "xiao4", 1.0, 1.4), syllable("吗", "ma1", 1.4, 1.6)};
    timeline.mismatches = {{0.6, 1.4, 1, 2, "学校", std::move(loudness)}};
    timeline.duration_s = 2.0;
    return timeline;
}

// 40 values (0.8 s): silence, a loud syllable, a dip to silence, a softer one, silence. Each
// change falls between the two values a frame of 25 fps averages.
std::vector<double> two_syllables_of_loudness() {
    std::vector<double> values;
    for (int k = 0; k < 40; ++k) {
        const double time_s = 0.02 * k;
        values.push_back(time_s < 0.09 ? 0.0 : time_s < 0.29 ? 1.0 : time_s < 0.45 ? 0.0 : time_s < 0.61 ? 0.5 : 0.0);
    }
    return values;
}

// The value at a frame's time (both values the frame averages are alike, as above).
double loudness_at(const TextMismatch& mismatch, double time_s) {
    const auto k = static_cast<std::size_t>(std::lround((time_s - mismatch.start_s) / kMismatchLoudnessStepS));
    return mismatch.loudness[std::min(k, mismatch.loudness.size() - 1)];
}

std::vector<MouthKeyFrame> keys_inside(const std::vector<MouthKeyFrame>& keys, double from_s, double to_s) {
    std::vector<MouthKeyFrame> inside;
    std::copy_if(keys.begin(), keys.end(), std::back_inserter(inside),
                 [&](const MouthKeyFrame& key) { return key.time_s > from_s && key.time_s < to_s; });
    return inside;
}

}  // namespace

TEST_SUITE("lip sync") {
    TEST_CASE("over a mismatch the mouth opens with the loudness and closes in its silences") {
        const Timeline timeline = timeline_with_stretch(two_syllables_of_loudness());
        const TextMismatch& mismatch = timeline.mismatches.front();
        const auto inside = keys_inside(mouth_key_frames(timeline), mismatch.start_s, mismatch.end_s);
        REQUIRE(inside.size() >= 4);
        // 学 (x: i e ..., shapes i and e) and 校 (i a u) are not mouthed: the speech does not say them.
        for (const MouthKeyFrame& key : inside) {
            CAPTURE(key.time_s);
            CHECK((key.shape == MouthShape::m || key.shape == MouthShape::z || key.shape == MouthShape::n ||
                   key.shape == MouthShape::a));
        }
        // Louder, more open; the silences closed; the loud syllable wider than the soft one.
        for (const MouthKeyFrame& a : inside) {
            for (const MouthKeyFrame& b : inside) {
                CAPTURE(a.time_s);
                CAPTURE(b.time_s);
                if (loudness_at(mismatch, a.time_s) > loudness_at(mismatch, b.time_s)) {
                    CHECK(opening(a.shape) >= opening(b.shape));
                }
            }
            if (loudness_at(mismatch, a.time_s) == 0.0) CHECK(a.shape == MouthShape::m);
        }
        const auto shape_at = [&](double time_s) {
            const auto key = std::find_if(inside.begin(), inside.end(),
                                          [&](const MouthKeyFrame& k) { return std::abs(k.time_s - time_s) < 1e-9; });
            return key == inside.end() ? MouthShape::f : key->shape;
        };
        // A run of one shape is held: key frames at its first and last frames.
        CHECK(shape_at(0.72) == MouthShape::a);  // loud, 0.7-0.9 s
        CHECK(shape_at(0.88) == MouthShape::a);
        CHECK(shape_at(0.92) == MouthShape::m);  // the dip between, 0.9-1.06 s
        CHECK(shape_at(1.04) == MouthShape::m);
        CHECK(shape_at(1.08) == MouthShape::n);  // softer, 1.06-1.22 s
        CHECK(shape_at(1.2) == MouthShape::n);
        CHECK(shape_at(1.24) == MouthShape::m);
        // Outside it the syllables are mouthed as ever: 吗 starts with closed lips.
        const auto keys = mouth_key_frames(timeline);
        CHECK(std::any_of(keys.begin(), keys.end(), [](const MouthKeyFrame& key) {
            return key.syllable == std::size_t{3} && key.shape == MouthShape::m && std::abs(key.time_s - 1.4) < 1e-9;
        }));
    }

    TEST_CASE("the frames follow the key frames: open on the loud syllable, shut in the dip") {
        const Timeline timeline = timeline_with_stretch(two_syllables_of_loudness());
        const FaceModel face = FaceModel::default_face();
        LipSyncOptions options;
        const auto frames = mouth_frames(face, mouth_key_frames(timeline, options), 50, options);
        const auto parted = [&](double time_s) {
            const MouthControls& mouth = frames[static_cast<std::size_t>(std::lround(time_s * options.fps))];
            return mouth.down.y - mouth.up.y;
        };
        const double closed = opening(MouthShape::m);
        CHECK(parted(0.8) > closed + 0.6 * (opening(MouthShape::a) - closed));
        CHECK(parted(0.96) == doctest::Approx(closed));
        CHECK(parted(1.16) > closed);
        CHECK(parted(1.16) < parted(0.8));
        CHECK(parted(1.32) == doctest::Approx(closed));
    }

    TEST_CASE("a mismatch without a loudness keeps the syllables' shapes, one for speech the text lacks opens a pause") {
        Timeline unmeasured = timeline_with_stretch({});
        Timeline plain = unmeasured;
        plain.mismatches.clear();
        CHECK(mouth_key_frames(unmeasured) == mouth_key_frames(plain));

        // 好 ... 吗 with 0.8 s between them, where the speech says what the text lacks.
        Timeline lacking;
        lacking.sentences = {sentence("好吗", 0.4, 1.6)};
        lacking.syllables = {syllable("好", "hao3", 0.4, 0.6), syllable("吗", "ma1", 1.4, 1.6)};
        lacking.mismatches = {{0.6, 1.4, 1, 0, "", two_syllables_of_loudness()}};
        Timeline unmarked = lacking;
        unmarked.mismatches.clear();
        const auto resting = keys_inside(mouth_key_frames(unmarked), 0.6, 1.4);
        REQUIRE_FALSE(resting.empty());
        CHECK(std::all_of(resting.begin(), resting.end(), [](const MouthKeyFrame& key) { return key.shape == MouthShape::m; }));
        const auto speaking = keys_inside(mouth_key_frames(lacking), 0.6, 1.4);
        CHECK(std::any_of(speaking.begin(), speaking.end(), [](const MouthKeyFrame& key) { return key.shape == MouthShape::a; }));
        CHECK(std::all_of(speaking.begin(), speaking.end(), [](const MouthKeyFrame& key) { return !key.syllable; }));
    }

    TEST_CASE("speech the text lacks after the last syllable closes the mouth after it") {
        Timeline timeline;
        timeline.sentences = {sentence("好", 0.4, 0.6)};
        timeline.syllables = {syllable("好", "hao3", 0.4, 0.6)};
        timeline.mismatches = {{0.6, 1.4, 1, 0, "", two_syllables_of_loudness()}};
        const auto keys = mouth_key_frames(timeline);
        CHECK(keys.back().shape == MouthShape::m);
        CHECK(keys.back().time_s == doctest::Approx(1.52));  // 1.4 + rest_transition_s, on a frame
    }

    TEST_CASE("a mismatch out of range or with a loudness outside 0..1 is named") {
        Timeline timeline = timeline_with_stretch({0.5, 1.5});
        CHECK_THROWS_WITH_AS(mouth_key_frames(timeline), doctest::Contains("mismatch 0 (0.6-1.4 s): loudness values must be in 0..1, found 1.5"), InvalidArgument);
        timeline = timeline_with_stretch({0.5});
        timeline.mismatches.front().syllable_count = 4;
        CHECK_THROWS_WITH_AS(mouth_key_frames(timeline), doctest::Contains("past the 4 syllables"), InvalidArgument);
    }
}

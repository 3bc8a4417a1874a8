// Lip movement and the animation editor (thesis 5.3, 5.4; SPEC "Mouth shapes").
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "talkface/animation.hpp"
#include "talkface/errors.hpp"
#include "talkface/expression_simulator.hpp"
#include "talkface/face_model.hpp"
#include "talkface/lip_sync.hpp"

using namespace talkface;

namespace {

Syllable make_syllable(const std::string& pinyin, std::size_t sentence, double start_s, double end_s) {
    return {pinyin, pinyin, sentence, start_s, end_s, std::nullopt, 1.0, false};
}

// Phrases of syllables read in turn from a list rich in b p m f, `syllable_s` each, with `pause_s`
// between phrases; every third phrase ends a sentence.
Timeline make_timeline(double syllable_s, double pause_s, std::size_t phrases) {
    static const std::vector<std::string> pinyin{
        "ba4",    "xian1", "guo2", "ma1",     "hao3",   "zhi1", "fu4",   "pian4", "mo2",   "bo1",  "shuang1",
        "feng1",  "ai4",   "min2", "zhuang4", "pu3",    "er2",  "biao3", "yun2",  "mian4", "fa1",  "wo3",
        "liang2", "peng2", "qiu1", "mei3",    "chuan2", "fo2",  "yue4",  "bu4",   "de5",   "ming2"};
    Timeline timeline;
    double time_s = 0.4;
    std::size_t next = 0;
    for (std::size_t phrase = 0; phrase < phrases; ++phrase) {
        const std::size_t length = 3 + phrase % 5;
        for (std::size_t k = 0; k < length; ++k) {
            auto syllable =
                make_syllable(pinyin[next++ % pinyin.size()], phrase / 3, time_s, time_s + syllable_s);
            syllable.pause_after = k + 1 == length;
            timeline.syllables.push_back(syllable);
            time_s += syllable_s;
        }
        time_s += pause_s;
    }
    timeline.duration_s = time_s + 0.5;
    return timeline;
}

bool is_closure_syllable(const std::string& pinyin) {
    return !pinyin.empty() && std::string("bpmf").find(pinyin.front()) != std::string::npos;
}

double largest_point_step(const MouthControls& a, const MouthControls& b) {
    auto d = [](Point2 p, Point2 q) { return std::hypot(p.x - q.x, p.y - q.y); };
    return std::max({d(a.up, b.up), d(a.down, b.down), d(a.left, b.left), d(a.right, b.right)});
}

struct Setup {
    const char* name;
    double syllable_s;
    double fps;
    MouthInterpolation interpolation;
};

}  // namespace

TEST_SUITE("lip_sync") {
    TEST_CASE("shapes start at the thesis's onsets inside a syllable") {
        const Syllable syllable = make_syllable("x", 0, 10.0, 11.0);
        auto onsets = shape_onsets_s(syllable, syllable_shapes("ba"));
        REQUIRE(onsets.size() == 2);
        CHECK(onsets[0] == 10.0);
        CHECK(onsets[1] == doctest::Approx(10.1905));
        onsets = shape_onsets_s(syllable, syllable_shapes("zhen"));
        REQUIRE(onsets.size() == 3);
        CHECK(onsets[1] == doctest::Approx(10.1688));
        CHECK(onsets[2] == doctest::Approx(10.6025));
        onsets = shape_onsets_s(syllable, syllable_shapes("zhuang"));
        REQUIRE(onsets.size() == 4);
        CHECK(onsets[1] == doctest::Approx(10.2847));
        CHECK(onsets[2] == doctest::Approx(10.5297));
        CHECK(onsets[3] == doctest::Approx(10.7412));
        CHECK(shape_onsets_s(syllable, syllable_shapes("a")) == std::vector<double>{10.0});
    }

    TEST_CASE("a measured final start moves the vowel, and the table can be replaced") {
        Syllable syllable = make_syllable("zhen", 0, 10.0, 11.0);
        syllable.final_start_s = 10.5;
        auto onsets = shape_onsets_s(syllable, syllable_shapes("zhen"));
        CHECK(onsets[0] == 10.0);
        CHECK(onsets[1] == 10.5);
        // n keeps its share of what follows the vowel's onset in the table.
        CHECK(onsets[2] == doctest::Approx(10.5 + (0.6025 - 0.1688) / (1.0 - 0.1688) * 0.5));
        // xian has no initial shape (h' dropped): its first shape is the vowel's pre-posture.
        onsets = shape_onsets_s(syllable, syllable_shapes("xian"));
        CHECK(onsets[0] == 10.0);
        CHECK(onsets[1] == doctest::Approx(10.1688));

        ShapeOnsetTable table;
        table.two_shapes = {0.5};
        CHECK(shape_onsets_s(make_syllable("x", 0, 0.0, 2.0), syllable_shapes("ba"), table)[1] == 1.0);
        table.three_shapes = {0.7, 0.3};
        CHECK_THROWS_WITH_AS(shape_onsets_s(syllable, syllable_shapes("ba"), table),
                             doctest::Contains("ShapeOnsetTable::three_shapes"), InvalidArgument);
    }

    TEST_CASE("lip properties on generated timelines, normal and fast speech") {
        const FaceModel face = FaceModel::default_face();
        const Setup setups[] = {
            {"normal speech, 25 fps, linear", 0.25, 25.0, MouthInterpolation::linear},
            {"normal speech, 30 fps, smooth", 0.25, 30.0, MouthInterpolation::smooth},
            {"fast speech (6.7/s), 25 fps, linear", 0.15, 25.0, MouthInterpolation::linear},
            {"fast speech (6.7/s), 30 fps, linear", 0.15, 30.0, MouthInterpolation::linear},
            {"fast speech (6.7/s), 30 fps, smooth", 0.15, 30.0, MouthInterpolation::smooth},
            {"fast speech (7/s), 25 fps, smooth", 1.0 / 7.0, 25.0, MouthInterpolation::smooth},
        };
        const MouthControls neutral = mouth_controls(face, MouthShape::m);
        const MouthControls shape_f = mouth_controls(face, MouthShape::f);
        for (const Setup& setup : setups) {
            const std::string setup_name = setup.name;
            CAPTURE(setup_name);
            LipSyncOptions options;
            options.fps = setup.fps;
            options.interpolation = setup.interpolation;
            const Timeline timeline = make_timeline(setup.syllable_s, 0.6, 24);
            const ExpressionSimulator expressions(timeline, 5);
            const Animation animation = animate(face, timeline, expressions, options);
            const auto& keys = animation.mouth_key_frames;
            const auto& frames = animation.frames;
            auto frame_at = [&](double time_s) {
                return static_cast<std::size_t>(std::llround(time_s * setup.fps));
            };
            REQUIRE(frames.size() ==
                    static_cast<std::size_t>(std::floor(timeline.duration_s * setup.fps + 1e-9)) + 1);

            // Key frames rise strictly and sit on frames.
            for (std::size_t k = 0; k < keys.size(); ++k) {
                CAPTURE(k);
                if (k > 0) CHECK(keys[k].time_s > keys[k - 1].time_s);
                CHECK(std::abs(keys[k].time_s * setup.fps - std::round(keys[k].time_s * setup.fps)) < 1e-9);
            }

            // Every b, p, m, f closes the lips on the frame of its onset.
            for (std::size_t k = 0; k < timeline.syllables.size(); ++k) {
                const Syllable& syllable = timeline.syllables[k];
                if (!is_closure_syllable(syllable.pinyin)) continue;
                CAPTURE(k);
                CAPTURE(syllable.pinyin);
                const MouthControls& mouth = *frames[frame_at(syllable.start_s)].mouth;
                CHECK((mouth == neutral || mouth == shape_f));
            }

            // No control point jumps more than the stated speed allows in one frame.
            const double max_step = options.max_speed_mns0_per_s * face.fapu("MNS0") / setup.fps;
            double largest = 0.0;
            for (std::size_t i = 1; i < frames.size(); ++i) {
                largest = std::max(largest, largest_point_step(*frames[i - 1].mouth, *frames[i].mouth));
            }
            CAPTURE(largest);
            CAPTURE(max_step);
            CHECK(largest <= max_step * (1.0 + 1e-9));

            const auto& syllables = timeline.syllables;
            for (std::size_t k = 0; k + 1 < syllables.size(); ++k) {
                const double gap_s = syllables[k + 1].start_s - syllables[k].end_s;
                CAPTURE(k);
                if (gap_s >= options.rest_min_pause_s) {
                    // Neutral through the pause, once the transitions are over.
                    const double from_s = syllables[k].end_s + options.rest_transition_s + 1.0 / setup.fps;
                    const double to_s =
                        syllables[k + 1].start_s - options.rest_transition_s - 1.0 / setup.fps;
                    for (std::size_t i = frame_at(from_s); i <= frame_at(to_s); ++i) {
                        CAPTURE(i);
                        CHECK(*frames[i].mouth == neutral);
                    }
                } else {
                    // Inside a phrase the mouth never rests: no neutral key frame between two
                    // syllables, and an open syllable boundary is not neutral.
                    for (const auto& key : keys) {
                        if (key.time_s > syllables[k].start_s && key.time_s < syllables[k + 1].start_s) {
                            CHECK(key.syllable.has_value());
                        }
                    }
                    if (!is_closure_syllable(syllables[k + 1].pinyin)) {
                        CHECK(*frames[frame_at(syllables[k].end_s)].mouth != neutral);
                    }
                }
            }
            // Neutral before the first syllable and after the last.
            CHECK(*frames.front().mouth == neutral);
            CHECK(*frames.back().mouth == neutral);
        }
    }

    TEST_CASE("frames carry the simulator's pose and expression") {
        const FaceModel face = FaceModel::default_face();
        const Timeline timeline = make_timeline(0.25, 0.6, 6);
        const ExpressionSimulator expressions(timeline, 17);
        const Animation animation = animate(face, timeline, expressions);
        CHECK(animation.events == expressions.events());
        for (std::size_t i = 0; i < animation.frames.size(); i += 7) {
            CAPTURE(i);
            const double time_s = static_cast<double>(i) / animation.fps;
            CHECK(animation.frames[i].pose == expressions.pose_at(time_s));
            CHECK(animation.frames[i].expression == expressions.expression_at(time_s));
            CHECK(animation.frames[i].mouth.has_value());
        }
    }

    TEST_CASE("key frames are written as exact JSON and TSV") {
        const std::vector<MouthKeyFrame> keys{
            {0.0, MouthShape::m, std::nullopt}, {0.12, MouthShape::h_prime, 0}, {0.16, MouthShape::a, 0}};
        const std::vector<ExpressionEvent> events{{ExpressionEventKind::blink, 1.0, 1.2345, 1.0},
                                                  {ExpressionEventKind::nod, 2.5, 3.0, -4.25}};
        CHECK(key_frames_json(keys, events, 25.0, 3.5) ==
              "{\"fps\":25,\"duration\":3.5,\n"
              "\"mouth\":[\n"
              "{\"time\":0,\"shape\":\"m\",\"syllable\":null},\n"
              "{\"time\":0.12,\"shape\":\"h'\",\"syllable\":0},\n"
              "{\"time\":0.16,\"shape\":\"a\",\"syllable\":0}\n"
              "],\n"
              "\"events\":[\n"
              "{\"kind\":\"blink\",\"start\":1,\"end\":1.234,\"amount\":1},\n"
              "{\"kind\":\"nod\",\"start\":2.5,\"end\":3,\"amount\":-4.25}\n"
              "]}\n");
        CHECK(key_frames_tsv(keys) == "0\tm\n0.12\th'\n0.16\ta\n");
        CHECK(key_frames_json({}, {}, 30.0, 0.0) == "{\"fps\":30,\"duration\":0,\n\"mouth\":[\n],\n\"events\":[\n]}\n");
    }

    TEST_CASE("key frames JSON refuses a frame rate or duration it cannot carry") {
        CHECK_THROWS_WITH_AS(key_frames_json({}, {}, 0.0, 1.0), doctest::Contains("fps"), InvalidArgument);
        CHECK_THROWS_WITH_AS(key_frames_json({}, {}, 25.0, -1.0), doctest::Contains("duration_s"), InvalidArgument);
        CHECK_THROWS_WITH_AS(key_frames_json({}, {}, 25.0, std::nan("")), doctest::Contains("duration_s"),
                             InvalidArgument);
    }

    TEST_CASE("a syllable that is not Mandarin is named with its index and times") {
        Timeline timeline;
        timeline.syllables = {make_syllable("ma3", 0, 0.0, 0.2), make_syllable("xyz", 0, 0.2, 0.4)};
        CHECK_THROWS_WITH_AS(mouth_key_frames(timeline), doctest::Contains("syllable 1 (\"xyz\", 0.2-0.4 s)"),
                             InvalidArgument);
        timeline.syllables[1] = make_syllable("ma3", 0, 0.5, 0.3);
        CHECK_THROWS_WITH_AS(mouth_key_frames(timeline), doctest::Contains("ends before it starts"),
                             InvalidArgument);
        LipSyncOptions options;
        options.fps = 0.0;
        CHECK_THROWS_WITH_AS(mouth_key_frames(Timeline{}, options), doctest::Contains("LipSyncOptions::fps"),
                             InvalidArgument);
    }
}

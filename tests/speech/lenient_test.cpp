// AlignOptions::lenient (issue #13): a transcript a word off is aligned, the stretch that does not
// say its text reported (time span, expected text), and the other syllables placed as well as
// with a right text; a right text is never marked. The clip: espeak-ng (cmn-latn-pinyin) says
// 小朋友们在公园里放风筝 (tests/data/speech/make_clips.sh).
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "common/speech_clips.hpp"
#include "speech/lenient_chain.hpp"
#include "speech/rival_syllables.hpp"
#include "talkface/errors.hpp"
#include "talkface/face_model.hpp"
#include "talkface/lip_sync.hpp"
#include "talkface/speech_aligner.hpp"
#include "talkface/transcript.hpp"

using namespace talkface;

namespace {

// Where 公园 (syllables 5 and 6 of what is said) starts and ends.
constexpr std::size_t kWordFirst = 5;
constexpr std::size_t kWordEnd = 7;

// How far the lips part in a shape, pixels of the default face.
double opening(MouthShape shape) {
    const MouthControls controls = mouth_controls(FaceModel::default_face(), shape);
    return controls.down.y - controls.up.y;
}

SpeechAligner lenient_aligner() {
    AlignOptions options;
    options.lenient = true;
    return SpeechAligner(options);
}

// A chain of `count` syllables (all `syllable`) of one state each, skippable at `skip_log_penalty`.
detail::SentenceChain one_state_syllables(const Syllable& syllable, std::size_t count, double skip_log_penalty) {
    detail::SentenceChain chain;
    for (std::size_t i = 0; i < count; ++i) {
        chain.syllables.push_back(&syllable);
        detail::PhoneState state;
        state.role = detail::StateRole::final;
        state.syllable = i;
        state.skip_log_penalty = skip_log_penalty;
        chain.states.push_back(state);
    }
    return chain;
}

// Six one-state syllables of 10 frames whose lenient path skips syllable 2 and takes syllable 3
// over 5 frames, on scores alike everywhere (no fit is an outlier) until a test sets them.
struct SkipBesideCase {
    Syllable syllable;
    detail::SentenceChain chain;
    std::vector<detail::StateSegment> path;
    detail::EmissionScores scores;
    detail::FeatureTrack track;
    detail::LoudnessProfile loudness;

    SkipBesideCase() : chain(detail::lenient_chain(one_state_syllables(syllable, 6, -20.0))) {
        chain.syllable_indices = {0, 1, 2, 3, 4, 5};
        std::vector<std::size_t> state_of(6);
        for (std::size_t s = 0; s < chain.states.size(); ++s)
            if (chain.states[s].role != detail::StateRole::generic_speech) state_of[chain.states[s].syllable] = s;
        path = {{state_of[0], 0, 10}, {state_of[1], 10, 20}, {state_of[3], 20, 25}, {state_of[4], 25, 40}, {state_of[5], 40, 50}};
        scores.frame_count = 50;
        scores.values.assign(scores.frame_count * detail::kPhoneClassCount, 0.0f);
        track.frame_count = scores.frame_count;
        track.values.assign(track.frame_count * detail::kFeatureCount, 0.0f);
        track.duration_s = static_cast<double>(track.frame_count) * detail::kFrameStepS;
        loudness.activity_db.assign(track.frame_count, 0.0f);
    }
    // The chain points at `syllable`: not to be copied.
    SkipBesideCase(const SkipBesideCase&) = delete;
    SkipBesideCase& operator=(const SkipBesideCase&) = delete;

    // The one mismatch place_lenient reports with these held-out gaps: (first syllable, count).
    std::pair<std::size_t, std::size_t> named(const std::vector<double>& held_out_gaps) const {
        Timeline result;
        result.syllables.resize(6);
        result.sentences.resize(1);
        std::vector<detail::SyllableEvidence> evidence(6);
        detail::place_lenient(chain, 0, path, {}, held_out_gaps, scores, track, loudness, result, evidence);
        REQUIRE(result.mismatches.size() == 1);
        return {result.mismatches.front().first_syllable, result.mismatches.front().syllable_count};
    }
};

}  // namespace

TEST_SUITE("speech") {
    TEST_CASE("lenient: a word the transcript lacks is reported where it is said, the rest is in place") {
        const auto truth = test::true_starts("lenient_espeak");
        REQUIRE(truth.size() == 11);
        const Timeline transcript = read_transcript("小朋友们在里放风筝。");
        const Timeline aligned = lenient_aligner().align_file(test::clip_path("lenient_espeak.flac"), transcript);
        REQUIRE(aligned.mismatches.size() == 1);
        const TextMismatch& mismatch = aligned.mismatches.front();
        CHECK(mismatch.syllable_count == 0);
        CHECK(mismatch.first_syllable == 5);  // 里, the syllable after the word
        CHECK(mismatch.expected_text.empty());
        CHECK(std::abs(mismatch.start_s - truth[kWordFirst]) < 0.05);
        CHECK(std::abs(mismatch.end_s - truth[kWordEnd]) < 0.05);
        CHECK(std::any_of(aligned.warnings.begin(), aligned.warnings.end(), [](const std::string& warning) {
            return warning.find("speech the transcript lacks") != std::string::npos;
        }));
        for (std::size_t i = 0; i < aligned.syllables.size(); ++i) {
            CAPTURE(i);
            const double said_start = truth[i < kWordFirst ? i : i + (kWordEnd - kWordFirst)];
            CHECK(std::abs(aligned.syllables[i].start_s - said_start) < 0.05);
            // In place, and measured so: the generic speech beside 在 and 里 is not silence to them.
            CHECK(aligned.syllables[i].confidence >= kLowAlignmentConfidence);
        }
        // Without lenient alignment nothing is reported (the checks judge the text instead).
        CHECK(SpeechAligner(AlignOptions{}).options().lenient == false);
    }

    TEST_CASE("lenient: a changed word is reported whole over its stretch, the syllables around it keep their place") {
        const auto truth = test::true_starts("lenient_espeak");
        const Timeline transcript = load_transcript(test::clip_path("lenient_espeak.txt"));  // 学校 for 公园
        const Timeline aligned = lenient_aligner().align_file(test::clip_path("lenient_espeak.flac"), transcript);
        REQUIRE(aligned.mismatches.size() == 1);
        const TextMismatch& mismatch = aligned.mismatches.front();
        // Both syllables: the path skips 学, the worse, and squeezes 校 between it and 里, where it
        // fits as an outlier of the sentence's syllables (it was reported as 学 alone, 60 ms long).
        CHECK(mismatch.first_syllable == kWordFirst);
        CHECK(mismatch.syllable_count == kWordEnd - kWordFirst);
        CHECK(mismatch.expected_text == "学校");
        CHECK(std::abs(mismatch.start_s - truth[kWordFirst]) < 0.1);
        CHECK(std::abs(mismatch.end_s - truth[kWordEnd]) < 0.1);
        for (std::size_t i = mismatch.first_syllable; i < mismatch.first_syllable + mismatch.syllable_count; ++i) {
            CAPTURE(i);
            CHECK(aligned.syllables[i].confidence == 0.0);
            CHECK(aligned.syllables[i].start_s >= mismatch.start_s - 1e-9);
            CHECK(aligned.syllables[i].end_s <= mismatch.end_s + 1e-9);
        }
        for (std::size_t i = 0; i < truth.size(); ++i) {
            if (i >= kWordFirst && i < kWordEnd) continue;
            CAPTURE(i);
            CHECK(std::abs(aligned.syllables[i].start_s - truth[i]) < 0.05);
        }
    }

    TEST_CASE("lenient: the stretch carries the audio's loudness, and the mouth follows it there") {
        const Timeline aligned = lenient_aligner().align_file(test::clip_path("lenient_espeak.flac"),
                                                              read_transcript("小朋友们在里放风筝。"));
        REQUIRE(aligned.mismatches.size() == 1);
        const TextMismatch& mismatch = aligned.mismatches.front();
        const std::vector<double>& loudness = mismatch.loudness;
        // A value every 20 ms over the stretch (公园, about 0.5 s of speech).
        CHECK(loudness.size() == static_cast<std::size_t>(std::ceil((mismatch.end_s - mismatch.start_s) / kMismatchLoudnessStepS - 1e-6)));
        REQUIRE(loudness.size() >= 10);
        CHECK(std::all_of(loudness.begin(), loudness.end(), [](double value) { return value >= 0.0 && value <= 1.0; }));
        // Two syllables of speech: loud in their vowels, softer between them and at the ends.
        const double loudest = *std::max_element(loudness.begin(), loudness.end());
        CHECK(loudest > 0.6);
        const auto peak = std::max_element(loudness.begin(), loudness.end()) - loudness.begin();
        CHECK(std::any_of(loudness.begin() + peak, loudness.end(), [&](double value) { return value < loudest - 0.3; }));

        // The mouth over the stretch: louder frames open wider; the two syllables of the text's
        // syllables around it keep their own shapes.
        const auto keys = mouth_key_frames(aligned);
        std::vector<std::pair<double, MouthShape>> inside;  // (loudness, shape)
        for (const MouthKeyFrame& key : keys) {
            // A frame in from either end: the neighbours' own key frames may round onto the ends.
            if (key.time_s <= mismatch.start_s + 0.04 || key.time_s >= mismatch.end_s - 0.04) continue;
            // The loudness of the frame: the mean of the values within half a frame (20 ms at 25 fps).
            double sum = 0.0;
            int count = 0;
            for (std::size_t k = 0; k < loudness.size(); ++k) {
                const double middle_s = mismatch.start_s + (static_cast<double>(k) + 0.5) * kMismatchLoudnessStepS;
                if (std::abs(middle_s - key.time_s) <= 0.02) {
                    sum += loudness[k];
                    ++count;
                }
            }
            REQUIRE(count > 0);
            inside.emplace_back(sum / count, key.shape);
        }
        REQUIRE(inside.size() >= 3);
        const auto widest = std::max_element(inside.begin(), inside.end(), [](const auto& a, const auto& b) {
            return opening(a.second) < opening(b.second);
        });
        const auto narrowest = std::min_element(inside.begin(), inside.end(), [](const auto& a, const auto& b) {
            return opening(a.second) < opening(b.second);
        });
        CHECK(opening(widest->second) > opening(narrowest->second));  // it opens and closes
        CHECK(widest->first > narrowest->first);                       // with the loudness
        for (const auto& [value, shape] : inside) {
            CAPTURE(value);
            CHECK((value < 0.1) == (shape == MouthShape::m));
            CHECK((value >= 0.67) == (shape == MouthShape::a));
        }
    }

    TEST_CASE("lenient: right texts are never marked, and aligned as without it") {
        const std::vector<std::pair<const char*, const char*>> clips = {
            {"one_sentence", ".wav"}, {"two_sentences", ".wav"}, {"comma_pause", ".flac"},
            {"run_together", ".flac"}, {"short_line", ".flac"}};
        for (const auto& [name, suffix] : clips) {
            CAPTURE(name);
            const std::string audio = test::clip_path(std::string(name) + suffix);
            const Timeline transcript = load_transcript(test::clip_path(std::string(name) + ".txt"));
            const Timeline strict = SpeechAligner().align_file(audio, transcript);
            const Timeline lenient = lenient_aligner().align_file(audio, transcript);
            CHECK(lenient.mismatches.empty());
            REQUIRE(lenient.syllables.size() == strict.syllables.size());
            for (std::size_t i = 0; i < strict.syllables.size(); ++i) {
                CAPTURE(i);
                CHECK(std::abs(lenient.syllables[i].start_s - strict.syllables[i].start_s) < 0.02);
            }
        }
    }

    TEST_CASE("lenient: syllables skipped stay skipped only where one of them or a neighbour fits the plain path as an outlier") {
        // Five one-state syllables; the lenient path skips syllable 2.
        const Syllable syllable;
        detail::SentenceChain chain = one_state_syllables(syllable, 5, -20.0);
        // Every skipped syllable rivalled: judged on the fits alone.
        const std::vector<double> rivalled(5, 0.3);
        const std::vector<detail::StateSegment> skips_2 = {{0, 0, 10}, {1, 10, 20}, {3, 20, 30}, {4, 30, 40}};
        const std::vector<double> usual = {1.0, 1.1, 0.9, 1.05, 0.95};
        CHECK(detail::unsupported_skips(chain, skips_2, usual, rivalled, {}) == std::vector<std::size_t>{2});
        std::vector<double> outlier = usual;
        outlier[2] = 0.2;  // 16 median absolute deviations under the median
        CHECK(detail::unsupported_skips(chain, skips_2, outlier, rivalled, {}).empty());
        outlier = usual;
        outlier[3] = 0.2;  // its neighbour
        CHECK(detail::unsupported_skips(chain, skips_2, outlier, rivalled, {}).empty());
        // Two syllables skipped together are judged together, with the run's neighbours.
        const std::vector<detail::StateSegment> skips_2_3 = {{0, 0, 10}, {1, 10, 20}, {4, 20, 40}};
        CHECK(detail::unsupported_skips(chain, skips_2_3, usual, rivalled, {}) == std::vector<std::size_t>{2, 3});
        outlier = usual;
        outlier[4] = 0.2;
        CHECK(detail::unsupported_skips(chain, skips_2_3, outlier, rivalled, {}).empty());
        // No plain path (more syllables than the speech holds): nothing to judge by.
        CHECK(detail::unsupported_skips(chain, skips_2, {}, rivalled, {}).empty());

        detail::forbid_skips(chain, {2});
        CHECK(std::isinf(chain.states[2].skip_log_penalty));
        CHECK(chain.states[3].skip_log_penalty == -20.0);
    }

    TEST_CASE("lenient: a skipped syllable that held-out models hear as another stands for an outlier") {
        // Five one-state syllables whose plain-path fits spread as in noise (none an outlier); the
        // lenient path skips syllable 2, rivalled.
        const Syllable syllable;
        const detail::SentenceChain chain = one_state_syllables(syllable, 5, -20.0);
        const std::vector<detail::StateSegment> skips_2 = {{0, 0, 10}, {1, 10, 20}, {3, 20, 30}, {4, 30, 40}};
        const std::vector<double> usual = {1.0, 1.1, 0.9, 1.05, 0.95};
        const std::vector<double> rivalled(5, 0.3);
        // Held-out models that never heard its text hear another syllable: kept.
        CHECK(detail::unsupported_skips(chain, skips_2, usual, rivalled, {0.0, 0.0, 1.4, 0.0, 0.0}).empty());
        // A gap a right syllable in noise has: judged by the fits, which do not support the skip.
        CHECK(detail::unsupported_skips(chain, skips_2, usual, rivalled, {0.0, 0.0, 0.9, 0.0, 0.0}) ==
              std::vector<std::size_t>{2});
        // A neighbour's gap is its own, not the skipped syllable's.
        CHECK(detail::unsupported_skips(chain, skips_2, usual, rivalled, {0.0, 0.0, 0.5, 1.4, 0.0}) ==
              std::vector<std::size_t>{2});
        // Still rivalled or not kept: its own text fits it better than every unlike syllable.
        CHECK(detail::unsupported_skips(chain, skips_2, usual, std::vector<double>(5, 0.0),
                                        {0.0, 0.0, 1.4, 0.0, 0.0}) == std::vector<std::size_t>{2});
    }

    TEST_CASE("lenient: an outlier stays skipped only where unlike syllables fit its stretch better than its text") {
        const Syllable syllable;
        detail::SentenceChain chain = one_state_syllables(syllable, 5, -20.0);
        const std::vector<detail::StateSegment> skips_2_3 = {{0, 0, 10}, {1, 10, 20}, {4, 20, 40}};
        std::vector<double> fits = {1.0, 1.1, 0.2, 1.05, 0.95};  // syllable 2 an outlier
        const double nan = std::numeric_limits<double>::quiet_NaN();
        // Its own text fits it better than every unlike syllable: a right syllable that fits badly.
        CHECK(detail::unsupported_skips(chain, skips_2_3, fits, {0.0, 0.0, 0.0, 0.0, 0.0}, {}) == std::vector<std::size_t>{2, 3});
        // One of the run rivalled is enough (the path skips a changed word's syllables together).
        CHECK(detail::unsupported_skips(chain, skips_2_3, fits, {0.0, 0.0, 0.0, 0.2, 0.0}, {}).empty());
        // Not measured: judged on the fits alone.
        CHECK(detail::unsupported_skips(chain, skips_2_3, fits, {nan, nan, nan, nan, nan}, {}).empty());
    }

    TEST_CASE("lenient: skipped syllables stay skipped only where one of them fits free sounds better than its text on held-out models") {
        const Syllable syllable;
        const detail::SentenceChain chain = one_state_syllables(syllable, 5, -20.0);
        const std::vector<detail::StateSegment> skips_2_3 = {{0, 0, 10}, {1, 10, 20}, {4, 20, 40}};
        const std::vector<double> fits = {1.0, 1.1, 0.2, 1.05, 0.95};  // syllable 2 an outlier
        const std::vector<double> rivalled(5, 0.3);
        const double nan = std::numeric_limits<double>::quiet_NaN();
        // Free sounds fit neither skipped syllable better than its text: a right pair the path skipped.
        CHECK(detail::unsupported_skips(chain, skips_2_3, fits, rivalled, {0.0, 0.0, 0.15, -0.1, 0.9}) ==
              std::vector<std::size_t>{2, 3});
        // One of the run gapped is enough (a neighbour outside it is not).
        CHECK(detail::unsupported_skips(chain, skips_2_3, fits, rivalled, {0.0, 0.0, 0.15, 0.4, 0.0}).empty());
        // Not measured: judged by the other rules alone.
        CHECK(detail::unsupported_skips(chain, skips_2_3, fits, rivalled, {nan, nan, nan, nan, nan}).empty());
        CHECK(detail::unsupported_skips(chain, skips_2_3, fits, rivalled, {}).empty());
    }

    TEST_CASE("lenient: a skipped run kept loses its edge syllables that fit their text on held-out models") {
        // Five one-state syllables; the lenient path skips 1, 2 and 3 together, and 2 (an outlier
        // of the plain path, rivalled) gaps as a changed syllable does.
        const Syllable syllable;
        const detail::SentenceChain chain = one_state_syllables(syllable, 5, -20.0);
        const std::vector<detail::StateSegment> skips_1_to_3 = {{0, 0, 10}, {4, 10, 40}};
        const std::vector<double> fits = {1.0, 1.1, 0.2, 1.05, 0.95};
        const std::vector<double> rivalled(5, 0.3);
        const double nan = std::numeric_limits<double>::quiet_NaN();
        // 1 and 3 fit their text on models that never heard them: right neighbours the path
        // skipped with the changed syllable. Their skips are forbidden, 2's is kept.
        CHECK(detail::unsupported_skips(chain, skips_1_to_3, fits, rivalled, {0.0, 0.05, 0.9, -0.1, 0.0}) ==
              std::vector<std::size_t>{1, 3});
        // From each end inward, up to the first syllable that gaps: 3 gaps, 1 and 2 do not.
        CHECK(detail::unsupported_skips(chain, skips_1_to_3, fits, rivalled, {0.0, 0.05, 0.08, 0.6, 0.0}) ==
              std::vector<std::size_t>{1, 2});
        // An edge syllable not measured is not judged: it stays, and so does what lies inside it.
        CHECK(detail::unsupported_skips(chain, skips_1_to_3, fits, rivalled, {0.0, nan, 0.05, 0.6, 0.0}).empty());
        // Every syllable of the run gapped a little at least (an edge may gap less than the run
        // must): all kept.
        CHECK(detail::unsupported_skips(chain, skips_1_to_3, fits, rivalled, {0.0, 0.15, 0.9, 0.12, 0.0}).empty());
    }

    TEST_CASE("lenient: a syllable whose held-out gap and tone both say another skips for less, and its run stays skipped") {
        const double nan = std::numeric_limits<double>::quiet_NaN();
        // Both gaps high: heard as another syllable; either alone, or a tone not judged, not.
        CHECK(detail::heard_otherwise({0.0, 1.4, 1.4, 0.2, 1.4}, {0.0, 4.0, 1.0, 6.0, nan}) ==
              std::vector<bool>{false, true, false, false, false});
        CHECK(detail::heard_otherwise({1.4, 1.4}, {}) == std::vector<bool>{false, false});
        // Its skip costs half another's.
        const Syllable syllable;
        detail::SentenceChain chain = one_state_syllables(syllable, 5, -20.0);
        for (auto& state : chain.states) state.skip_log_penalty = -std::numeric_limits<double>::infinity();
        const detail::SentenceChain lenient = detail::lenient_chain(chain, {false, false, true, false, false});
        std::vector<double> skips;
        for (const auto& state : lenient.states)
            if (detail::is_syllable_state(state)) skips.push_back(state.skip_log_penalty);
        REQUIRE(skips.size() == 5);
        CHECK(skips[2] == doctest::Approx(0.5 * skips[1]));
        CHECK(skips[0] == skips[1]);
        // A run with no outlier of the plain path's fits, none rivalled, is kept where one of its
        // syllables is heard as another (its edges are still judged by their held-out gaps).
        const std::vector<detail::StateSegment> skips_2_3 = {{0, 0, 10}, {1, 10, 20}, {4, 20, 40}};
        const std::vector<double> usual = {1.0, 1.1, 0.9, 1.05, 0.95};
        const std::vector<double> unrivalled(5, 0.0);
        const std::vector<double> gaps = {0.0, 0.0, 1.4, 0.6, 0.0};
        CHECK(detail::unsupported_skips(chain, skips_2_3, usual, unrivalled, gaps) == std::vector<std::size_t>{2, 3});
        CHECK(detail::unsupported_skips(chain, skips_2_3, usual, unrivalled, gaps, {false, false, true, false, false}).empty());
        CHECK(detail::unsupported_skips(chain, skips_2_3, usual, unrivalled, {0.0, 0.0, 1.4, 0.05, 0.0},
                                        {false, false, true, false, false}) == std::vector<std::size_t>{3});
    }

    TEST_CASE("lenient: a syllable beside a skipped one joins its mismatch where free sounds fit it far better than its text") {
        const SkipBesideCase test_case;
        auto named = [&](const std::vector<double>& held_out_gaps) { return test_case.named(held_out_gaps); };
        // 3 gaps as a changed syllable does, 1 and 4 as right ones: the mismatch is 2 and 3.
        CHECK(named({0.0, 0.1, 0.0, 0.9, 0.2, 0.0}) == std::make_pair(std::size_t{2}, std::size_t{2}));
        // Under the bar, or not measured: 2 alone.
        CHECK(named({0.0, 0.1, 0.0, 0.3, 0.2, 0.0}) == std::make_pair(std::size_t{2}, std::size_t{1}));
        CHECK(named({}) == std::make_pair(std::size_t{2}, std::size_t{1}));
        // It grows outward while neighbours gap: 1, 2 and 3.
        CHECK(named({0.0, 0.8, 0.0, 0.9, 0.2, 0.0}) == std::make_pair(std::size_t{1}, std::size_t{3}));
    }

    TEST_CASE("lenient: a syllable beside a skipped one that fits as an outlier joins its mismatch only where it gaps on held-out models") {
        // The path of the test above; every state is silence. Each syllable's frames favour
        // silence over the other classes by a little more or less, and 3's favour no class, so
        // that 3 alone fits as an outlier of the chain's syllables.
        SkipBesideCase test_case;
        detail::EmissionScores& scores = test_case.scores;
        for (std::size_t t = 0; t < scores.frame_count; ++t) {
            const float others = t < 10 ? -5.0f : t < 20 ? -5.5f : t < 25 ? 0.0f : t < 40 ? -6.0f : -4.5f;
            for (std::size_t c = 0; c < detail::kPhoneClassCount; ++c)
                if (c != static_cast<std::size_t>(detail::kSilence)) scores.values[t * detail::kPhoneClassCount + c] = others;
        }
        auto named = [&](const std::vector<double>& held_out_gaps) { return test_case.named(held_out_gaps); };
        // Not measured: the outlier joins, as before the held-out gap.
        CHECK(named({}) == std::make_pair(std::size_t{2}, std::size_t{2}));
        // It gaps a little, under the bar of a syllable that fits as usual (0.5): it joins.
        CHECK(named({0.0, 0.0, 0.0, 0.15, 0.0, 0.0}) == std::make_pair(std::size_t{2}, std::size_t{2}));
        // Its text fits it on models that never heard it: a right neighbour that the models
        // re-estimated on the recording fit badly. 2 alone.
        CHECK(named({0.0, 0.0, 0.0, 0.05, 0.0, 0.0}) == std::make_pair(std::size_t{2}, std::size_t{1}));
        CHECK(named({0.0, 0.0, 0.0, -0.3, 0.0, 0.0}) == std::make_pair(std::size_t{2}, std::size_t{1}));
    }

    TEST_CASE("lenient: a syllable's own text fits its stretch better than unlike syllables do, a wrong one does not") {
        // A stretch of "ba": 3 frames of closure, 3 of burst, 24 of a.
        detail::EmissionScores scores;
        scores.frame_count = 30;
        scores.values.assign(scores.frame_count * detail::kPhoneClassCount, -10.0f);
        for (std::size_t t = 0; t < scores.frame_count; ++t) {
            const int best = t < 3 ? detail::kSilence : t < 6 ? detail::kBurst : detail::kVowelA;
            scores.values[t * detail::kPhoneClassCount + static_cast<std::size_t>(best)] = 0.0f;
        }
        Syllable ba;
        ba.pinyin = "ba3";
        Syllable shi;
        shi.pinyin = "shi4";
        Syllable yue;
        yue.pinyin = "yue4";
        detail::SentenceChain chain;
        chain.syllables = {&ba, &shi, &yue};
        const detail::SyllableFrames stretch{0, 30};
        CHECK(detail::rival_share(chain, 0, stretch, scores) < 0.05);
        CHECK(detail::rival_share(chain, 1, stretch, scores) > 0.3);
        CHECK(detail::rival_share(chain, 2, stretch, scores) > 0.3);
        // No frames: nothing to judge.
        CHECK(detail::rival_share(chain, 1, {10, 10}, scores) == 0.0);
    }

    TEST_CASE("lenient: generic speech shorter than most of a syllable is not speech the transcript lacks") {
        // Four syllables of 20 frames on the plain path; the lenient path has two generic stretches.
        const Syllable syllable;
        const detail::SentenceChain plain = one_state_syllables(syllable, 4, -std::numeric_limits<double>::infinity());
        const std::vector<detail::StateSegment> plain_path = {{0, 0, 20}, {1, 20, 40}, {2, 40, 60}, {3, 60, 80}};
        const detail::SentenceChain lenient = detail::lenient_chain(plain);
        // The last state of `role` of syllable `i`: for generic speech, the one after the syllable.
        auto state_of = [&](detail::StateRole role, std::size_t i) {
            std::size_t found = lenient.states.size();
            for (std::size_t s = 0; s < lenient.states.size(); ++s)
                if (lenient.states[s].role == role && lenient.states[s].syllable == i) found = s;
            REQUIRE(found < lenient.states.size());
            return found;
        };
        const auto final = detail::StateRole::final;
        const auto generic = detail::StateRole::generic_speech;
        // Generic speech of 10 frames after syllable 0 and of 16 after syllable 1.
        const std::vector<detail::StateSegment> path = {
            {state_of(final, 0), 0, 20},  {state_of(generic, 0), 20, 30}, {state_of(final, 1), 30, 50},
            {state_of(generic, 1), 50, 66}, {state_of(final, 2), 66, 86},  {state_of(final, 3), 86, 106}};
        const std::size_t first_generic = state_of(generic, 0);
        const auto frames = detail::frames_on_path(plain, plain_path);
        CHECK(detail::short_generic(lenient, path, frames) == std::vector<std::size_t>{first_generic});
        // No plain path: nothing to judge by.
        CHECK(detail::short_generic(lenient, path, {}).empty());
        detail::SentenceChain forbidden = lenient;
        detail::forbid_states(forbidden, {first_generic});
        CHECK(std::isinf(forbidden.states[first_generic].entry_log_penalty));
    }
}

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "common/chain_state.hpp"
#include "speech/alignment_confidence.hpp"
#include "speech/lenient_chain.hpp"
#include "talkface/speech_aligner.hpp"

using namespace talkface::detail;

namespace {

constexpr std::size_t kSyllables = 12;
constexpr std::size_t kInitialFrames = 4;
constexpr std::size_t kFinalFrames = 10;
constexpr std::size_t kEdgeFrames = 20;
// The syllable a drifted path places late, and by how much: 80 ms, the first syllable's worth of
// its final given to the syllable before.
constexpr std::size_t kDrifted = 6;
constexpr std::size_t kDriftFrames = 8;

// The chain's states: up to 1.2 s each, only the edge silences optional.
PhoneState chain_state(PhoneClass phone_class, StateRole role, std::size_t syllable, double median_frames) {
    return talkface::test::chain_state(phone_class, role, syllable, median_frames, 120, role == StateRole::edge_silence);
}

// A sentence of sibilant + vowel syllables, the vowels taking turns so that a syllable moved onto
// its neighbour's frames sounds wrong; emissions favour each frame's true class by 4 with noise of
// ±1, and the spectrum changes (the landmarks' bonus) where each syllable starts, as speech does.
struct Sentence {
    SentenceChain chain;
    std::vector<StateSegment> truth;
    EmissionScores scores;
};

Sentence make_sentence() {
    const PhoneClass vowels[] = {kVowelA, kVowelI, kVowelU, kVowelO};
    Sentence sentence;
    std::mt19937 random(7);
    std::uniform_real_distribution<float> noise(-1.0f, 1.0f);
    std::size_t frame = 0;
    auto add = [&](const PhoneState& state, std::size_t frames) {
        sentence.truth.push_back({sentence.chain.states.size(), frame, frame + frames});
        sentence.chain.states.push_back(state);
        for (std::size_t t = 0; t < frames; ++t, ++frame)
            for (int c = 0; c < kPhoneClassCount; ++c)
                sentence.scores.values.push_back((c == state.phone_class ? 0.0f : -4.0f) + noise(random));
    };
    add(chain_state(kSilence, StateRole::edge_silence, 0, 10.0), kEdgeFrames);
    for (std::size_t s = 0; s < kSyllables; ++s) {
        add(chain_state(kSibilant, StateRole::initial, s, static_cast<double>(kInitialFrames)), kInitialFrames);
        add(chain_state(vowels[s % 4], StateRole::final, s, static_cast<double>(kFinalFrames)), kFinalFrames);
    }
    add(chain_state(kSilence, StateRole::edge_silence, kSyllables - 1, 10.0), kEdgeFrames);
    static const std::vector<talkface::Syllable> syllables(kSyllables);
    for (const auto& syllable : syllables) sentence.chain.syllables.push_back(&syllable);
    sentence.scores.frame_count = frame;
    sentence.scores.boundary.assign(frame + 1, 0.0f);
    for (const StateSegment& segment : sentence.truth)
        if (sentence.chain.states[segment.state].role == StateRole::initial) sentence.scores.boundary[segment.first_frame] = 1.0f;
    return sentence;
}

// `truth` with syllable kDrifted starting `frames` late: the final before it stretched over its
// start, its own final squeezed.
std::vector<StateSegment> drifted(std::vector<StateSegment> path, std::size_t frames = kDriftFrames) {
    const std::size_t initial = 1 + 2 * kDrifted;
    path[initial - 1].end_frame += frames;
    path[initial].first_frame += frames;
    path[initial].end_frame += frames;
    path[initial + 1].first_frame += frames;
    return path;
}

// Each syllable's confidence on `path`, as the aligner gives it (with each syllable's start_sureness
// and far_start_share where given).
std::vector<double> confidences(const Sentence& sentence, const std::vector<StateSegment>& path,
                                const std::vector<double>& sureness = std::vector<double>(kSyllables, 1.0),
                                const std::vector<double>& far = std::vector<double>(kSyllables, 0.0)) {
    std::vector<SyllableFrames> frames(kSyllables, {sentence.scores.frame_count, 0});
    for (const StateSegment& segment : path) {
        const PhoneState& state = sentence.chain.states[segment.state];
        if (is_pause(state.role)) continue;
        frames[state.syllable].first_frame = std::min(frames[state.syllable].first_frame, segment.first_frame);
        frames[state.syllable].end_frame = std::max(frames[state.syllable].end_frame, segment.end_frame);
    }
    const std::vector<SyllableFit> fits = syllable_fit_parts(sentence.chain, path, sentence.scores, frames);
    const std::vector<double> timing = syllable_timing(sentence.chain, path, sentence.scores, frames);
    std::vector<SyllableEvidence> evidence;
    for (std::size_t i = 0; i < kSyllables; ++i)
        evidence.push_back({true, 0, fits[i], timing[i], 0.0, sureness[i], far[i]});
    talkface::Timeline timeline;
    timeline.syllables.resize(kSyllables);
    set_confidences(evidence, false, timeline);
    std::vector<double> result;
    for (const auto& syllable : timeline.syllables) result.push_back(syllable.confidence);
    return result;
}

}  // namespace

TEST_SUITE("alignment confidence") {
    TEST_CASE("a syllable placed 80 ms late comes out below the threshold, the same syllable placed right above it") {
        const Sentence sentence = make_sentence();
        const auto right = confidences(sentence, sentence.truth);
        const auto wrong = confidences(sentence, drifted(sentence.truth));
        for (std::size_t i = 0; i < kSyllables; ++i) {
            CAPTURE(i);
            CHECK(right[i] >= talkface::kLowAlignmentConfidence);
        }
        CHECK(wrong[kDrifted] < talkface::kLowAlignmentConfidence);
        CHECK(wrong[kDrifted] < right[kDrifted] - 0.2);
    }

    TEST_CASE("a syllable's timing counts against it where its length departs from its neighbours' pace") {
        // Only the timing: emissions that fit the drifted path as well as the right one (every
        // class alike) leave its length, its sounds' lengths and the spectrum's change to judge.
        Sentence sentence = make_sentence();
        std::fill(sentence.scores.values.begin(), sentence.scores.values.end(), 0.0f);
        std::vector<SyllableFrames> right_frames, wrong_frames;
        const auto wrong_path = drifted(sentence.truth);
        for (std::size_t s = 0; s < kSyllables; ++s) {
            right_frames.push_back({sentence.truth[1 + 2 * s].first_frame, sentence.truth[2 + 2 * s].end_frame});
            wrong_frames.push_back({wrong_path[1 + 2 * s].first_frame, wrong_path[2 + 2 * s].end_frame});
        }
        const auto right = syllable_timing(sentence.chain, sentence.truth, sentence.scores, right_frames);
        const auto wrong = syllable_timing(sentence.chain, wrong_path, sentence.scores, wrong_frames);
        // The syllable stretched over the drifted one's start and the drifted one itself.
        CHECK(wrong[kDrifted - 1] < right[kDrifted - 1]);
        CHECK(wrong[kDrifted] < right[kDrifted]);
        CHECK(wrong[0] == doctest::Approx(right[0]));
    }

    TEST_CASE("a syllable another path starts elsewhere loses evidence, the more frames the more, up to a cap") {
        const Sentence sentence = make_sentence();
        const auto drift = [&](std::size_t frames) { return frames_on_path(sentence.chain, drifted(sentence.truth, frames)); };
        const auto placed = frames_on_path(sentence.chain, sentence.truth);
        const auto agreeing = syllable_steadiness(placed, {placed});
        const auto two_off = syllable_steadiness(placed, {drift(2)});
        const auto eight_off = syllable_steadiness(placed, {drift(8)});
        const auto twenty_off = syllable_steadiness(placed, {drift(20)});
        const auto both = syllable_steadiness(placed, {drift(2), drift(8)});
        for (std::size_t i = 0; i < kSyllables; ++i) {
            CAPTURE(i);
            CHECK(agreeing[i] == 0.0);
            // Only the moved syllable's start counts: the one before it ends later but starts in place.
            if (i != kDrifted) CHECK(eight_off[i] == 0.0);
        }
        CHECK(two_off[kDrifted] < 0.0);
        CHECK(eight_off[kDrifted] < two_off[kDrifted]);
        CHECK(twenty_off[kDrifted] == eight_off[kDrifted]);
        CHECK(both[kDrifted] == doctest::Approx(two_off[kDrifted] + eight_off[kDrifted]));
        // A path that does not place the syllables (none found) says nothing of them.
        const auto none = syllable_steadiness(placed, {std::vector<SyllableFrames>(kSyllables)});
        CHECK(std::all_of(none.begin(), none.end(), [](double value) { return value == 0.0; }));
    }

    TEST_CASE("a syllable only the landmarks hold where it starts is judged by a search without them too") {
        // The spectrum changing strongly 3 frames before syllable kDrifted's start (and nowhere
        // else): the search with the landmarks' bonus starts it on that change, against its sounds;
        // the one without starts it where its sounds do. Measured against the first alone, a path
        // that starts it on the change would look steady.
        Sentence sentence = make_sentence();
        const std::size_t start = sentence.truth[1 + 2 * kDrifted].first_frame;
        const std::size_t early = start - 3;
        sentence.scores.boundary.assign(sentence.scores.frame_count + 1, 0.0f);
        sentence.scores.boundary[early] = 20.0f;
        const std::vector<float> bonus = sentence.scores.boundary;
        ViterbiWorkspace workspace;
        const std::vector<std::vector<SyllableFrames>> searches = {
            light_search(sentence.chain, sentence.scores, workspace, kLightSoundsWeight, true),
            light_search(sentence.chain, sentence.scores, workspace, kLightSoundsWeight, false)};
        CHECK(sentence.scores.boundary == bonus);
        CHECK(searches[0][kDrifted].first_frame == early);
        CHECK(searches[1][kDrifted].first_frame == start);
        const auto held = searches[0];
        CHECK(syllable_steadiness(held, {searches[0]})[kDrifted] == 0.0);
        CHECK(syllable_steadiness(held, searches)[kDrifted] < 0.0);
    }

    TEST_CASE(
        "a syllable whose start the search cannot decide is less sure of it, and comes out lower, than one "
        "it can") {
        // Over the 4 frames either side of syllable kDrifted's start the sibilant and the vowel
        // before fit alike, and no landmark marks the change: the path starts it somewhere there,
        // and the search finds starts a frame or two away nearly as good.
        Sentence sentence = make_sentence();
        const std::size_t start = sentence.truth[1 + 2 * kDrifted].first_frame;
        const PhoneClass before = sentence.chain.states[2 * kDrifted].phone_class;
        for (std::size_t t = start - 4; t < start + 4; ++t) {
            float* row = &sentence.scores.values[t * kPhoneClassCount];
            row[kSibilant] = row[before] = 0.0f;
        }
        sentence.scores.boundary[start] = 0.0f;
        ViterbiWorkspace workspace;
        EntryMaxMarginals marginals;
        const auto path =
            viterbi_align_with_marginals(sentence.chain.states, sentence.scores, workspace, marginals);
        const std::vector<double> sureness = start_sureness(sentence.chain, path, marginals);
        REQUIRE(sureness.size() == kSyllables);
        for (std::size_t i = 0; i < kSyllables; ++i) {
            CAPTURE(i);
            CHECK(sureness[i] > 0.0);
            CHECK(sureness[i] <= 1.0);
            if (i != kDrifted) CHECK(sureness[kDrifted] < sureness[i] - 0.2);
        }
        // Every fit here is good, so the confidences lie high on the logistic: its log-odds show the step.
        const auto sure = confidences(sentence, path);
        const auto measured = confidences(sentence, path, sureness);
        auto log_odds_lost = [&](std::size_t i) {
            return std::log(sure[i] / (1.0 - sure[i])) - std::log(measured[i] / (1.0 - measured[i]));
        };
        CHECK(log_odds_lost(kDrifted) > 1.0);
        for (std::size_t i = 0; i < kSyllables; ++i) {
            CAPTURE(i);
            if (i != kDrifted) CHECK(log_odds_lost(i) < 0.3);
        }
        // Without marginals (a chain searched in windows) every syllable counts as sure.
        const auto unmeasured = start_sureness(sentence.chain, path, EntryMaxMarginals{});
        CHECK(std::all_of(unmeasured.begin(), unmeasured.end(), [](double value) { return value == 1.0; }));
    }

    TEST_CASE(
        "a syllable whose sounds fit a start 100 ms away nearly as well is likely placed far off, and "
        "comes out lower, than one its sounds hold") {
        // Syllables kDrifted - 2 to kDrifted + 2 said under a burst of noise (every class alike, no
        // landmark): only their duration priors place them, and starts of theirs 10 frames or more
        // from the path's are nearly as good (and of the syllable after, whose start the noise
        // borders); further away the sounds hold each start.
        Sentence sentence = make_sentence();
        const std::size_t first = sentence.truth[1 + 2 * (kDrifted - 2)].first_frame;
        const std::size_t end = sentence.truth[2 + 2 * (kDrifted + 2)].end_frame;
        std::fill(sentence.scores.values.begin() + static_cast<std::ptrdiff_t>(first * kPhoneClassCount),
                  sentence.scores.values.begin() + static_cast<std::ptrdiff_t>(end * kPhoneClassCount), 0.0f);
        std::fill(sentence.scores.boundary.begin() + static_cast<std::ptrdiff_t>(first + 1),
                  sentence.scores.boundary.begin() + static_cast<std::ptrdiff_t>(end), 0.0f);
        ViterbiWorkspace workspace;
        EntryMaxMarginals marginals;
        const auto path =
            viterbi_align_with_marginals(sentence.chain.states, sentence.scores, workspace, marginals);
        const std::vector<double> far = far_start_share(sentence.chain, path, marginals);
        const std::vector<double> sureness = start_sureness(sentence.chain, path, marginals);
        REQUIRE(far.size() == kSyllables);
        const auto near_only = confidences(sentence, path, sureness);
        const auto measured = confidences(sentence, path, sureness, far);
        auto log_odds_lost = [&](std::size_t i) {
            return std::log(near_only[i] / (1.0 - near_only[i])) -
                   std::log(measured[i] / (1.0 - measured[i]));
        };
        for (std::size_t i = 0; i < kSyllables; ++i) {
            CAPTURE(i);
            CHECK(far[i] >= 0.0);
            CHECK(far[i] < 1.0);
            if (i + 2 >= kDrifted && i <= kDrifted + 2) {
                CHECK(far[i] > 0.3);
                CHECK(log_odds_lost(i) > 2.0);
            } else if (i + 4 < kDrifted || i > kDrifted + 4) {
                CHECK(far[i] < 0.05);
                CHECK(log_odds_lost(i) < 0.3);
            } else if (i + 3 < kDrifted || i > kDrifted + 3) {
                // Two syllables from the burst: its disagreement weighs in with the neighbours'.
                CHECK(far[i] < 0.05);
                CHECK(log_odds_lost(i) < 0.5);
            }
        }
        // Without marginals (a chain searched in windows) no start counts as far off.
        const auto unmeasured = far_start_share(sentence.chain, path, EntryMaxMarginals{});
        CHECK(std::all_of(unmeasured.begin(), unmeasured.end(), [](double value) { return value == 0.0; }));
    }

    TEST_CASE("a room's evidence, lower throughout, keeps its right syllables' confidences near a clean recording's") {
        // A clean recording's evidence, 0.3-0.8 (median 0.55, as the person's clean passages), and
        // the same lowered by 0.3 throughout, as a room lowers it (median 0.25).
        std::vector<double> clean, room;
        for (std::size_t i = 0; i <= 100; ++i) {
            clean.push_back(0.3 + 0.005 * static_cast<double>(i));
            room.push_back(clean.back() - 0.3);
        }
        auto confidences_of = [](const std::vector<double>& fits) {
            // Each syllable a chain of its own, so that its evidence is its fit alone.
            std::vector<SyllableEvidence> evidence;
            for (std::size_t i = 0; i < fits.size(); ++i) evidence.push_back({true, i, {fits[i], 0.0}, 0.0, 0.0});
            talkface::Timeline timeline;
            timeline.syllables.resize(fits.size());
            set_confidences(evidence, false, timeline);
            return timeline;
        };
        const auto in_clean = confidences_of(clean);
        const auto in_room = confidences_of(room);
        std::size_t clean_low = 0, room_low = 0;
        for (std::size_t i = 0; i < clean.size(); ++i) {
            clean_low += in_clean.syllables[i].confidence < talkface::kLowAlignmentConfidence;
            room_low += in_room.syllables[i].confidence < talkface::kLowAlignmentConfidence;
        }
        // Half given back (the relative share alone) flagged a third of the room's syllables.
        CHECK(room_low <= clean_low + 15);
        CHECK(in_room.syllables[50].confidence > in_clean.syllables[50].confidence - 0.1);
        // Every syllable still ranks by its evidence, and a room still lowers it some.
        CHECK(in_room.syllables[50].confidence < in_clean.syllables[50].confidence);
        CHECK(in_room.syllables[10].confidence < in_room.syllables[50].confidence);
    }

    TEST_CASE(
        "a run of syllables the other searches place elsewhere comes out lower than one syllable alone with "
        "the same disagreement") {
        // One chain of syllables that fit alike; syllable kLone and syllables kRun - 1 to kRun + 1
        // each have the same share of their starts 100 ms or more away. A misplaced run's syllables
        // disagree together, while a right syllable's searches disagree alone now and then (in noise
        // and fast speech, bench/README.md Session 35: 10.2% of phone-kinds' fast speech's right
        // syllables flagged): the run's weighs more.
        constexpr std::size_t kCount = 21, kLone = 5, kRun = 15;
        std::vector<SyllableEvidence> evidence;
        for (std::size_t i = 0; i < kCount; ++i) {
            const bool disagrees = i == kLone || (i + 1 >= kRun && i <= kRun + 1);
            evidence.push_back({true, 0, {0.55, 0.0}, 0.0, 0.0, 1.0, disagrees ? 0.6 : 0.0});
        }
        talkface::Timeline timeline;
        timeline.syllables.resize(kCount);
        set_confidences(evidence, false, timeline);
        const auto& syllables = timeline.syllables;
        CHECK(syllables[kRun].confidence < syllables[kLone].confidence - 0.05);
        CHECK(syllables[kRun].confidence < talkface::kLowAlignmentConfidence);
        // A syllable's own disagreement still weighs most: the lone one ranks under its neighbours.
        CHECK(syllables[kLone].confidence < syllables[kLone - 1].confidence - 0.2);
        CHECK(syllables[kLone + 3].confidence > 0.9);
    }

    TEST_CASE("a recording whose free-sound gaps scatter twice a clean one's flags no more of its syllables") {
        // The same posteriors and gaps around the same median, the noisy recording's deviations
        // twice the clean one's (whose spread is a clean recording's, kept as it is): noise makes
        // every syllable's gap scatter, right or not, and unscaled its right syllables' tail fell
        // under the threshold (issue 12: up to 13% of them flagged at 15-20 dB SNR).
        auto confidences_of = [](double deviation_scale) {
            std::vector<SyllableEvidence> evidence;
            for (std::size_t i = 0; i <= 100; ++i) {
                const double deviation = 0.132 * (static_cast<double>(i) - 50.0) / 50.0;
                evidence.push_back({true, i, {0.55, -0.15 + deviation_scale * deviation}, 0.0, 0.0});
            }
            talkface::Timeline timeline;
            timeline.syllables.resize(evidence.size());
            set_confidences(evidence, false, timeline);
            return timeline;
        };
        const auto clean = confidences_of(1.0);
        const auto noisy = confidences_of(2.0);
        std::size_t clean_low = 0, noisy_low = 0;
        for (std::size_t i = 0; i < clean.syllables.size(); ++i) {
            CAPTURE(i);
            CHECK(noisy.syllables[i].confidence == doctest::Approx(clean.syllables[i].confidence));
            clean_low += clean.syllables[i].confidence < talkface::kLowAlignmentConfidence;
            noisy_low += noisy.syllables[i].confidence < talkface::kLowAlignmentConfidence;
        }
        CHECK(noisy_low == clean_low);
        // A gap beyond the rest still tells: the worst-fitting syllable ranks lowest.
        CHECK(noisy.syllables[100].confidence < noisy.syllables[50].confidence);
    }

    TEST_CASE("lenient alignment: a drifted syllable comes out low, by its timing and where other searches start it") {
        // Emissions that fit every class alike leave a syllable's timing and the other searches to
        // judge its place: a lenient path that says the text whole with syllable kDrifted 80 ms
        // late, placed as the aligner places a lenient chain's path (place_lenient), against the
        // chain searched again with the sounds weighing less (kLenientLightSoundsWeight), which follows
        // the duration priors and starts it in place. Lenient confidences had neither term.
        Sentence sentence = make_sentence();
        std::fill(sentence.scores.values.begin(), sentence.scores.values.end(), 0.0f);
        const SentenceChain lenient = lenient_chain(sentence.chain);
        // The lenient chain's states are the plain chain's in order, with generic speech between.
        std::vector<std::size_t> lenient_state;
        for (std::size_t s = 0; s < lenient.states.size(); ++s)
            if (lenient.states[s].role != StateRole::generic_speech) lenient_state.push_back(s);
        REQUIRE(lenient_state.size() == sentence.chain.states.size());
        auto on_lenient_chain = [&](std::vector<StateSegment> path) {
            for (StateSegment& segment : path) segment.state = lenient_state[segment.state];
            return path;
        };
        talkface::detail::FeatureTrack track;
        track.frame_count = sentence.scores.frame_count;
        track.values.assign(track.frame_count * kFeatureCount, 0.0f);
        track.duration_s = static_cast<double>(track.frame_count) * kFrameStepS;
        const LoudnessProfile loudness;
        ViterbiWorkspace workspace;
        const std::vector<std::vector<SyllableFrames>> light = {
            light_search(lenient, sentence.scores, workspace, kLenientLightSoundsWeight, true)};
        auto confidences = [&](const std::vector<StateSegment>& path, const std::vector<std::vector<SyllableFrames>>& others) {
            talkface::Timeline result;
            result.syllables.resize(kSyllables);
            std::vector<SyllableEvidence> evidence(kSyllables);
            SentenceChain chain = lenient;
            chain.syllable_indices.resize(kSyllables);
            for (std::size_t i = 0; i < kSyllables; ++i) chain.syllable_indices[i] = i;
            place_lenient(chain, 0, on_lenient_chain(path), others, {}, sentence.scores, track, loudness, result, evidence);
            REQUIRE(result.mismatches.empty());
            set_confidences(evidence, true, result);
            return result;
        };
        const auto right = confidences(sentence.truth, light);
        const auto wrong = confidences(drifted(sentence.truth), light);
        const auto unsearched = confidences(drifted(sentence.truth), {});
        for (std::size_t i = 0; i < kSyllables; ++i) {
            CAPTURE(i);
            CHECK(right.syllables[i].confidence >= talkface::kLowAlignmentConfidence);
        }
        CHECK(wrong.syllables[kDrifted].confidence < talkface::kLowAlignmentConfidence);
        // Each term counts: without the other search its timing alone lowers it (the fits are
        // alike), and the other search lowers it further.
        CHECK(unsearched.syllables[kDrifted].confidence < right.syllables[kDrifted].confidence - 0.2);
        CHECK(wrong.syllables[kDrifted].confidence < unsearched.syllables[kDrifted].confidence - 0.1);
    }
}

#include <doctest/doctest.h>

#include <vector>

#include "common/chain_state.hpp"
#include "speech/hsmm.hpp"

using namespace talkface::detail;

namespace {

using talkface::test::chain_state;

// A sentence of `syllables` sibilant + vowel syllables between edge silences, and emissions that
// favour each planted segment's class by 5 per frame: the search must find exactly the plant.
struct PlantedSentence {
    std::vector<PhoneState> states;
    std::vector<StateSegment> truth;
    EmissionScores emissions;
};

PlantedSentence plant(std::size_t syllables) {
    PlantedSentence sentence;
    std::size_t frame = 0;
    auto add = [&](const PhoneState& state, std::size_t frames) {
        sentence.truth.push_back({sentence.states.size(), frame, frame + frames});
        sentence.states.push_back(state);
        for (std::size_t t = 0; t < frames; ++t, ++frame)
            for (int c = 0; c < kPhoneClassCount; ++c) sentence.emissions.values.push_back(c == state.phone_class ? 0.0f : -5.0f);
    };
    add(chain_state(kSilence, StateRole::edge_silence, 0, 1.0, 110, true), 20);
    for (std::size_t s = 0; s < syllables; ++s) {
        add(chain_state(kSibilant, StateRole::initial, s, 4.0, 12, false), 3 + s % 3);
        add(chain_state(kVowelA, StateRole::final, s, 8.0, 30, false), 6 + 2 * (s % 4));
    }
    add(chain_state(kSilence, StateRole::edge_silence, syllables - 1, 1.0, 110, true), 20);
    sentence.emissions.frame_count = frame;
    return sentence;
}

// a (10 frames), n (6), e (10): a room's tail of the a over the n makes each n frame fit the a 0.8
// better than the n.
struct NasalAfterVowel {
    std::vector<PhoneState> states;
    EmissionScores emissions;

    NasalAfterVowel() {
        PhoneState vowel_a = chain_state(kVowelA, StateRole::final, 0, 10.0, 40, false);
        PhoneState nasal = chain_state(kNasal, StateRole::initial, 1, 6.0, 16, false);
        PhoneState vowel_e = chain_state(kVowelE, StateRole::final, 1, 10.0, 40, false);
        vowel_a.log_sigma = vowel_e.log_sigma = 0.5;
        nasal.log_sigma = 0.45;
        states = {vowel_a, nasal, vowel_e};
        emissions.frame_count = 26;
        for (std::size_t t = 0; t < emissions.frame_count; ++t) {
            const int truth = t < 10 ? kVowelA : t < 16 ? kNasal : kVowelE;
            for (int c = 0; c < kPhoneClassCount; ++c)
                emissions.values.push_back(c == truth ? 0.0f : truth == kNasal && c == kVowelA ? 0.8f : -5.0f);
        }
    }
};

// Two vowels of one class (duration medians 10 and 20 frames) over 30 frames that fit it alike:
// the emissions say nothing of where the second starts.
struct TwoAlikeVowels {
    std::vector<PhoneState> states = {chain_state(kVowelA, StateRole::final, 0, 10.0, 40, false),
                                      chain_state(kVowelA, StateRole::final, 1, 20.0, 40, false)};
    EmissionScores emissions;

    TwoAlikeVowels() {
        emissions.frame_count = 30;
        emissions.values.assign(30 * kPhoneClassCount, -1.0f);
    }
};

void check_same_path(const std::vector<StateSegment>& path, const std::vector<StateSegment>& truth) {
    REQUIRE(path.size() == truth.size());
    for (std::size_t i = 0; i < truth.size(); ++i) {
        CAPTURE(i);
        CHECK(path[i].state == truth[i].state);
        CHECK(path[i].first_frame == truth[i].first_frame);
        CHECK(path[i].end_frame == truth[i].end_frame);
    }
}

}  // namespace

TEST_SUITE("HSMM search") {
    TEST_CASE("a sentence finds the planted durations of its states") {
        const PlantedSentence sentence = plant(20);
        ViterbiWorkspace workspace;
        check_same_path(viterbi_align(sentence.states, sentence.emissions, workspace), sentence.truth);
    }

    TEST_CASE("a sentence of hundreds of syllables is searched in windows of bounded memory") {
        // 600 syllables with no punctuation: 1202 states over 7840 frames, more cells than one
        // search may hold.
        const PlantedSentence sentence = plant(600);
        REQUIRE(sentence.states.size() * (sentence.emissions.frame_count + 1) > kMaxSearchCells);
        ViterbiWorkspace workspace;
        check_same_path(viterbi_align(sentence.states, sentence.emissions, workspace), sentence.truth);
        CHECK(workspace.entry.size() <= kMaxSearchCells);
        CHECK(workspace.finish.size() <= kMaxSearchCells);
    }

    TEST_CASE(
        "a workspace's tables keep their size for a shorter search, and it finds the same path as a new "
        "one") {
        // A resize down and up again zeroes the grown part: a recording's searches alternate
        // between longer and shorter sentences.
        const PlantedSentence longer = plant(20);
        const PlantedSentence shorter = plant(5);
        ViterbiWorkspace workspace;
        viterbi_align(longer.states, longer.emissions, workspace);
        const std::size_t cells = workspace.entry.size();
        check_same_path(viterbi_align(shorter.states, shorter.emissions, workspace), shorter.truth);
        CHECK(workspace.entry.size() == cells);
        CHECK(workspace.finish.size() == cells);
        check_same_path(viterbi_align(longer.states, longer.emissions, workspace), longer.truth);
    }

    TEST_CASE("a pause with a tail holds a silence far longer than its longest explicit duration") {
        // Two syllables with 1.5 s of silence between them and no sentence mark (a transcript
        // without punctuation): the pause between them must take it all.
        PlantedSentence sentence;
        std::size_t frame = 0;
        auto add = [&](PhoneState state, std::size_t frames) {
            sentence.truth.push_back({sentence.states.size(), frame, frame + frames});
            sentence.states.push_back(state);
            for (std::size_t t = 0; t < frames; ++t, ++frame)
                for (int c = 0; c < kPhoneClassCount; ++c) sentence.emissions.values.push_back(c == state.phone_class ? 0.0f : -5.0f);
        };
        PhoneState pause = chain_state(kSilence, StateRole::short_pause, 0, 6.0, 60, true);
        pause.log_sigma = 0.7;
        pause.has_tail = true;
        add(chain_state(kSilence, StateRole::edge_silence, 0, 1.0, 110, true), 20);
        add(chain_state(kSibilant, StateRole::initial, 0, 4.0, 12, false), 4);
        add(chain_state(kVowelA, StateRole::final, 0, 10.0, 30, false), 10);
        add(pause, 150);
        add(chain_state(kSibilant, StateRole::initial, 1, 4.0, 12, false), 4);
        add(chain_state(kVowelA, StateRole::final, 1, 10.0, 30, false), 10);
        add(chain_state(kSilence, StateRole::edge_silence, 1, 1.0, 110, true), 20);
        sentence.emissions.frame_count = frame;
        ViterbiWorkspace workspace;
        check_same_path(viterbi_align(sentence.states, sentence.emissions, workspace), sentence.truth);
    }

    TEST_CASE("a boundary bonus moves the change between two sounds the emissions cannot tell apart") {
        // Two vowels of one class over 30 frames: the emissions say nothing of where the second
        // starts, the priors (medians 10 and 20 frames) put it at frame 9; a landmark at frame 16 moves it
        // there, and a bonus smaller than what the priors lose there does not.
        TwoAlikeVowels vowels;
        const auto& states = vowels.states;
        auto& emissions = vowels.emissions;
        ViterbiWorkspace workspace;
        auto second_start = [&] {
            const auto path = viterbi_align(states, emissions, workspace);
            REQUIRE(path.size() == 2);
            return path[1].first_frame;
        };
        CHECK(second_start() == 9);
        emissions.boundary.assign(31, 0.0f);
        emissions.boundary[16] = 3.0f;
        CHECK(second_start() == 16);
        emissions.boundary[16] = 0.1f;
        CHECK(second_start() == 9);
    }

    TEST_CASE("a nasal whose frames sound a little like the vowel before keeps its length") {
        // Frame by frame the emissions would give the a three of the n's frames; the priors,
        // weighted against frames that are not independent, leave it two.
        const NasalAfterVowel nasal;
        ViterbiWorkspace workspace;
        const auto path = viterbi_align(nasal.states, nasal.emissions, workspace);
        REQUIRE(path.size() == 3);
        CHECK(path[1].first_frame == 12);
        CHECK(path[2].first_frame == 16);
    }

    TEST_CASE("the weight of the sounds against the priors moves a boundary the two dispute") {
        // The nasal above: at weight 1 the a takes two of its frames; with the sounds at a quarter
        // the priors (a: 10 frames) give it back one, and with them weighed four times the a takes four.
        const NasalAfterVowel nasal;
        ViterbiWorkspace workspace;
        auto nasal_start = [&](double weight) {
            const auto path = viterbi_align(nasal.states, nasal.emissions, workspace, nasal.emissions.frame_count, weight);
            REQUIRE(path.size() == 3);
            return path[1].first_frame;
        };
        CHECK(nasal_start(1.0) == 12);
        CHECK(nasal_start(0.25) == 11);
        CHECK(nasal_start(4.0) == 14);
    }

    TEST_CASE(
        "the best whole path through each state's start scores the path's own score where the path starts "
        "it, less elsewhere") {
        // The planted sentence with landmarks' bonuses on some frames (paid by the state entered
        // there, in either direction of the search): the forward tables and the reversed search
        // must meet at the same score, that of the best path, at every state's start on it.
        PlantedSentence sentence = plant(20);
        sentence.emissions.boundary.assign(sentence.emissions.frame_count + 1, 0.0f);
        for (std::size_t t = 0; t <= sentence.emissions.frame_count; t += 7)
            sentence.emissions.boundary[t] = 0.5f;
        ViterbiWorkspace workspace;
        EntryMaxMarginals marginals;
        const auto path =
            viterbi_align_with_marginals(sentence.states, sentence.emissions, workspace, marginals);
        check_same_path(path, viterbi_align(sentence.states, sentence.emissions, workspace));
        REQUIRE(marginals.width == sentence.emissions.frame_count + 1);
        const float best = marginals.at(path.front().state, path.front().first_frame);
        for (const StateSegment& segment : path) {
            CAPTURE(segment.state);
            CHECK(marginals.at(segment.state, segment.first_frame) == doctest::Approx(best).epsilon(1e-5));
            // A frame either way gives a frame a class the emissions score 5 lower (the duration
            // priors give some back).
            for (std::size_t moved = 1; moved <= 15; ++moved) {
                if (segment.first_frame >= moved)
                    CHECK(marginals.at(segment.state, segment.first_frame - moved) < best - 3.0f);
                if (segment.first_frame + moved < marginals.width)
                    CHECK(marginals.at(segment.state, segment.first_frame + moved) < best - 3.0f);
            }
        }
    }

    TEST_CASE(
        "where the sounds cannot tell a state's start, its other starts score nearly as well as the path's") {
        // The two vowels of one class above: only the duration priors place the second's start.
        TwoAlikeVowels vowels;
        const auto& states = vowels.states;
        auto& emissions = vowels.emissions;
        ViterbiWorkspace workspace;
        EntryMaxMarginals marginals;
        const auto path = viterbi_align_with_marginals(states, emissions, workspace, marginals);
        REQUIRE(path.size() == 2);
        const float best = marginals.at(1, path[1].first_frame);
        CHECK(marginals.at(1, path[1].first_frame - 1) > best - 0.5f);
        CHECK(marginals.at(1, path[1].first_frame + 1) > best - 0.5f);
        CHECK(marginals.at(1, path[1].first_frame + 1) <= best);
    }

    TEST_CASE("a sentence searched in windows has no marginals, and the same path") {
        const PlantedSentence sentence = plant(600);
        ViterbiWorkspace workspace;
        EntryMaxMarginals marginals;
        check_same_path(
            viterbi_align_with_marginals(sentence.states, sentence.emissions, workspace, marginals),
            sentence.truth);
        CHECK(marginals.values.empty());
    }

    TEST_CASE("a chain longer than its frames has no path") {
        PlantedSentence sentence = plant(10);
        sentence.emissions.frame_count = 15;
        sentence.emissions.values.resize(15 * kPhoneClassCount);
        ViterbiWorkspace workspace;
        CHECK(viterbi_align(sentence.states, sentence.emissions, workspace).empty());
    }
}

// The decisions about sentences run together (src/speech/run_together.hpp) on hand-made cuts and
// timelines, where the right answer is plain: the aligner's end-to-end tests cover the audio.
#include <doctest/doctest.h>

#include <vector>

#include "speech/run_together.hpp"

using namespace talkface;
using namespace talkface::detail;

namespace {

// Two sentences of 10 syllables each, cut at a pause of `cut_pause` frames; the first has a
// comma's pause of `comma_pause` frames in its middle.
struct TwoSentences {
    std::vector<FrameSpan> spans;
    std::vector<std::size_t> syllables{10, 10};
    LoudnessProfile loudness;
};

TwoSentences two_sentences(std::size_t first_length, std::size_t comma_pause, std::size_t cut_pause) {
    TwoSentences cut;
    cut.spans = {{0, first_length}, {first_length + cut_pause, first_length + cut_pause + 200}};
    if (comma_pause > 0) cut.loudness.pauses.push_back({first_length / 2, first_length / 2 + comma_pause});
    if (cut_pause > 0) cut.loudness.pauses.push_back({first_length, first_length + cut_pause});
    return cut;
}

Syllable syllable(std::size_t sentence, double start_s, double end_s, bool pause_after = false) {
    Syllable s;
    s.sentence = sentence;
    s.start_s = start_s;
    s.end_s = end_s;
    s.pause_after = pause_after;
    return s;
}

// Sentence 0 runs 0-2 s with a comma after its second syllable (pause 0.8-1.0 s); sentence 1
// starts at `second_start_s`.
Timeline aligned_two(double first_end_s, double second_start_s) {
    Timeline timeline;
    timeline.sentences.resize(2);
    timeline.sentences[0].start_s = 0.0;
    timeline.sentences[0].end_s = first_end_s;
    timeline.sentences[1].start_s = second_start_s;
    timeline.sentences[1].end_s = second_start_s + 1.0;
    timeline.syllables = {syllable(0, 0.0, 0.4), syllable(0, 0.4, 0.8, true), syllable(0, 1.0, first_end_s),
                          syllable(1, second_start_s, second_start_s + 1.0)};
    return timeline;
}

}  // namespace

TEST_SUITE("sentences run together") {
    TEST_CASE("a sentence end at a long pause and even rates is not in doubt") {
        const TwoSentences cut = two_sentences(200, 0, 60);
        CHECK(find_run_together(cut.spans, cut.syllables, cut.loudness) == std::vector<bool>{false, false});
        CHECK_FALSE(are_sentence_ends_in_doubt(cut.spans, cut.syllables, cut.loudness));
    }

    TEST_CASE("a cut no longer than a comma's pause inside a sentence is in doubt") {
        const TwoSentences cut = two_sentences(200, 30, 20);
        CHECK(find_run_together(cut.spans, cut.syllables, cut.loudness)[0]);
        CHECK(are_sentence_ends_in_doubt(cut.spans, cut.syllables, cut.loudness));
    }

    TEST_CASE("a cut that leaves neighbours at very different rates is in doubt") {
        // 10 syllables in 1 s beside 10 in 2 s: one sentence took part of the other.
        const TwoSentences cut = two_sentences(100, 0, 60);
        CHECK(find_run_together(cut.spans, cut.syllables, cut.loudness)[0]);
        CHECK(are_sentence_ends_in_doubt(cut.spans, cut.syllables, cut.loudness));
    }

    TEST_CASE("a chain that leaves the sentence end in the cut's pause confirms the cut") {
        SentenceCut cut;
        cut.spans = {{0, 200}, {260, 360}};
        cut.runs_on = {true, false};
        CHECK_FALSE(moves_sentence_end(cut, aligned_two(2.0, 2.6), 0, 1));
        CHECK(moves_sentence_end(cut, aligned_two(1.6, 2.6), 0, 1));  // ended at its comma
    }

    TEST_CASE("only a pause the text marks may hold the cut's pause") {
        SentenceCut cut;
        cut.spans = {{0, 80}, {100, 360}};  // the cutter took the comma's pause, 0.8-1.0 s
        cut.runs_on = {true, false};
        CHECK(is_cut_pause_in_text(cut, aligned_two(2.0, 2.1), 0, 1));
        // The same pause between two syllables with no comma between them: a wrong text's doing.
        Timeline no_comma = aligned_two(2.0, 2.1);
        no_comma.syllables[1].pause_after = false;
        CHECK_FALSE(is_cut_pause_in_text(cut, no_comma, 0, 1));
    }

    TEST_CASE("a cut pause the syllables run on through for a longer pause of their own is passed over") {
        SentenceCut cut;
        cut.spans = {{0, 50}, {55, 360}};  // a dip of 0.05 s inside the second syllable, 0.4-0.8 s
        cut.runs_on = {true, false};
        const Timeline aligned = aligned_two(2.0, 2.1);  // the sentences 0.1 s apart
        CHECK_FALSE(is_cut_pause_in_text(cut, aligned, 0, 1));
        CHECK(is_cut_pause_passed_over(cut, aligned, 0, 1));
        // A wrong text bent over a real pause ends its sentence at a shorter one, or none.
        cut.spans = {{0, 40}, {70, 360}};
        CHECK_FALSE(is_cut_pause_passed_over(cut, aligned, 0, 1));
        CHECK_FALSE(is_cut_pause_passed_over(cut, aligned_two(2.0, 2.0), 0, 1));
        // Some of it between two syllables (the comma's pause, 0.8-1.0 s): heard, not passed over.
        cut.spans = {{0, 78}, {84, 360}};
        CHECK_FALSE(is_cut_pause_passed_over(cut, aligned, 0, 1));
    }

    TEST_CASE("blocks and neighbours skip sentences without syllables") {
        Timeline transcript;
        transcript.sentences.resize(3);
        transcript.syllables = {syllable(0, 0, 0), syllable(2, 0, 0)};
        CHECK(spoken_sentences_of(transcript) == std::vector<bool>{true, false, true});
        using Pair = std::pair<std::size_t, std::size_t>;
        CHECK(spoken_neighbours(spoken_sentences_of(transcript)) == std::vector<Pair>{{0, 2}});
        SentenceCut cut;
        cut.spans.resize(3);
        cut.runs_on = {false, false, false};
        CHECK(block_count(cut, transcript) == 2);
        cut.runs_on = {true, false, false};
        CHECK(block_count(cut, transcript) == 1);
    }
}

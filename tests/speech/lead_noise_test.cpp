// own_voice_share (issue 13): a short line the cutter found no pause before has its first syllable
// drawn over the recording's noise before the voice, and its own fit and rhythm are judged without
// that noise; a bare line's quiet initial and a line loud from its start keep every frame.
#include <doctest/doctest.h>

#include <cstddef>
#include <vector>

#include "speech/alignment_checks.hpp"
#include "speech/hsmm.hpp"
#include "speech/lead_noise.hpp"
#include "speech/sentence_cutter.hpp"

using namespace talkface::detail;

namespace {

// Three syllables from frame `first` on, lasting `frames` each, after a pause from frame 0; the
// path's frames are the recording's less `first_scored`.
struct Line {
    std::vector<StateSegment> path;
    std::vector<AlignedStretch> stretches;
};

Line line_of(std::size_t first, const std::vector<std::size_t>& frames, std::size_t first_scored) {
    Line line;
    if (first > first_scored) {
        line.path.push_back({0, 0, first - first_scored});
        line.stretches.push_back({first_scored, first, true, 0, false});
    }
    std::size_t at = first;
    for (std::size_t i = 0; i < frames.size(); ++i) {
        line.path.push_back({i + 1, at - first_scored, at + frames[i] - first_scored});
        line.stretches.push_back({at, at + frames[i], false, i, false});
        at += frames[i];
    }
    return line;
}

// A recording of `total` frames at `noise_db`, the voice at `voice_db` over [voice_first, voice_end).
LoudnessProfile loudness_of(std::size_t total, float noise_db, float voice_db, std::size_t voice_first,
                            std::size_t voice_end) {
    LoudnessProfile loudness;
    loudness.activity_db.assign(total, noise_db);
    for (std::size_t t = voice_first; t < voice_end; ++t) loudness.activity_db[t] = voice_db;
    return loudness;
}

}  // namespace

TEST_CASE("a short line's first syllable drawn over the hiss before the voice is judged from the voice on") {
    // A codec's hiss 16 dB under the voice fills the first 45 frames, and the path gives them to
    // the first syllable (its 75 frames against its neighbours' 15).
    const Line line = line_of(0, {75, 15, 15}, 0);
    const LoudnessProfile loudness = loudness_of(130, 18.0F, 34.0F, 45, 105);
    const OwnVoiceShare own = own_voice_share(line.path, line.stretches, loudness, 0);
    CHECK(own.has_noise);
    REQUIRE(own.path.size() == 3);
    CHECK(own.path.front().first_frame == 45);
    CHECK(own.path.front().end_frame == 75);
    REQUIRE(own.stretches.size() == 2);
    CHECK(own.stretches.front().syllable == 1);
    CHECK(syllable_length_spread(line.stretches) > 0.7);
    CHECK(syllable_length_spread(own.stretches) == doctest::Approx(0.0));
}

TEST_CASE("the noise is left out in the scores' frames up to the voice or the first syllable's last frames") {
    struct Case {
        std::size_t first, first_syllable_frames, first_scored, voice_first, onset_scored;
    };
    // The scores start 5 frames into the recording, the voice 30 frames into the first syllable;
    // a first syllable all quiet (the voice starts with the second) keeps its last 3 frames.
    for (const Case& c : {Case{10, 50, 5, 40, 35}, Case{0, 40, 0, 40, 37}}) {
        const Line line = line_of(c.first, {c.first_syllable_frames, 20, 20}, c.first_scored);
        const OwnVoiceShare own =
            own_voice_share(line.path, line.stretches, loudness_of(120, 12.0F, 32.0F, c.voice_first, 110),
                            c.first_scored);
        CHECK(own.has_noise);
        REQUIRE(own.path.size() == 3);
        CHECK(own.path.front().state == 1);
        CHECK(own.path.front().first_frame == c.onset_scored);
    }
}

TEST_CASE("a bare line's quiet initial and a line loud from its start keep every frame") {
    // A quiet s- of 10 frames (0.1 s) 20 dB under the vowel: an initial, not noise.
    const Line bare = line_of(0, {30, 20, 20}, 0);
    const LoudnessProfile initial = loudness_of(70, 12.0F, 32.0F, 10, 70);
    const OwnVoiceShare kept = own_voice_share(bare.path, bare.stretches, initial, 0);
    CHECK_FALSE(kept.has_noise);
    CHECK(kept.path.size() == bare.path.size());
    CHECK(kept.stretches.size() == bare.stretches.size());
    const LoudnessProfile loud = loudness_of(70, 30.0F, 32.0F, 0, 70);
    CHECK_FALSE(own_voice_share(bare.path, bare.stretches, loud, 0).has_noise);
}

TEST_CASE("a lone syllable drawn over the hiss on both sides of its voice is judged on its voice") {
    // 走！ through a lossy stream (bench/short_kinds_bench.py, p-loss): 1.32 s of hiss 32 dB under
    // the voice, which holds frames 52-90; the path gives the syllable all 132 frames.
    const Line lone = line_of(0, {132}, 0);
    const OwnVoiceShare own =
        own_voice_share(lone.path, lone.stretches, loudness_of(132, 25.0F, 57.0F, 52, 90), 0);
    CHECK(own.has_noise);
    REQUIRE(own.path.size() == 1);
    CHECK(own.path.front().first_frame == 52);
    CHECK(own.path.front().end_frame == 90);
    CHECK(own.stretches.empty());
    // In a line of more syllables the last keeps the frames after the voice: only the first's
    // noise is left out.
    const Line two = line_of(0, {70, 62}, 0);
    const OwnVoiceShare first_only =
        own_voice_share(two.path, two.stretches, loudness_of(132, 25.0F, 57.0F, 52, 90), 0);
    REQUIRE(first_only.path.size() == 2);
    CHECK(first_only.path.back().end_frame == 132);
    // A lone syllable whose quiet end is shorter than the noise keeps it.
    const OwnVoiceShare short_end =
        own_voice_share(lone.path, lone.stretches, loudness_of(132, 25.0F, 57.0F, 52, 125), 0);
    REQUIRE(short_end.path.size() == 1);
    CHECK(short_end.path.front().end_frame == 132);
}

// The acoustic observations of speech do not depend on digital silence around it (issue 13): a
// short line padded with exact zeros (short_lines_bench.py's 出發！, 0.5 s each side) had its floor
// at the zeros' -100 dB, every sound read near the speech level, and the path gave 發's vowel
// the whole line. The levels are taken above the floor of the frames that hold any sound.
#include <doctest/doctest.h>

#include <cstddef>
#include <vector>

#include "speech/acoustic_model.hpp"
#include "speech/frame_features.hpp"
#include "speech/sentence_cutter.hpp"

using namespace talkface::detail;

namespace {

// A track of `frames` frames: each band of frame t at level_db(t), the cepstra zero.
template <typename Level>
FeatureTrack track_of(std::size_t frames, Level level_db) {
    FeatureTrack track;
    track.frame_count = frames;
    track.values.assign(frames * kFeatureCount, 0.0f);
    for (std::size_t t = 0; t < frames; ++t)
        for (int column = kEnergyDb; column <= kHighBandDb; ++column)
            track.values[t * kFeatureCount + static_cast<std::size_t>(column)] = level_db(t);
    return track;
}

// A faint floor of noise, a weak onset, then a vowel, as in a line cut to its sound.
float line_db(std::size_t t) {
    if (t < 10) return -40.0f + static_cast<float>(t % 3);
    if (t < 20) return 0.0f + static_cast<float>(t % 4);
    return 30.0f + static_cast<float>(t % 5);
}

}  // namespace

TEST_SUITE("speech") {
    TEST_CASE("a line padded with digital silence is observed as the line alone") {
        constexpr std::size_t kLine = 50, kPad = 50;
        const FeatureTrack bare = track_of(kLine, line_db);
        const FeatureTrack padded = track_of(kLine + 2 * kPad, [](std::size_t t) {
            return t < kPad || t >= kPad + kLine ? -100.0f : line_db(t - kPad);
        });
        std::vector<float> bare_rows, padded_rows;
        observe(bare, measure_loudness(bare), {0, kLine}, bare_rows);
        observe(padded, measure_loudness(padded), {kPad, kPad + kLine}, padded_rows);
        REQUIRE(bare_rows.size() == padded_rows.size());
        for (std::size_t t = 0; t < kLine; ++t) {
            CAPTURE(t);
            for (const int column : {kLoudness, kTilt, kLowBand})
                CHECK(padded_rows[t * kObservationCount + static_cast<std::size_t>(column)] ==
                      doctest::Approx(bare_rows[t * kObservationCount + static_cast<std::size_t>(column)]));
        }
    }
}

// A voice's pitch (pitch_track.hpp) and a syllable's tone heard in it (tone_contour.hpp), for
// lenient alignment (issue 13): a changed word the broad classes hear alike differs in its tones.
#include <doctest/doctest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "speech/pitch_track.hpp"
#include "speech/tone_contour.hpp"

using namespace talkface::detail;

namespace {

// A voiced sound at `hz`, as a voice's harmonics falling off, 16 kHz, `frames` hops: the pitch of
// its last frame.
PitchFrame pitch_of_voice(double hz, std::size_t frames) {
    PitchTracker tracker;
    PitchFrame last;
    std::vector<float> hop(160);
    std::size_t n = 0;
    for (std::size_t f = 0; f < frames; ++f) {
        for (float& v : hop) {
            double sum = 0.0;
            for (int h = 1; h <= 12; ++h) sum += std::sin(2.0 * M_PI * hz * h * static_cast<double>(n) / 16000.0 + 0.7 * h) / h;
            v = static_cast<float>(0.1 * sum);
            ++n;
        }
        last = tracker.push(hop.data(), hop.size());
    }
    return last;
}

}  // namespace

TEST_CASE("pitch: a voice's period is found from 90 to 350 Hz, noise has none") {
    for (const double hz : {90.0, 120.0, 180.0, 250.0, 350.0}) {
        const PitchFrame frame = pitch_of_voice(hz, 6);
        INFO(hz);
        CHECK(frame.hz == doctest::Approx(hz).epsilon(0.015));
        CHECK(frame.voicing > 0.9f);
    }
    PitchTracker tracker;
    std::uint64_t state = 88172645463325252ull;
    std::vector<float> hop(160);
    PitchFrame frame;
    for (int f = 0; f < 6; ++f) {
        for (float& v : hop) {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            v = static_cast<float>(static_cast<double>(state >> 11) / 9007199254740992.0 - 0.5);
        }
        frame = tracker.push(hop.data(), hop.size());
    }
    CHECK(frame.voicing < 0.5f);
}

TEST_CASE("tone: a syllable whose pitch falls where its text has a level tone gaps above 0, its neighbours under") {
    // Eight syllables of each tone as a speaker says them (semitones from his median), a little
    // apart from one another; then one more, written tone 1 and said falling.
    const std::vector<std::array<double, 3>> of_tone = {{3, 3, 3}, {-2, 0, 2}, {-3, -5, -3}, {4, 1, -3}};
    std::vector<ToneShape> shapes;
    std::vector<std::string> pinyin;
    std::vector<std::size_t> sentences;
    for (int k = 0; k < 8; ++k)
        for (int t = 0; t < 4; ++t) {
            ToneShape shape;
            for (std::size_t i = 0; i < 3; ++i) shape.semitones[i] = of_tone[t][i] + 0.4 * std::sin(k * 3 + t + i);
            shape.is_measured = true;
            shapes.push_back(shape);
            pinyin.push_back("ma" + std::to_string(t + 1));
            sentences.push_back(static_cast<std::size_t>(k));
        }
    ToneShape falling;
    falling.semitones = {4.2, 0.8, -2.7};
    falling.is_measured = true;
    shapes.push_back(falling);
    pinyin.push_back("sha1");
    sentences.push_back(8);
    const std::vector<double> gaps = tone_gaps(shapes, pinyin, sentences);
    CHECK(gaps.back() > 5.0);
    for (std::size_t i = 0; i + 1 < gaps.size(); ++i) CHECK(gaps[i] < 0.0);
    // A light tone is not judged, nor a shape with too few voiced frames.
    pinyin.back() = "de5";
    CHECK(std::isnan(tone_gaps(shapes, pinyin, sentences).back()));
    pinyin.back() = "sha1";
    shapes.back().is_measured = false;
    CHECK(std::isnan(tone_gaps(shapes, pinyin, sentences).back()));
}

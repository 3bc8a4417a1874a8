#include "speech/tone_contour.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "common/order_statistics.hpp"

namespace talkface::detail {

namespace {

// A frame is voiced where its pitch's correlation reaches this (pitch_track.hpp).
constexpr float kMinVoicing = 0.6f;
// A final with fewer voiced frames has no shape.
constexpr std::size_t kMinVoicedFrames = 3;
// A tone is learned from at least this many syllables.
constexpr std::size_t kMinShapesOfTone = 3;
constexpr std::size_t kTones = 4;
constexpr double kFoldSemitones = 9.0;

bool is_voiced(const PitchFrame& frame) { return frame.voicing >= kMinVoicing && frame.hz > 0.0f; }

// The tones a syllable may be said in (bit t - 1 for tone t): its own, and where Mandarin changes
// it before another syllable (a third tone before a third tone rises; 一 and 不 vary); none for a
// light tone.
unsigned allowed_tones(const std::vector<std::string>& pinyin, const std::vector<std::size_t>& sentences, std::size_t i) {
    const std::string& own = pinyin[i];
    if (own.empty()) return 0;
    const int tone = own.back() - '0';
    if (tone < 1 || tone > 4) return 0;
    unsigned allowed = 1u << (tone - 1);
    const bool has_next = i + 1 < pinyin.size() && sentences[i + 1] == sentences[i] && !pinyin[i + 1].empty();
    if (tone == 3 && has_next && pinyin[i + 1].back() == '3') allowed |= 1u << 1;
    if (own == "yi1" || own == "bu4") allowed = 0b1111u;
    return allowed;
}

}  // namespace

double median_voiced_hz(const FeatureTrack& track, const std::vector<std::size_t>& frames) {
    std::vector<double> hz;
    for (const std::size_t t : frames)
        if (t < track.pitch.size() && is_voiced(track.pitch[t])) hz.push_back(track.pitch[t].hz);
    return hz.empty() ? 0.0 : upper_median(hz);
}

ToneShape tone_shape(const FeatureTrack& track, std::size_t first, std::size_t end, double reference_hz) {
    ToneShape shape;
    if (!(reference_hz > 0.0)) return shape;
    std::vector<double> semitones;
    for (std::size_t t = first; t < end && t < track.pitch.size(); ++t)
        if (is_voiced(track.pitch[t])) {
            // A period taken for its double or its half (an octave off) is folded back: a voice's
            // tones span less than an octave around its median.
            double semitone = 12.0 * std::log2(track.pitch[t].hz / reference_hz);
            if (semitone > kFoldSemitones) semitone -= 12.0;
            if (semitone < -kFoldSemitones) semitone += 12.0;
            semitones.push_back(semitone);
        }
    if (semitones.size() < kMinVoicedFrames) return shape;
    for (std::size_t k = 0; k < 3; ++k) {
        const std::size_t from = k * semitones.size() / 3, to = std::max(from + 1, (k + 1) * semitones.size() / 3);
        shape.semitones[k] = upper_median(std::vector<double>(semitones.begin() + static_cast<std::ptrdiff_t>(from),
                                                        semitones.begin() + static_cast<std::ptrdiff_t>(to)));
    }
    shape.is_measured = true;
    return shape;
}

std::vector<double> tone_gaps(const std::vector<ToneShape>& shapes, const std::vector<std::string>& pinyin,
                              const std::vector<std::size_t>& sentences) {
    const std::size_t count = shapes.size();
    std::vector<double> gaps(count, std::numeric_limits<double>::quiet_NaN());
    std::vector<unsigned> allowed(count);
    // Sums of the shapes of syllables with one tone only, to learn the tones from.
    std::array<std::array<double, 3>, kTones> sum{}, sum_squares{};
    std::array<std::size_t, kTones> seen{};
    std::vector<int> learned_tone(count, -1);
    for (std::size_t i = 0; i < count; ++i) {
        allowed[i] = allowed_tones(pinyin, sentences, i);
        if (!shapes[i].is_measured || allowed[i] == 0 || (allowed[i] & (allowed[i] - 1)) != 0) continue;
        int tone = 0;
        while (!(allowed[i] & (1u << tone))) ++tone;
        learned_tone[i] = tone;
        ++seen[static_cast<std::size_t>(tone)];
        for (std::size_t k = 0; k < 3; ++k) {
            sum[static_cast<std::size_t>(tone)][k] += shapes[i].semitones[k];
            sum_squares[static_cast<std::size_t>(tone)][k] += shapes[i].semitones[k] * shapes[i].semitones[k];
        }
    }
    for (std::size_t i = 0; i < count; ++i) {
        if (!shapes[i].is_measured || allowed[i] == 0) continue;
        // The tones learned without this syllable; the variance pooled within them.
        std::array<std::array<double, 3>, kTones> mean{};
        std::array<bool, kTones> is_learned{};
        std::array<double, 3> within{};
        double degrees = 0.0;
        for (std::size_t t = 0; t < kTones; ++t) {
            std::array<double, 3> s = sum[t], q = sum_squares[t];
            std::size_t n = seen[t];
            if (learned_tone[i] == static_cast<int>(t)) {
                --n;
                for (std::size_t k = 0; k < 3; ++k) {
                    s[k] -= shapes[i].semitones[k];
                    q[k] -= shapes[i].semitones[k] * shapes[i].semitones[k];
                }
            }
            if (n < kMinShapesOfTone) continue;
            is_learned[t] = true;
            for (std::size_t k = 0; k < 3; ++k) {
                mean[t][k] = s[k] / static_cast<double>(n);
                within[k] += q[k] - s[k] * mean[t][k];
            }
            degrees += static_cast<double>(n - 1);
        }
        if (degrees < 1.0) continue;
        auto log_likelihood = [&](std::size_t t) {
            double sum_z = 0.0;
            for (std::size_t k = 0; k < 3; ++k) {
                const double variance = std::max(within[k] / degrees, 0.25);  // half a semitone at least
                const double d = shapes[i].semitones[k] - mean[t][k];
                sum_z += d * d / variance;
            }
            return -0.5 * sum_z;
        };
        double own = -std::numeric_limits<double>::infinity(), other = own;
        bool is_own_learned = false;
        for (std::size_t t = 0; t < kTones; ++t) {
            if (!is_learned[t]) continue;
            if (allowed[i] & (1u << t)) {
                own = std::max(own, log_likelihood(t));
                is_own_learned = true;
            } else {
                other = std::max(other, log_likelihood(t));
            }
        }
        if (is_own_learned && other > -std::numeric_limits<double>::infinity()) gaps[i] = other - own;
    }
    return gaps;
}

}  // namespace talkface::detail

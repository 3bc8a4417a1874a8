// A test clip's samples in a room, as bench/'s reverb rows put a voice in one (issue 12).
#ifndef TALKFACE_TESTS_ROOM_AUDIO_HPP
#define TALKFACE_TESTS_ROOM_AUDIO_HPP

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace talkface::test {

// `dry` in a room like the one sox's `reverb 40 50 60` makes (bench/'s reverb rows; Jezar's
// freeverb, with the settings sox's reverb.c derives from those three numbers): eight damped
// feedback combs in parallel, their lengths scaled to a room of 60%, feedback 0.831 for a
// reverberance of 40%, damping 0.35 for 50%, then four allpasses in series, the wet sound fed at
// 0.015 of the input and added to the dry sound; scaled to the dry peak.
inline std::vector<float> in_room(const std::vector<float>& dry, int rate_hz) {
    constexpr double kRoomScale = 0.64, kFeedback = 0.831, kDamping = 0.35, kWetGain = 0.015;
    struct Filter {
        std::vector<double> line;
        std::size_t at = 0;
        double low = 0.0;
    };
    const double per_sample = rate_hz / 44100.0;
    auto filter = [](double length) {
        return Filter{std::vector<double>(static_cast<std::size_t>(length + 0.5), 0.0)};
    };
    std::vector<Filter> combs, allpasses;
    for (int length : {1116, 1188, 1277, 1356, 1422, 1491, 1557, 1617})
        combs.push_back(filter(length * kRoomScale * per_sample));
    for (int length : {556, 441, 341, 225}) allpasses.push_back(filter(length * per_sample));
    std::vector<double> out(dry.size());
    double dry_peak = 0.0, out_peak = 0.0;
    for (std::size_t i = 0; i < dry.size(); ++i) {
        const double in = dry[i];
        double wet = 0.0;
        for (Filter& comb : combs) {
            const double delayed = comb.line[comb.at];
            comb.low = delayed + (comb.low - delayed) * kDamping;
            comb.line[comb.at] = kWetGain * in + comb.low * kFeedback;
            comb.at = (comb.at + 1) % comb.line.size();
            wet += delayed;
        }
        for (Filter& allpass : allpasses) {
            const double delayed = allpass.line[allpass.at];
            allpass.line[allpass.at] = wet + delayed * 0.5;
            allpass.at = (allpass.at + 1) % allpass.line.size();
            wet = delayed - wet;
        }
        out[i] = in + wet;
        dry_peak = std::max(dry_peak, std::fabs(in));
        out_peak = std::max(out_peak, std::fabs(out[i]));
    }
    std::vector<float> samples(out.size());
    for (std::size_t i = 0; i < out.size(); ++i)
        samples[i] = static_cast<float>(out[i] * dry_peak / out_peak);
    return samples;
}

}  // namespace talkface::test

#endif

// The aligner's test clips (tests/data/speech/README.md): where they are, and the true onsets the
// generator wrote beside each.
#ifndef TALKFACE_TESTS_SPEECH_CLIPS_HPP
#define TALKFACE_TESTS_SPEECH_CLIPS_HPP

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "common/test_paths.hpp"

namespace talkface::test {

inline std::string clip_path(const std::string& file) { return source_path("tests/data/speech/" + file); }

// tests/data/speech/NAME.json, the generator's truth, as text.
inline std::string clip_truth_text(const std::string& name) {
    std::ifstream in(clip_path(name + ".json"));
    return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

// The true onsets of tests/data/speech/NAME.json: its syllables' "start" values, in order.
inline std::vector<double> true_starts(const std::string& name) {
    const std::string text = clip_truth_text(name);
    std::vector<double> starts;
    const std::size_t syllables = text.find("\"syllables\"");
    for (std::size_t at = text.find("\"start\":", syllables); at != std::string::npos; at = text.find("\"start\":", at + 1))
        starts.push_back(std::stod(text.substr(at + 8)));
    return starts;
}

// `speech` with `noise` (of mean power 1, as long) under it at `snr_db` against the speech's active
// level: the mean power of its loud (above -40 dBFS) 10 ms frames at `rate_hz`; both scaled by 0.7,
// below clipping. Empty if no frame of the speech is loud.
inline std::vector<float> mixed_at_snr(const std::vector<float>& speech, const std::vector<float>& noise, int rate_hz,
                                       double snr_db) {
    double speech_power = 0.0;
    std::size_t active = 0;
    const auto frame = static_cast<std::size_t>(rate_hz / 100);
    for (std::size_t i = 0; i + frame <= speech.size(); i += frame) {
        double power = 0.0;
        for (std::size_t k = i; k < i + frame; ++k) power += static_cast<double>(speech[k]) * speech[k];
        power /= static_cast<double>(frame);
        if (power > 1e-4) speech_power += power, ++active;
    }
    if (active == 0) return {};
    const double gain = std::sqrt(speech_power / static_cast<double>(active) / std::pow(10.0, snr_db / 10.0));
    std::vector<float> mixed(speech.size());
    for (std::size_t i = 0; i < speech.size(); ++i) mixed[i] = static_cast<float>(0.7 * (speech[i] + gain * noise[i]));
    return mixed;
}

// `samples` with a headset's hiss under them (uniform, peak 1e-3, drawn the same on every run).
inline void add_headset_hiss(std::vector<float>& samples) {
    std::uint32_t state = 777u;
    for (float& v : samples)
        v += 1e-3f * (static_cast<float>((state = state * 1664525u + 1013904223u) >> 8) / 8388608.0f - 1.0f);
}

}  // namespace talkface::test

#endif

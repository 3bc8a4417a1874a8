// The aligner's test clips (tests/data/speech/README.md): where they are, and the true onsets the
// generator wrote beside each.
#ifndef TALKFACE_TESTS_SPEECH_CLIPS_HPP
#define TALKFACE_TESTS_SPEECH_CLIPS_HPP

#include <cstddef>
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

}  // namespace talkface::test

#endif

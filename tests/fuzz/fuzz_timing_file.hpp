// What the timing-file fuzz targets share: any bytes as a timing in one format, for a fixed
// transcript, give either talkface::ParseError or a timeline whose syllables are all timed, in
// order, inside the audio, each ending after it starts.
#ifndef TALKFACE_TESTS_FUZZ_TIMING_FILE_HPP
#define TALKFACE_TESTS_FUZZ_TIMING_FILE_HPP

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "talkface/errors.hpp"
#include "talkface/timing_formats.hpp"
#include "talkface/transcript.hpp"

inline int fuzz_timing_file(const std::uint8_t* data, std::size_t size, const char* format) {
    static const talkface::Timeline transcript = talkface::read_transcript("你好，世界。ni3 hao3!");
    constexpr double kDurationS = 30.0;
    talkface::Timeline timeline;
    try {
        timeline = talkface::read_timing_string(std::string_view(reinterpret_cast<const char*>(data), size), format,
                                                transcript, kDurationS);
    } catch (const talkface::ParseError&) {
        return 0;
    }
    if (timeline.syllables.size() != transcript.syllables.size()) std::abort();
    double previous_start_s = 0.0;
    for (const auto& syllable : timeline.syllables) {
        if (!(syllable.start_s >= previous_start_s - 1e-9 && syllable.end_s >= syllable.start_s)) std::abort();
        if (!(syllable.end_s <= kDurationS + 0.001)) std::abort();
        previous_start_s = syllable.start_s;
    }
    return 0;
}

#endif

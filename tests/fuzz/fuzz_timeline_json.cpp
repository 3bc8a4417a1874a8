// Any bytes as a timeline JSON document: either talkface::ParseError, or a timeline that keeps the
// reader's promises (indices in range, times >= 0, ends after starts, confidence 0..1) and that
// writes and reads back to the same bytes.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>

#include "talkface/errors.hpp"
#include "talkface/timeline_json.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    talkface::Timeline timeline;
    try {
        timeline = talkface::timeline_from_json(std::string_view(reinterpret_cast<const char*>(data), size));
    } catch (const talkface::ParseError&) {
        return 0;
    }
    for (const auto& syllable : timeline.syllables) {
        if (syllable.sentence >= timeline.sentences.size()) std::abort();
        if (!(syllable.start_s >= 0.0 && syllable.end_s >= syllable.start_s)) std::abort();
        if (!(syllable.confidence >= 0.0 && syllable.confidence <= 1.0)) std::abort();
    }
    const std::string json = talkface::timeline_to_json(timeline);
    if (talkface::timeline_to_json(talkface::timeline_from_json(json)) != json) std::abort();
    return 0;
}

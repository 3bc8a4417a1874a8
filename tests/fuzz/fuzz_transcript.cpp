// Any bytes as a transcript: either talkface::Error, or sentences whose every syllable has a
// reading the lips know.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "talkface/errors.hpp"
#include "talkface/lip_sync.hpp"
#include "talkface/transcript.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    talkface::Timeline transcript;
    try {
        transcript = talkface::read_transcript(std::string_view(reinterpret_cast<const char*>(data), size));
    } catch (const talkface::Error&) {
        return 0;
    }
    for (const auto& syllable : transcript.syllables) {
        if (syllable.sentence >= transcript.sentences.size()) std::abort();
        (void)talkface::syllable_shapes(syllable.pinyin);  // throws, uncaught, on a reading it cannot show
    }
    return 0;
}

// Any bytes as a transcript: either talkface::Error (not an internal one), or sentences whose
// every syllable has a reading the lips know, and written forms (numbers, Latin words) that cover
// their syllables in order, each at least one, none overlapping.
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
    } catch (const talkface::Error& error) {
        if (error.code() == talkface::ErrorCode::internal) std::abort();
        return 0;
    }
    for (const auto& syllable : transcript.syllables) {
        if (syllable.sentence >= transcript.sentences.size()) std::abort();
        (void)talkface::syllable_shapes(syllable.pinyin);  // throws, uncaught, on a reading it cannot show
    }
    std::size_t covered = 0;
    for (const auto& form : transcript.written_forms) {
        if (form.text.empty() || form.syllable_count == 0 || form.first_syllable < covered ||
            form.first_syllable + form.syllable_count > transcript.syllables.size()) {
            std::abort();
        }
        covered = form.first_syllable + form.syllable_count;
    }
    return 0;
}

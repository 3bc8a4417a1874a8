// What every transcript the reader returns keeps, whatever bytes it came from: sentences whose
// every syllable has a reading the lips know, and written forms (numbers, Latin words) that cover
// their syllables in order, each at least one, none overlapping. Aborts where it does not.
#ifndef TALKFACE_FUZZ_TRANSCRIPT_CONTRACT_HPP
#define TALKFACE_FUZZ_TRANSCRIPT_CONTRACT_HPP

#include <cstddef>
#include <cstdlib>

#include "talkface/lip_sync.hpp"
#include "talkface/timeline.hpp"

inline void check_transcript_contract(const talkface::Timeline& transcript) {
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
}

#endif

// A short line refused on weak evidence is aligned with a warning (issue 13: "it refuses only on
// strong evidence, which a line of a few syllables rarely gives"). On a line of 1-8 syllables the
// measures of three checks (own fit, the spread of the syllables' lengths, the typical syllable
// against the order margin) lie past their limits for right lines as for wrong texts: nine sessions
// moved the limits and no bar on one measure parted them (bench/README.md, sessions 36, 40, 41 and
// 43). A refusal by one of them (WeighedRefusal) carries how far past its limit the measure lay, and
// from how far past the check calls the evidence strong; CheckMode::refuse refuses a short line only
// on strong evidence, and aligns it on weak evidence with the finding kept as a warning, as
// CheckMode::warn gives it. The other checks' refusals (a text that fits worse than free sounds, an
// order margin as small as a wrong text's, a syllable drawn over speech or squeezed, a tail of
// unspoken speech) were never a right short line's on the tuning lines, and stand. A line is short
// under kMinHeldOutSyllables: from 6 syllables on, texts that lack their last 1-3 syllables (align_bench
// --mismatch's one-sentence "tail-" texts of 6-8 syllables, espeak-ng's and the person's) are refused
// on evidence as weak as a right line's, 7 of them, where 4 right lines of 6-8 syllables would be freed
// (bench/README.md, session 44 (short44)).
#ifndef TALKFACE_SPEECH_WEAK_EVIDENCE_HPP
#define TALKFACE_SPEECH_WEAK_EVIDENCE_HPP

#include <optional>
#include <string>

#include "talkface/errors.hpp"
#include "talkface/timeline.hpp"

namespace talkface::detail {

// A refusal on one measure past its limit: `past_limit` (in the measure's own unit, as its message
// states it) and `strong_past_limit`, from where the check calls its evidence strong on a short line.
class WeighedRefusal : public AlignmentError {
public:
    WeighedRefusal(const std::string& message, double past_limit, double strong_past_limit);
    double past_limit() const { return past_limit_; }
    double strong_past_limit() const { return strong_past_limit_; }

private:
    double past_limit_;
    double strong_past_limit_;
};

// The warning that stands for `refusal` of `transcript` where CheckMode::refuse aligns it: a line of
// one spoken sentence under kMinHeldOutSyllables (a line too short for the held-out checks) refused
// by a WeighedRefusal short of its strong bar. Nothing where the refusal stands. The warning begins as
// CheckMode::warn's does, names the sentence and the measure (the refusal's message) and says how sure: how
// far past its limit, and how far past refuses.
std::optional<std::string> describe_weak_evidence(const AlignmentError& refusal, const Timeline& transcript);

}  // namespace talkface::detail

#endif

#include "speech/weak_evidence.hpp"

#include "common/number_format.hpp"
#include "speech/alignment_checks.hpp"
#include "speech/line_among_voices.hpp"

namespace talkface::detail {

WeighedRefusal::WeighedRefusal(const std::string& message, double past_limit, double strong_past_limit)
    : AlignmentError(message), past_limit_(past_limit), strong_past_limit_(strong_past_limit) {}

std::optional<std::string> describe_weak_evidence(const AlignmentError& refusal, const Timeline& transcript) {
    const auto* weighed = dynamic_cast<const WeighedRefusal*>(&refusal);
    if (weighed == nullptr || weighed->past_limit() >= weighed->strong_past_limit()) return std::nullopt;
    if (!is_one_spoken_line(transcript) || transcript.syllables.size() >= kMinHeldOutSyllables)
        return std::nullopt;
    const std::size_t syllables = transcript.syllables.size();
    return "the transcript may not match the audio (aligned anyway: weak evidence on a line of " +
           std::to_string(syllables) + (syllables == 1 ? " syllable, " : " syllables, ") +
           format_fixed(weighed->past_limit(), 2) + " past its limit, where " +
           format_fixed(weighed->strong_past_limit(), 2) + " past refuses): " + refusal.what();
}

}  // namespace talkface::detail

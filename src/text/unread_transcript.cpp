#include "text/unread_transcript.hpp"

namespace talkface::detail {

std::string describe_unread_transcript(const Timeline& transcript) {
    std::string description =
        std::to_string(transcript.sentences.size()) + " sentences, none with a Mandarin reading";
    if (transcript.warnings.empty()) return description;
    description += "; " + transcript.warnings.front();
    if (transcript.warnings.size() > 1)
        description += " (and " + std::to_string(transcript.warnings.size() - 1) + " more warnings)";
    return description;
}

}  // namespace talkface::detail

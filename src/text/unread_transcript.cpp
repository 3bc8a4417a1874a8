#include "text/unread_transcript.hpp"

namespace talkface::detail {

namespace {

// "1 sentence", "2 sentences", "0 sentences".
std::string counted(std::size_t count, const char* noun) {
    return std::to_string(count) + " " + noun + (count == 1 ? "" : "s");
}

}  // namespace

std::string describe_unread_transcript(const Timeline& transcript) {
    const std::size_t sentences = transcript.sentences.size();
    std::string description =
        counted(sentences, "sentence") +
        (sentences == 1 ? ", with no Mandarin reading" : ", none with a Mandarin reading");
    if (transcript.warnings.empty()) return description;
    description += "; " + transcript.warnings.front();
    if (transcript.warnings.size() > 1)
        description += " (and " + counted(transcript.warnings.size() - 1, "more warning") + ")";
    return description;
}

}  // namespace talkface::detail

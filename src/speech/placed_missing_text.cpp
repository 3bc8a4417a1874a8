#include "speech/placed_missing_text.hpp"

#include "speech/alignment_checks.hpp"
#include "speech/room_placement.hpp"

namespace talkface::detail {

void check_missing_text_as_placed(const CutAlignment& aligned, const CutAlignment* unkept,
                                  const FeatureTrack& heard, const LoudnessProfile& loudness,
                                  std::vector<std::string>& weak_findings) {
    check_missing_text(aligned.result, heard, loudness, weak_findings);
    std::vector<Timeline> others;
    if (aligned.room_result) others.push_back(with_room_placement(aligned.result, *aligned.room_result));
    if (unkept && unkept->room_result) {
        others.push_back(unkept->result);
        others.push_back(with_room_placement(unkept->result, *unkept->room_result));
    }
    // A pause that is no missing sentence's is reported once, as the checked syllables place it.
    std::vector<std::string> other_findings;
    for (const Timeline& placed : others) check_missing_text(placed, heard, loudness, other_findings);
}

}  // namespace talkface::detail
